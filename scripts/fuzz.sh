#!/usr/bin/env bash
# Fuzzes every reader and the C API with libFuzzer and AddressSanitizer through cargo-fuzz.
# A crash, a panic or a failed assertion stops the run and leaves the input in
# fuzz/artifacts/TARGET/. Targets: parse (every reader), che_build, che_edit, chf_build, chf_edit, capi_calls
# (sequences of C API calls on one handle), read_off, read_obj, read_ply, read_stl,
# read_tetgen, read_mesh, read_msh, read_vtk (one reader each), levelfile (saved .che and
# .chf files, mutated, opened loaded and mapped).
#
#   scripts/fuzz.sh                 # each target for 60 s, growing fuzz/corpus/TARGET/
#   scripts/fuzz.sh --time 600      # longer
#   scripts/fuzz.sh --runs 20000    # a fixed number of inputs with a fixed seed: the same
#                                   # inputs on every machine; the kept corpus is not changed
#   scripts/fuzz.sh --replay        # every input of the kept corpus once (-runs=0)
#   scripts/fuzz.sh --long          # each target for 10 million inputs or one hour
#   scripts/fuzz.sh --target NAME ...  # only that target (with any of the above)
#
# The kept corpus (fuzz/corpus/TARGET/, committed) is minimised after a run with
# `cargo fuzz cmin -O TARGET` in fuzz/ (see RELIABILITY.md).
# cargo-fuzz needs nightly-only compiler flags; RUSTC_BOOTSTRAP=1 lets the one stable
# toolchain of this machine accept them (for this build only).
set -euo pipefail
cd "$(dirname "$0")/.."
limit=(-max_total_time=60)
keep=1
targets=(parse che_build che_edit chf_build chf_edit capi_calls read_off read_obj read_ply read_stl read_tetgen
    read_mesh read_msh read_vtk levelfile)
chosen=()
while [ $# -gt 0 ]; do
    case "$1" in
        --time) limit=(-max_total_time="$2"); shift 2 ;;
        --runs) limit=(-runs="$2" -seed=1); keep=0; shift 2 ;;
        --replay) limit=(-runs=0); keep=0; shift ;;
        --long) limit=(-runs=10000000 -max_total_time=3600); shift ;;
        --target) chosen+=("$2"); shift 2 ;;
        *) echo "usage: $0 [--time SECONDS | --runs N | --replay | --long] [--target NAME]..." >&2
           exit 2 ;;
    esac
done
[ ${#chosen[@]} -gt 0 ] && targets=("${chosen[@]}")
if ! cargo fuzz --version >/dev/null 2>&1; then
    cargo install --locked cargo-fuzz
fi
export RUSTC_BOOTSTRAP=1
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$PWD/target}/fuzz"
cd fuzz
cargo fuzz build -O
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
for target in "${targets[@]}"; do
    corpus="corpus/$target"
    mkdir -p "$corpus"
    # libFuzzer writes what it finds into the first folder: the kept corpus on a search,
    # a scratch folder on a fixed-seed pass or a replay.
    dirs=("$corpus")
    if [ "$keep" = 0 ]; then
        mkdir -p "$scratch/$target"
        dirs=("$scratch/$target" "$corpus")
    fi
    [ -d "seeds/$target" ] && dirs+=("seeds/$target")
    # A reader's bad-input fixtures are seeds too (tests/fixtures/bad/FORMAT/).
    bad="../tests/fixtures/bad/${target#read_}"
    [[ "$target" == read_* && -d "$bad" ]] && dirs+=("$bad")
    echo "== fuzz $target ${limit[*]}"
    rm -rf "artifacts/$target"
    log="$scratch/$target.log"
    # -max_len: the builders' inputs are small meshes; bigger ones only slow the search. A
    # level file of a small mesh has a table of some 30 sections, 64 bytes each.
    max_len=4096
    [ "$target" = levelfile ] && max_len=16384
    if ! cargo fuzz run -O "$target" "${dirs[@]}" -- "${limit[@]}" -max_len="$max_len" \
        >"$log" 2>&1; then
        tail -n 60 "$log" >&2
        echo "fuzz $target failed: the input is in fuzz/artifacts/$target" >&2
        exit 1
    fi
    # The coverage line (cov: edges, ft: features, corp: inputs) and the count of inputs run.
    grep -E "^#[0-9]+[[:space:]]+(INITED|DONE)[[:space:]]" "$log" | tail -n 1 || true
    grep -E "^Done " "$log" || tail -n 3 "$log"
done
