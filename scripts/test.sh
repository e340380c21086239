#!/usr/bin/env bash
# The one test command. On a bare Debian 12 with Rust it installs what it needs, then runs
# every test: formatting, lints and the API docs, the Rust unit, property and integration tests (with
# the header drift test), a fixed-seed fuzz pass of every reader and builder, the C and C++ tests against the package installed into a
# temporary prefix (with valgrind), and the differential tests against OpenMesh and CGAL
# on real meshes.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
step() { echo; echo "== $* ($(( $(date +%s) - start )) s)"; }

step "Debian packages"
bash scripts/install-deps.sh

step "links in the pages resolve inside a clone (docs/check-links.py)"
python3 docs/check-links.py

step "every shell script parses (bash -n): the benchmark scripts run nowhere else"
for script in scripts/*.sh .ci/run; do bash -n "$script"; done

step "cargo fmt and clippy"
cargo fmt --check
# The fuzz crate is its own workspace (cargo-fuzz), outside the one above.
cargo fmt --check --manifest-path fuzz/Cargo.toml
cargo clippy --workspace --all-targets --locked -- -D warnings

step "the library's API docs build with every link resolved (cargo doc)"
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --locked -p topomesh

step "the library builds for Windows (scripts/check-windows.sh)"
bash scripts/check-windows.sh

step "real meshes (libcgal-demo) and tetrahedral meshes (tetgen), before the tests that read them"
bash scripts/fetch-meshes.sh
bash scripts/fetch-tets.sh --no-large

step "cargo test"
cargo test --workspace --locked

step "the exports against brute force on every real mesh (optimised: minutes unoptimised)"
cargo test --release --locked --test che_export

step "fuzzing: every target, fixed seed, then the kept corpus (scripts/fuzz.sh)"
bash scripts/fuzz.sh --runs 20000
bash scripts/fuzz.sh --replay

step "C and C++ tests (install, find_package, ctest, differential, valgrind)"
bash scripts/c-tests.sh

step "C and C++ tests under ASan+UBSan, stress tests under TSan (scripts/sanitize.sh)"
bash scripts/sanitize.sh

step "all tests passed"
