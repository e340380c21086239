#!/usr/bin/env bash
# The scale run: topomesh against OpenMesh and CGAL on the generated torus at growing sizes,
# each run a process of its own so that each peak resident set is its own. Writes
# BENCHMARKS-scale.md: the method, the table of this run, the machine, the commit and this
# command, and the lines each run printed. The page holds the latest run only.
#
#   scripts/bench-scale.sh [--sizes "10000000 50000000 ..."] [--dir DIR] [--limit-gb G]
#
# For each size N (triangles, as `topomesh generate torus --triangles N` rounds them):
#   - OpenMesh and CGAL: c-tests/diff_surface's topomesh_bench_scale (bench_scale.cpp: the
#     same torus generated in C++, the peer built from the arrays as scripts/bench.sh's
#     benchmark builds it, the arrays freed, one VV sweep over every vertex);
#   - topomesh: `topomesh generate torus --triangles N -o DIR/torus-N.che` (generate, build
#     at level 2 on every thread, save), then `topomesh bench DIR/torus-N.che --repeat 1
#     --trusted-only --json` (the mapped trusted open, then the sweeps on the mapping), and the
#     file's size;
# each under /usr/bin/time -v: its wall-clock time, its maximum resident set, and whether it
# was killed (signal 9: the OOM killer) or ran out of memory. A library that fails at one
# size is not run at the larger ones. Builds and installs the package into a temporary
# prefix and builds topomesh_bench_scale against it, as scripts/bench.sh does.
#
# --sizes: the sizes (default "10000000 50000000 100000000 200000000 400000000").
# --stream-sizes: sizes for topomesh's streaming build alone (`generate --stream`; none by
# default), in a table of their own. --volume-stream-sizes: sizes in tetrahedra of the box
# streamed into a level-1 .chf (`generate box --tetrahedra N --stream`, then `bench` sweeps
# TT on the mapping), topomesh alone, in a table of their own (none by default). --dir:
# where the .che files go, kept there (default: a temporary directory, each file removed
# after its size; a level-2 file takes about 38 bytes per triangle). --limit-gb G: run each
# process under `ulimit -v` of G GiB, so that it fails with "out of memory" instead of
# meeting the OOM killer on a shared machine (a mapped .che counts against it too).
# Respects CARGO_TARGET_DIR and TOPOMESH_MESH_DIR.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cmdline="scripts/bench-scale.sh${*:+ $*}"
sizes=(10000000 50000000 100000000 200000000 400000000)
stream_sizes=()
volume_sizes=()
keep_dir=""
limit_gb=""
while (($#)); do
  case "$1" in
    --sizes) read -r -a sizes <<<"$2"; shift 2 ;;
    --stream-sizes) read -r -a stream_sizes <<<"$2"; shift 2 ;;
    --volume-stream-sizes) read -r -a volume_sizes <<<"$2"; shift 2 ;;
    --dir) keep_dir="$2"; shift 2 ;;
    --limit-gb) limit_gb="$2"; shift 2 ;;
    -h|--help) sed -n 2,31p "$0"; exit 0 ;;
    *) echo "bench-scale.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done
out="$root/BENCHMARKS-scale.md"
[[ -x /usr/bin/time ]] || { echo "bench-scale.sh: needs GNU time (apt-get install time)" >&2; exit 1; }
command -v jq >/dev/null || { echo "bench-scale.sh: needs jq (apt-get install jq)" >&2; exit 1; }

work="$(mktemp -d "${TMPDIR:-/tmp}/topomesh-scale.XXXXXX")"
trap 'rm -rf "$work"' EXIT
files="${keep_dir:-$work/files}"
mkdir -p "$files"
prefix="$work/prefix"
# shellcheck source=scripts/package.sh
source "$root/scripts/package.sh"
install_package "$root" "$prefix" "$work/pkg"
echo "== topomesh_bench_scale (OpenMesh and CGAL compile slowly: about a minute)"
cmake -S "$root/c-tests/diff_surface" -B "$work/diff" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DTOPOMESH_MESH_DIR="${TOPOMESH_MESH_DIR:-$HOME/.cache/topomesh/meshes}" >/dev/null
cmake --build "$work/diff" --target topomesh_bench_scale >/dev/null
harness="$work/diff/topomesh_bench_scale"
topomesh="$prefix/bin/topomesh"

# Runs "$@" under /usr/bin/time -v (and the memory limit) with stdout to $work/run.out;
# sets run_s (wall-clock seconds), run_gib (maximum resident set, GiB) and run_end ("ok",
# "killed (signal N)" or "exit N").
timed() {
  local t="$work/time.txt" rc=0
  (
    [[ -z "$limit_gb" ]] || ulimit -v "$((limit_gb * 1048576))"
    exec /usr/bin/time -v -o "$t" "$@"
  ) >"$work/run.out" 2>"$work/run.err" || rc=$?
  run_s="$(awk -F': ' '/Elapsed \(wall clock\)/ {
    n = split($2, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; printf "%.2f", s }' "$t")"
  run_gib="$(awk '/Maximum resident set size/ { printf "%.2f", $NF / 1048576 }' "$t")"
  local sig
  sig="$(sed -n 's/.*Command terminated by signal \([0-9]*\).*/\1/p' "$t")"
  if [[ -n "$sig" ]]; then run_end="killed (signal $sig)"
  elif ((rc)); then run_end="exit $rc"
  else run_end=ok; fi
}

# A value of a `key=value` line of the harness.
field() { tr ' ' '\n' <"$work/run.out" | sed -n "s/^$1=//p"; }

# One peer at size $2: its row cells (build s | peak GiB | VV sweep s) into $work/cells.$1,
# its line into $work/lines.md; returns 1 when it failed (not to be run at larger sizes).
peer_run() {
  local peer="$1" n="$2" cells
  echo "== $peer, $n triangles"
  timed "$harness" "$peer" "$n"
  echo "$peer $n: $(cat "$work/run.out") (/usr/bin/time: ${run_s} s, max RSS ${run_gib} GiB, $run_end)" \
    >>"$work/lines.md"
  [[ -z "$(field triangles)" ]] || field triangles >"$work/tris"
  if [[ "$run_end" != ok ]]; then
    cells="$run_end | $run_gib | –"
  elif grep -q "failed: out of memory" "$work/run.out"; then
    cells="out of memory | $run_gib | –"
  else
    cells="$(printf '%.2f' "$(field build_s)") | $(awk -v b="$(field peak_rss_bytes)" 'BEGIN { printf "%.2f", b / 2^30 }') | $(printf '%.3f' "$(field vv_sweep_s)")"
    echo "$cells" >"$work/cells.$peer"
    return 0
  fi
  echo "$cells" >"$work/cells.$peer"
  return 1
}

# topomesh at size $1 (with $2 = --stream, by the streaming build): generate (and save),
# then bench the file; cells (generate s | peak GiB | VV sweep s | bench max RSS GiB | file
# GiB) into $work/cells.topomesh, its lines into $work/lines.md; returns 1 when generate
# failed.
topomesh_run() {
  local n="$1" how="${2:-}" che="$files/torus-$1${2:+-streamed}.che" gen bytes sweep
  echo "== topomesh, $n triangles${how:+ ($how)}"
  timed "$topomesh" generate torus --triangles "$n" -o "$che" ${how:+"$how"}
  echo "topomesh generate $n${how:+ $how}: $(cat "$work/run.out") (/usr/bin/time: ${run_s} s," \
    "max RSS ${run_gib} GiB, $run_end)" >>"$work/lines.md"
  sed -n 's/.* \([0-9]*\) triangles,.*/\1/p' "$work/run.out" >>"$work/tris"
  if [[ "$run_end" != ok ]]; then
    echo "$run_end | $run_gib | – | – | –" >"$work/cells.topomesh"
    rm -f "$che"
    return 1
  fi
  gen="$run_s | $run_gib"
  bytes="$(stat -c %s "$che")"
  timed "$topomesh" bench "$che" --repeat 1 --trusted-only --json
  if [[ "$run_end" == ok ]]; then
    sweep="$(jq -r '.sweeps.relations[] | select(.relation == "VV") | .seconds.median' "$work/run.out")"
    echo "topomesh bench $n: opens $(jq -c '[.opens[] | {(.mode + " " + .verify): .seconds.median}] | add' \
      "$work/run.out"), VV sweep $sweep s (/usr/bin/time: ${run_s} s, max RSS ${run_gib} GiB)" >>"$work/lines.md"
    sweep="$(printf '%.3f' "$sweep")"
  else
    echo "topomesh bench $n: $run_end (/usr/bin/time: max RSS ${run_gib} GiB)" >>"$work/lines.md"
    sweep="$run_end"
  fi
  echo "$gen | $sweep | $run_gib | $(awk -v b="$bytes" 'BEGIN { printf "%.2f", b / 2^30 }')" >"$work/cells.topomesh"
  [[ -n "$keep_dir" ]] || rm -f "$che"
}

# Every size: the table rows into $work/rows.md.
run_all() {
  local n lib failed=() cells
  : >"$work/rows.md"
  : >"$work/lines.md"
  for n in "${sizes[@]}"; do
    : >"$work/tris"
    for lib in openmesh cgal topomesh; do
      if [[ " ${failed[*]:-} " == *" $lib "* ]]; then
        if [[ "$lib" == topomesh ]]; then cells="not run | | | |"; else cells="not run | |"; fi
        echo "$cells" >"$work/cells.$lib"
        continue
      fi
      if [[ "$lib" == topomesh ]]; then topomesh_run "$n" || failed+=("$lib")
      else peer_run "$lib" "$n" || failed+=("$lib"); fi
    done
    echo "| $(head -1 "$work/tris" | grep . || echo "$n") | $(cat "$work/cells.openmesh") | $(cat "$work/cells.cgal") | $(cat "$work/cells.topomesh") |" \
      >>"$work/rows.md"
  done
}

# Every --stream-sizes size, topomesh alone: the rows into $work/stream_rows.md.
run_streamed() {
  : >"$work/stream_rows.md"
  local n
  for n in "${stream_sizes[@]}"; do
    : >"$work/tris"
    topomesh_run "$n" --stream || true
    echo "| $(head -1 "$work/tris" | grep . || echo "$n") | $(cat "$work/cells.topomesh") |" \
      >>"$work/stream_rows.md"
  done
}

# The box of $1 tetrahedra streamed into a level-1 .chf, then its TT sweep on the mapping:
# the row into $work/volume_rows.md, the lines into $work/lines.md.
volume_run() {
  local n="$1" chf="$files/box-$1-streamed.chf" tets gen bytes sweep
  echo "== topomesh, $n tetrahedra (--stream)"
  timed "$topomesh" generate box --tetrahedra "$n" -o "$chf" --stream
  echo "topomesh generate box $n --stream: $(cat "$work/run.out") (/usr/bin/time: ${run_s} s," \
    "max RSS ${run_gib} GiB, $run_end)" >>"$work/lines.md"
  tets="$(sed -n 's/.* \([0-9]*\) tetrahedra,.*/\1/p' "$work/run.out")"
  if [[ "$run_end" != ok ]]; then
    echo "| ${tets:-$n} | $run_end | $run_gib | – | – | – |" >>"$work/volume_rows.md"
    rm -f "$chf"
    return
  fi
  gen="$run_s | $run_gib"
  bytes="$(stat -c %s "$chf")"
  timed "$topomesh" bench "$chf" --repeat 1 --trusted-only --json
  if [[ "$run_end" == ok ]]; then
    sweep="$(jq -r '.sweeps.relations[] | select(.relation == "TT") | .seconds.median' "$work/run.out")"
    echo "topomesh bench box $n: TT sweep $sweep s (/usr/bin/time: ${run_s} s, max RSS ${run_gib} GiB)" \
      >>"$work/lines.md"
    sweep="$(printf '%.3f' "$sweep")"
  else
    sweep="$run_end"
  fi
  echo "| $tets | $gen | $sweep | $run_gib | $(awk -v b="$bytes" 'BEGIN { printf "%.2f", b / 2^30 }') |" \
    >>"$work/volume_rows.md"
  [[ -n "$keep_dir" ]] || rm -f "$chf"
}

load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
run_all
run_streamed
: >"$work/volume_rows.md"
for n in "${volume_sizes[@]}"; do volume_run "$n"; done
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

# The machine and the toolchain, then the page.
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?')"
dirty="$(git -C "$root" status --porcelain 2>/dev/null | grep -q . && echo ' (with local changes)' || true)"
model="$(lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -1)"
cpus="$(nproc)"
mem="$(free -g | awk '/^Mem:/ {print $2 " GiB"}')"
swap="$(free -g | awk '/^Swap:/ {print $2 " GiB"}')"
os="$(. /etc/os-release 2>/dev/null && echo "$PRETTY_NAME" || uname -s)"
cxx="$(c++ --version | head -1)"
rustc_v="$(rustc --version)"
om_v="$(dpkg-query -W -f '${Version}' libopenmesh-dev 2>/dev/null || echo '?')"
cgal_v="$(dpkg-query -W -f '${Version}' libcgal-dev 2>/dev/null || echo '?')"
{
  echo "# Benchmarks: at scale"
  echo
  echo "<!-- Written by scripts/bench-scale.sh: run it again instead of editing this page. -->"
  echo
  echo "topomesh against OpenMesh (TriMesh, ArrayKernel) and CGAL (Surface_mesh) on the generated torus"
  echo "(\`topomesh generate torus --triangles N\`) as it grows towards and past the machine's memory. The"
  echo "latest run only; the head-to-head on real meshes is [BENCHMARKS.md](BENCHMARKS.md)."
  echo
  echo "## Method"
  echo
  echo "- Every run is a process of its own under \`/usr/bin/time -v\` (its wall-clock time and its maximum"
  echo "  resident set; a kill by the OOM killer shows as signal 9). A library that fails at one size is not"
  echo "  run at the larger ones."
  echo "- OpenMesh and CGAL: \`topomesh_bench_scale\` (\`c-tests/diff_surface/bench_scale.cpp\`) generates the"
  echo "  same torus in C++ (the same vertices, positions and triangles, in the same order), builds the peer"
  echo "  from the arrays as the head-to-head benchmark does (\`reserve()\` first, one thread), frees the"
  echo "  arrays and sweeps VV once over every vertex. *build s*: its wall-clock build time; *peak*: the"
  echo "  process's VmHWM (the arrays included, as they are while a program builds)."
  echo "- topomesh: \`topomesh generate torus --triangles N -o torus-N.che\` generates the arrays, builds"
  echo "  level 2 on every thread and saves the level file: *generate s* and *peak* are that whole process's."
  echo "  Then \`topomesh bench torus-N.che --repeat 1 --trusted-only --json\` opens the file mapped and trusted"
  echo "  (reading nothing) and sweeps VV, VF and FF on the mapping: *VV sweep s* is its VV sweep, *bench RSS*"
  echo "  that process's maximum resident set, where the mapped file's pages count while they are mapped."
  echo "- GiB are 2^30 bytes."
  echo
  echo "## Results"
  echo
  echo "Command: \`$cmdline\` ($(date -u +%Y-%m-%d), commit $commit$dirty)."
  echo
  echo "- Machine: $model, $cpus logical CPUs, $mem of memory, $swap of swap, $os. Load average (1, 5,"
  echo "  15 min) before the run: $load_before; after: $load_after.${limit_gb:+ Every process under \`ulimit -v\` of $limit_gb GiB.}"
  echo "- C++: $cxx; \`-O2 -DNDEBUG\`; OpenMesh $om_v, CGAL $cgal_v (Debian). topomesh: $rustc_v, cargo"
  echo "  release profile."
  echo
  echo "| triangles | OpenMesh build s | OpenMesh peak GiB | OpenMesh VV sweep s | CGAL build s | CGAL peak GiB | CGAL VV sweep s | topomesh generate s | topomesh peak GiB | topomesh VV sweep s | topomesh bench RSS GiB | .che file GiB |"
  echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  cat "$work/rows.md"
  if ((${#stream_sizes[@]})); then
    echo
    echo "The streaming build (\`topomesh generate torus --triangles N -o F.che --stream\`: the triangles"
    echo "go from the generator into the file, paired there; the resident set counts the file's mapped"
    echo "pages, which the system writes back and drops as memory fills), swept as above:"
    echo
    echo "| triangles | generate s | peak GiB | VV sweep s | bench RSS GiB | .che file GiB |"
    echo "|---:|---:|---:|---:|---:|---:|"
    cat "$work/stream_rows.md"
  fi
  if ((${#volume_sizes[@]})); then
    echo
    echo "A volume by the streaming build (\`topomesh generate box --tetrahedra N -o F.chf --stream\`: the"
    echo "tetrahedra go from the generator into a level-1 file, paired and counted there; the resident set"
    echo "counts the file's mapped pages), then \`topomesh bench F.chf --repeat 1 --trusted-only --json\`:"
    echo "the mapped trusted open and a TT sweep (the four neighbours of every tetrahedron) on the mapping:"
    echo
    echo "| tetrahedra | generate s | peak GiB | TT sweep s | bench RSS GiB | .chf file GiB |"
    echo "|---:|---:|---:|---:|---:|---:|"
    cat "$work/volume_rows.md"
  fi
  echo
  echo "What each run printed:"
  echo
  echo '```text'
  cat "$work/lines.md"
  echo '```'
} >"$work/page.md"
mv "$work/page.md" "$out"
echo "== wrote $out"
