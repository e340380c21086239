#!/usr/bin/env bash
# Fuzzes every reader (parse) and both builders (che_build, chf_build) with libFuzzer and
# AddressSanitizer through cargo-fuzz. A crash, a panic or a failed assertion stops the run
# and leaves the input in fuzz/artifacts/TARGET/.
#
#   scripts/fuzz.sh                 # each target for 60 s
#   scripts/fuzz.sh --time 600      # longer
#   scripts/fuzz.sh --runs 20000    # a fixed number of inputs with a fixed seed: the same
#                                   # inputs on every machine (what scripts/test.sh runs)
#
# cargo-fuzz needs nightly-only compiler flags; RUSTC_BOOTSTRAP=1 lets the one stable
# toolchain of this machine accept them (for this build only).
set -euo pipefail
cd "$(dirname "$0")/.."
limit=(-max_total_time=60)
while [ $# -gt 0 ]; do
    case "$1" in
        --time) limit=(-max_total_time="$2"); shift 2 ;;
        --runs) limit=(-runs="$2" -seed=1); shift 2 ;;
        *) echo "usage: $0 [--time SECONDS | --runs N]" >&2; exit 2 ;;
    esac
done
if ! cargo fuzz --version >/dev/null 2>&1; then
    cargo install --locked cargo-fuzz
fi
export RUSTC_BOOTSTRAP=1
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$PWD/target}/fuzz"
cd fuzz
cargo fuzz build -O
for target in parse che_build chf_build; do
    corpus="corpus/$target"
    mkdir -p "$corpus"
    seeds=()
    [ -d "seeds/$target" ] && seeds=("seeds/$target")
    echo "== fuzz $target ${limit[*]}"
    rm -rf "artifacts/$target"
    log="$(mktemp)"
    # -max_len: the builders' inputs are small meshes; bigger ones only slow the search.
    if ! cargo fuzz run -O "$target" "$corpus" "${seeds[@]}" -- "${limit[@]}" -max_len=4096 \
        >"$log" 2>&1; then
        tail -n 60 "$log" >&2
        echo "fuzz $target failed: the input is in fuzz/artifacts/$target" >&2
        exit 1
    fi
    grep -E "^(#[0-9]+ *DONE|Done )" "$log" || tail -n 3 "$log"
    rm -f "$log"
done
