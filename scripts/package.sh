# Sourced by the benchmark scripts: install_package ROOT PREFIX BUILD builds the CMake
# package of the checkout ROOT (the cmake/ project, Release) in BUILD and installs it into
# PREFIX, as a C or C++ user would find it.
install_package() {
  local root="$1" prefix="$2" build="$3"
  echo "== topomesh package -> $prefix"
  cmake -S "$root/cmake" -B "$build" -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" >/dev/null
  cmake --install "$build" >/dev/null
}
