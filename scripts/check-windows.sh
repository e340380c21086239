#!/usr/bin/env bash
# The library builds for Windows: `cargo check` of the library crate for
# x86_64-pc-windows-gnu with warnings as errors (platform code behind `cfg` must leave
# nothing unused on the other side). Needs the target's standard library from rustup; where
# rustup cannot fetch it (no network to its server), says so and exits 0, so that the
# other tests still run.
set -euo pipefail
cd "$(dirname "$0")/.."
target=x86_64-pc-windows-gnu
if ! rustup target list --installed 2>/dev/null | grep -qx "$target"; then
    if ! timeout 300 rustup target add "$target" >/dev/null 2>&1; then
        echo "skipped: rustup could not install the $target standard library"
        exit 0
    fi
fi
RUSTFLAGS="-D warnings" CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$PWD/target}/windows" \
    cargo check --locked --target "$target" -p topomesh --lib
echo "the library checks for $target"
