#!/usr/bin/env bash
# Builds and installs the topomesh CMake package into a prefix, builds c-tests/ against it
# with find_package, and runs ctest (C ABI, C++ wrapper, static link, pkg-config, README
# examples, and the C tests under valgrind when it is installed).
#
#   scripts/c-tests.sh [PREFIX]      PREFIX defaults to a fresh temporary directory
#
# Needs cargo, cmake, a C and C++ compiler, pkg-config, valgrind (Debian 12:
# apt-get install cmake g++ valgrind pkg-config). Respects CARGO_TARGET_DIR, and
# CTEST_ARGS (extra ctest arguments, e.g. "-LE readers" or "-L valgrind").
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
prefix="${1:-}"
if [[ -z "$prefix" ]]; then
    prefix="$(mktemp -d "${TMPDIR:-/tmp}/topomesh-prefix.XXXXXX")"
fi
mkdir -p "$prefix"
prefix="$(cd "$prefix" && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/topomesh-c-tests.XXXXXX")"
trap 'rm -rf "$work"' EXIT
jobs="$(nproc 2>/dev/null || echo 2)"

echo "== topomesh package -> $prefix"
cmake -S "$root/cmake" -B "$work/pkg" -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DCMAKE_BUILD_TYPE=Release
cmake --build "$work/pkg" --parallel "$jobs"
cmake --install "$work/pkg"

echo "== c-tests against $prefix"
cmake -S "$root/c-tests" -B "$work/tests" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$work/tests" --parallel "$jobs"
# shellcheck disable=SC2086
ctest --test-dir "$work/tests" --output-on-failure --parallel "$jobs" ${CTEST_ARGS:-}
echo "== c-tests passed (package installed in $prefix)"
