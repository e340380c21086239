#!/usr/bin/env bash
# The C and C++ tests of c-tests/ under AddressSanitizer + UndefinedBehaviorSanitizer, and the
# concurrent stress tests under ThreadSanitizer, against the installed package.
#
#   scripts/sanitize.sh            # the short runs (small meshes; what scripts/test.sh runs)
#   scripts/sanitize.sh --full     # also the differential tests on every small mesh and a
#                                  # long stress run (see RELIABILITY.md)
#
# Under AddressSanitizer the Rust library is instrumented too: it is built a second time
# with RUSTFLAGS=-Zsanitizer=address (RUSTC_BOOTSTRAP=1 lets the stable toolchain take the
# flag; the standard library stays uninstrumented, as -Zbuild-std needs its sources) and
# put before the installed one with LD_LIBRARY_PATH; the tests' runtime (GCC's libasan)
# serves both. The stress tests run under ThreadSanitizer with c-tests/stress/tsan.supp,
# which ignores what the uninstrumented library does (RELIABILITY.md says why, and why not
# helgrind or drd).
# Needs what scripts/c-tests.sh needs; the differential tests need the meshes of
# scripts/fetch-meshes.sh and scripts/fetch-tets.sh --no-large.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
full=0
[ "${1:-}" = "--full" ] && full=1
work="$(mktemp -d "${TMPDIR:-/tmp}/topomesh-sanitize.XXXXXX")"
trap 'rm -rf "$work"' EXIT
jobs="$(nproc 2>/dev/null || echo 2)"
prefix="$work/prefix"

echo "== topomesh package -> $prefix"
cmake -S "$root/cmake" -B "$work/pkg" -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/pkg" --parallel "$jobs" >/dev/null
cmake --install "$work/pkg" >/dev/null

# configure DIR FLAGS: c-tests built with the sanitizer flags.
configure() {
    cmake -S "$root/c-tests" -B "$1" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_C_FLAGS="$2" -DCMAKE_CXX_FLAGS="$2" -DCMAKE_EXE_LINKER_FLAGS="$2" >/dev/null
}

echo "== the library under AddressSanitizer (-Zsanitizer=address)"
# --target: build scripts and proc macros stay uninstrumented.
triple="$(rustc -vV | sed -n 's/^host: //p')"
asan_target="${CARGO_TARGET_DIR:-$root/target}/asan"
(cd "$root" && RUSTC_BOOTSTRAP=1 RUSTFLAGS="-Zsanitizer=address" CARGO_TARGET_DIR="$asan_target" \
    cargo build --release --lib --locked --target "$triple")
mkdir -p "$work/asan-lib"
cp "$asan_target/$triple/release/libtopomesh.so" "$work/asan-lib/libtopomesh.so.0"

echo "== c-tests under AddressSanitizer and UndefinedBehaviorSanitizer"
configure "$work/asan" "-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
targets=(test_status test_che_build test_che_relations test_che_iter test_che_star test_chf_build
    test_chf_relations test_chf_bulk test_che_load test_chf_load test_che_wrapper test_chf_wrapper
    example_c example_cpp test_bad_inputs test_stress test_stress_cpp test_che_export
    test_chf_export test_oom test_che_write test_chf_write test_levelfile test_elements
    example_elements example_repair_c example_repair_cpp test_che_edit test_chf_edit
    test_chf_edit_wrapper test_export example_simplify example_refine)
tests='^(c_test_|cpp_|example_|stress_)'
if [ "$full" = 1 ]; then
    targets+=(topomesh_diff topomesh_diffvol)
    tests='^(c_test_|cpp_|example_|stress_|diff\.synthetic\.|diff\.(oblong-shuffled|mpi)\.|diffvol\.(cases|double-torus-2k))'
fi
cmake --build "$work/asan" --parallel "$jobs" --target "${targets[@]}" >/dev/null
# The tests must load the instrumented library, not the installed one. The address-space
# limit of test_oom's rlimit case cannot hold AddressSanitizer's shadow memory: that case
# runs in the plain and valgrind runs only.
loads="$(LD_LIBRARY_PATH="$work/asan-lib" ldd "$work/asan/test_status")"
[[ "$loads" == *"$work/asan-lib/libtopomesh"* ]] ||
    { echo "the tests do not load the instrumented library: $loads" >&2; exit 1; }
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    LD_LIBRARY_PATH="$work/asan-lib" \
    ctest --test-dir "$work/asan" --output-on-failure -R "$tests" -E oom_rlimit -LE valgrind

echo "== stress tests under ThreadSanitizer"
configure "$work/tsan" "-fsanitize=thread"
cmake --build "$work/tsan" --parallel "$jobs" --target test_stress test_stress_cpp >/dev/null
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$root/c-tests/stress/tsan.supp"
grid=12 rounds=2
[ "$full" = 1 ] && grid=40 rounds=20
"$work/tsan/stress/test_stress" "$grid" "$rounds"
"$work/tsan/stress/test_stress_cpp" "$grid" "$rounds"
echo "== sanitizers passed"
