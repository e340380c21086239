#!/usr/bin/env bash
# The head-to-head benchmark: topomesh (levels 1-3, every access path) against OpenMesh and
# CGAL Surface_mesh, in one process, from the same arrays. Writes the whole of
# BENCHMARKS.md: a short method section and the result tables of this run, with the
# machine, the compilers, the flags, the commit and this command. The page holds the latest
# run only; what changed between runs, and why, goes to CHANGELOG.md.
#
#   scripts/bench.sh [--reps N] [--export-meshes "A B"] [--edit-meshes "A B"] [--edit-reps N]
#                    [--levelfile-meshes "A B"] [MESH...]
#   scripts/bench.sh --edit-only [--edit-meshes "A B"] [--edit-reps N]
#   scripts/bench.sh --export-only [--reps N] [--export-meshes "A B"]
#   scripts/bench.sh --levelfile-only [--reps N] [--levelfile-meshes "A B"]
#   scripts/bench.sh --charts-only
#
# MESH: names in the mesh cache (default: bunny00 armadillo holes polygon_mesh
# blobby-shuffled bunny00-sub2 bunny00-sub3) or paths to .off files. Fetches the meshes
# (scripts/fetch-meshes.sh), builds and installs the package into a temporary prefix
# (the cmake/ project, as scripts/c-tests.sh does), builds c-tests/diff_surface's topomesh_bench
# and topomesh_bench_export (-O2, no -march=native) and runs them, the export benchmark on
# the --export-meshes (default: bunny00 bunny00-sub3), and the editing benchmark
# topomesh_bench_edit (flip storm, split refinement, simplification, garbage collection,
# against OpenMesh and CGAL) on the --edit-meshes (default: bunny00 bunny00-sub3), --edit-reps
# runs each (default 1: the large mesh takes minutes per library), and the level-file
# benchmark topomesh_bench_levelfile (the build against che_mesh_save and che_mesh_open,
# mapped or loaded, trusted or verified, and against OpenMesh reading its binary .om) on the
# --levelfile-meshes (default: bunny00 bunny00-sub3), --reps rounds. --edit-only runs the
# editing benchmark alone and replaces the page's Editing section with its tables,
# keeping the rest of the page; --export-only does the same for the Exports section and
# --levelfile-only for the Level files section (added when the page has none). Then writes
# the charts of the page (docs/bench-surfaces-*.svg, by tools/plot from the page's tables);
# --charts-only redraws them from the page as it is, without running anything. Respects
# CARGO_TARGET_DIR and TOPOMESH_MESH_DIR.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cmdline="scripts/bench.sh${*:+ $*}"
reps=5
meshes=()
export_meshes=(bunny00 bunny00-sub3)
edit_meshes=(bunny00 bunny00-sub3)
edit_reps=1
levelfile_meshes=(bunny00 bunny00-sub3)
edit_only=0
export_only=0
levelfile_only=0
charts_only=0
while (($#)); do
  case "$1" in
    --reps) reps="$2"; shift 2 ;;
    --export-meshes) read -r -a export_meshes <<<"$2"; shift 2 ;;
    --edit-meshes) read -r -a edit_meshes <<<"$2"; shift 2 ;;
    --edit-reps) edit_reps="$2"; shift 2 ;;
    --levelfile-meshes) read -r -a levelfile_meshes <<<"$2"; shift 2 ;;
    --edit-only) edit_only=1; shift ;;
    --export-only) export_only=1; shift ;;
    --levelfile-only) levelfile_only=1; shift ;;
    --charts-only) charts_only=1; shift ;;
    -h|--help) sed -n 2,32p "$0"; exit 0 ;;
    *) meshes+=("$1"); shift ;;
  esac
done
out="$root/BENCHMARKS.md"

# The measurements of the page's main tables, one per line, as tools/plot reads them
# (tools/plot/src/results.rs): mesh, triangles, library, kind, path, quantity, value.
surface_results() {
  awk -F'|' -v OFS='\t' '
    function trim(s) { gsub(/^[ \t]+|[ \t]+$/, "", s); return s }
    function name(l) { if (l == "CGAL") return "CGAL Surface_mesh"; sub(/^topomesh /, "CHE ", l); return l }
    /^### / { mesh = substr($0, 5); main = 0; next }
    /^[0-9]+ vertices, [0-9]+ triangles/ { split($0, w, " "); tris = w[3]; next }
    /^\| library \| path \| build/ { main = 1; next }
    !/^\|/ { main = 0; next }
    main && !/^\|---/ {
      lib = trim($2); path = trim($3); kind = (lib ~ /^topomesh/) ? "topomesh" : "peer"
      if (trim($4) != "″") {
        print mesh, tris, name(lib), kind, "", "build_ms", trim($4)
        print mesh, tris, name(lib), kind, "", "memory_bytes", sprintf("%.0f", trim($6) * 1048576)
      }
      split("VV VF FF EF curves", rel, " ")
      for (i = 1; i <= 5; i++) {
        v = trim($(7 + i))
        if (v != "–" && v != "") print mesh, tris, name(lib), kind, path, rel[i], v
      }
    }' "$1"
}

charts() {
  local results="${TMPDIR:-/tmp}/topomesh-bench-results.$$.tsv"
  surface_results "$out" >"$results"
  (cd "$root" && cargo run -q -p topomesh-plot -- --results "$results" --out-dir "$root/docs" \
    --prefix bench-surfaces --element triangle)
  rm -f "$results"
}

if ((charts_only)); then
  charts
  exit 0
fi
((${#meshes[@]})) || meshes=(bunny00 armadillo holes polygon_mesh blobby-shuffled bunny00-sub2 bunny00-sub3)
dir="${TOPOMESH_MESH_DIR:-$HOME/.cache/topomesh/meshes}"

"$root/scripts/fetch-meshes.sh"

work="$(mktemp -d "${TMPDIR:-/tmp}/topomesh-bench.XXXXXX")"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
# shellcheck source=scripts/package.sh
source "$root/scripts/package.sh"
install_package "$root" "$prefix" "$work/pkg"
echo "== topomesh_bench (OpenMesh and CGAL compile slowly: about a minute)"
cmake -S "$root/c-tests/diff_surface" -B "$work/diff" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DTOPOMESH_MESH_DIR="$dir" >/dev/null
if ((edit_only)); then
  cmake --build "$work/diff" --target topomesh_bench_edit >/dev/null
elif ((export_only)); then
  cmake --build "$work/diff" --target topomesh_bench_export >/dev/null
elif ((levelfile_only)); then
  cmake --build "$work/diff" --target topomesh_bench_levelfile >/dev/null
else
  cmake --build "$work/diff" --target topomesh_bench topomesh_bench_export topomesh_bench_edit \
    topomesh_bench_levelfile >/dev/null
fi

# The editing benchmark into $work/editing.md: a section of its own, with its command,
# commit and load, so that --edit-only can replace it in a page written by a full run.
editing() {
  local files=() m load0
  for m in "${edit_meshes[@]}"; do
    if [[ -f "$m" ]]; then files+=("$m"); else files+=("$dir/$m.off"); fi
  done
  echo "== editing on ${#files[@]} meshes, $edit_reps repetition(s)"
  load0="$(cut -d' ' -f1-3 /proc/loadavg)"
  "$work/diff/topomesh_bench_edit" --reps "$edit_reps" --md "$work/edit-tables.md" "${files[@]}"
  {
    echo
    echo "## Editing"
    echo
    echo "\`c-tests/diff_surface/bench_edit.cpp\` (\`topomesh_bench_edit\`): the same operations, written once in"
    echo "\`edit_policy.hpp\` over a small adapter per library, on topomesh's C++ wrapper (\`topomesh::Surface\`,"
    echo "levels 2 and 3), OpenMesh's TriMesh and CGAL's Surface_mesh, each on a fresh build from the same arrays"
    echo "(the build untimed; CPU time of the benchmark thread):"
    echo
    echo "- flip storm: one million uniformly random edge ids from the same seeded generator (mt19937_64);"
    echo "  each flipped when the library's check allows it (topomesh \`is_flip_ok\`, OpenMesh \`is_flip_ok\`;"
    echo "  CGAL has none: an interior edge whose flipped edge does not exist yet, what the other two check);"
    echo "- edge-split refinement by longest-edge bisection: passes over the edge ids, new edges included,"
    echo "  split at its midpoint every edge longer than 1.5 × the mean edge length that is the longest of its"
    echo "  triangles, until a pass splits none (splitting every long edge in id order runs away on bunny00, in"
    echo "  OpenMesh as in topomesh); topomesh \`split\`, OpenMesh \`split(EdgeHandle, Point)\`, CGAL"
    echo "  \`Euler::split_edge\` and \`Euler::split_face\` on each side;"
    echo "- shortest-edge simplification to 10 % of the triangles: the policy of \`topomesh simplify\` (a heap"
    echo "  with one entry per edge, the library's link-condition check, no triangle turned over, the merged"
    echo "  vertex at the midpoint; OpenMesh \`is_collapse_ok\`/\`collapse\`, CGAL"
    echo "  \`does_satisfy_link_condition\`/\`Euler::collapse_edge\`);"
    echo "- garbage collection after removing every other triangle id (only the collection timed; topomesh's"
    echo "  wrapper also returns the old -> new maps, the peers none)."
    echo
    echo "The same policy; the edges may differ: the counts are given per library. The three number the edges"
    echo "of a fresh build alike (by first use in the triangle order), so the flips and collapses chosen agree;"
    echo "the split passes number new edges differently (same splits, a few more or fewer edges looked at)."
    echo "The targets: each operation at least 2× faster than the faster peer (ratio at most 0.50×), memory"
    echo "while editing at most 0.6× OpenMesh's. Ratios from one run on a shared machine. The simplification"
    echo "spends much of its time in the policy's own queue, the same for every library; a second table gives"
    echo "that share, timed alone (the queue operations of one more run replayed), and what is left. A third"
    echo "gives the floor of the flip storm: the same draws on copies of CHE's arrays alone (\`floor_che.hpp\`),"
    echo "what a library built on these arrays cannot beat; a target below it cannot be met on them."
    echo
    echo "Command: \`$cmdline\` ($(date -u +%Y-%m-%d), commit $commit$dirty); $edit_reps repetition(s); load"
    echo "average before: $load0; after: $(cut -d' ' -f1-3 /proc/loadavg). Machine and compilers as above."
    cat "$work/edit-tables.md"
  } >"$work/editing.md"
}
# The export benchmark into $work/exports.md: a section of its own, with its command, commit
# and load, so that --export-only can replace it in a page written by a full run.
exports() {
  local files=() m load0
  for m in "${export_meshes[@]}"; do
    if [[ -f "$m" ]]; then files+=("$m"); else files+=("$dir/$m.off"); fi
  done
  ((${#files[@]})) || return 0
  echo "== exports on ${#files[@]} meshes"
  load0="$(cut -d' ' -f1-3 /proc/loadavg)"
  "$work/diff/topomesh_bench_export" --reps "$reps" --md "$work/export-tables.md" "${files[@]}"
  {
    echo
    echo "## Exports"
    echo
    echo "Eigen $eigen_v, meshoptimizer $meshopt_v (Debian); the rest as above. Command: \`$cmdline\`"
    echo "($(date -u +%Y-%m-%d), commit $commit$dirty); load average before: $load0; after:"
    echo "$(cut -d' ' -f1-3 /proc/loadavg)."
    cat "$work/export-tables.md"
  } >"$work/exports.md"
}
# The level-file benchmark into $work/levelfile.md: a section of its own, with its command,
# commit and load, so that --levelfile-only can replace it in a page written by a full run.
# Its temporary .che and .om files go to $work.
levelfile() {
  local files=() m load0
  for m in "${levelfile_meshes[@]}"; do
    if [[ -f "$m" ]]; then files+=("$m"); else files+=("$dir/$m.off"); fi
  done
  ((${#files[@]})) || return 0
  echo "== level files on ${#files[@]} meshes, $reps rounds"
  load0="$(cut -d' ' -f1-3 /proc/loadavg)"
  TMPDIR="$work" "$work/diff/topomesh_bench_levelfile" --reps "$reps" --md "$work/levelfile-tables.md" "${files[@]}"
  {
    echo
    echo "## Level files"
    echo
    echo "\`c-tests/diff_surface/bench_levelfile.cpp\` (\`topomesh_bench_levelfile\`): what opening a saved CHE costs"
    echo "(\`che_mesh_save\`, \`che_mesh_open\`; the layout in [docs/level-files.md](docs/level-files.md)) against"
    echo "building it from the arrays, and against OpenMesh reading its own binary format. In one process,"
    echo "interleaved rounds (each runs every step once, from a different first one), medians of the"
    echo "wall-clock time (the build and the verified opens run on every thread), the process's CPU time beside it:"
    echo
    echo "- the build: \`che_mesh_from_triangles_ex\` at level 2 on every thread (\`che_build_options_default\`,"
    echo "  what a program without a level file pays) and on one;"
    echo "- \`che_mesh_save\` of that mesh to a .che (a temporary file written, synced, renamed);"
    echo "- \`che_mesh_open\` with \`TOPOMESH_OPEN_MAPPED | TOPOMESH_OPEN_TRUSTED\` (the header and the section table"
    echo "  checked; the arrays are the file's pages), \`TOPOMESH_OPEN_MAPPED\` (every checksum and invariant checked)"
    echo "  and 0 (read into memory, everything checked), each with the first query, vertex 0's one-ring"
    echo "  (\`che_vertex_vertices\`); the mapped trusted open also right after an untimed one (caches warm, as for"
    echo "  a program opening one file after another);"
    echo "- OpenMesh: \`OpenMesh::IO::read_mesh\` into its TriMesh of the same mesh written once as a binary .om"
    echo "  (\`write_mesh\`, \`Options::Binary\`), then vertex 0's one-ring;"
    echo "- a VV sweep over every vertex through the C++ wrapper (\`Surface::vertex_vertices\`, the *C++ wrapper*"
    echo "  path of the tables above) on the built mesh, on a mapped trusted mesh just opened (its pages touched"
    echo "  for the first time) and on one whose pages an earlier sweep touched."
    echo
    echo "The files are in the page cache (each was just written): these are warm-cache times, not a disk's."
    echo "The targets: the mapped trusted open with its first query at least 1000× faster than the build (the"
    echo "faster of the two) and 100× faster than OpenMesh's read; a verified open at least 5× faster than the"
    echo "build; the mapped sweep at most 1.20× the in-memory one."
    echo
    echo "Command: \`$cmdline\` ($(date -u +%Y-%m-%d), commit $commit$dirty); $reps rounds; load average"
    echo "before: $load0; after: $(cut -d' ' -f1-3 /proc/loadavg). Machine and compilers as above."
    cat "$work/levelfile-tables.md"
  } >"$work/levelfile.md"
}
# Replaces the page's section "## $1" (up to the next "## " heading) with the file $2 (a
# blank line, then the section), or adds it at the end when the page has none: the page
# into $work/page.md. Blank lines before the replaced section are dropped, as its file
# brings its own.
replace_section() {
  awk -v head="## $1" -v file="$2" '
    function section(  l) { while ((getline l < file) > 0) print l; close(file); done = 1 }
    $0 == head { blanks = 0; section(); skip = 1; next }
    skip && /^## / { skip = 0; print "" }
    skip { next }
    /^$/ { blanks++; next }
    { for (; blanks > 0; blanks--) print ""; print }
    END { if (!done) section() }' "$out" >"$work/page.md"
}
eigen_v="$(dpkg-query -W -f '${Version}' libeigen3-dev 2>/dev/null || echo 'not installed')"
meshopt_v="$(dpkg-query -W -f '${Version}' libmeshoptimizer-dev 2>/dev/null || echo 'not installed')"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?')"
dirty="$(git -C "$root" status --porcelain 2>/dev/null | grep -q . && echo ' (with local changes)' || true)"
if ((edit_only)); then
  [[ -f "$out" ]] || { echo "bench.sh: --edit-only needs a page written by a full run" >&2; exit 1; }
  editing
  replace_section Editing "$work/editing.md"
  mv "$work/page.md" "$out"
  echo "== wrote $out (Editing)"
  exit 0
fi
if ((export_only)); then
  [[ -f "$out" ]] || { echo "bench.sh: --export-only needs a page written by a full run" >&2; exit 1; }
  exports
  replace_section Exports "$work/exports.md"
  mv "$work/page.md" "$out"
  echo "== wrote $out (Exports)"
  exit 0
fi
if ((levelfile_only)); then
  [[ -f "$out" ]] || { echo "bench.sh: --levelfile-only needs a page written by a full run" >&2; exit 1; }
  levelfile
  replace_section "Level files" "$work/levelfile.md"
  mv "$work/page.md" "$out"
  echo "== wrote $out (Level files)"
  exit 0
fi

files=()
for m in "${meshes[@]}"; do
  if [[ -f "$m" ]]; then files+=("$m"); else files+=("$dir/$m.off"); fi
done
echo "== running on ${#files[@]} meshes, $reps repetitions"
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
"$work/diff/topomesh_bench" --reps "$reps" --md "$work/tables.md" "${files[@]}"
: >"$work/exports.md"
exports
: >"$work/editing.md"
((${#edit_meshes[@]})) && editing
: >"$work/levelfile.md"
levelfile
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

# The machine and the toolchain.
model="$(lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -1)"
cpus="$(nproc)"
threads="$(lscpu | sed -n 's/^Thread(s) per core:[[:space:]]*//p' | head -1)"
mem="$(free -g | awk '/^Mem:/ {print $2 " GiB"}')"
os="$(. /etc/os-release 2>/dev/null && echo "$PRETTY_NAME" || uname -s)"
cxx="$(c++ --version | head -1)"
rustc_v="$(rustc --version)"
om_v="$(dpkg-query -W -f '${Version}' libopenmesh-dev 2>/dev/null || echo '?')"
cgal_v="$(dpkg-query -W -f '${Version}' libcgal-dev 2>/dev/null || echo '?')"
{
  echo "# Benchmarks: surfaces"
  echo
  echo "<!-- Written by scripts/bench.sh: run it again instead of editing this page. -->"
  echo
  echo "topomesh's CHE against OpenMesh (TriMesh, ArrayKernel) and CGAL (Surface_mesh), in one"
  echo "process, built from the same arrays, with the same sweeps. The latest run only: what changed"
  echo "between runs, and why, is in [CHANGELOG.md](CHANGELOG.md); the tetrahedral head-to-head is"
  echo "[BENCHMARKS-volumes.md](BENCHMARKS-volumes.md)."
  echo
  echo "## Method"
  echo
  echo "- \`scripts/bench.sh [--reps N] [MESH...]\` fetches the meshes (\`scripts/fetch-meshes.sh\`),"
  echo "  installs the package into a temporary prefix, builds the harness \`topomesh_bench\`"
  echo "  (\`c-tests/diff_surface/bench.cpp\`) against it and rewrites this page."
  echo "- Each build and sweep runs N times, interleaved across the libraries (round r builds each"
  echo "  of them in turn, from a different first one, then runs each sweep in turn); the tables give"
  echo "  the median of the benchmark thread's CPU time (CLOCK_THREAD_CPUTIME_ID, user + system: the"
  echo "  machine may be shared, and wall-clock time counts the waits for a core; it is shown for"
  echo "  builds). Build times include the positions (every library stores them) and the page faults"
  echo "  of fresh memory. topomesh builds on one thread (\`threads\` 1), as the peers do."
  echo "- Connectivity memory is counted from container sizes: OpenMesh V·sizeof(Vertex) +"
  echo "  E·sizeof(Edge) + F·sizeof(Face); CGAL 4 B per vertex, 16 B per half-edge, 4 B per face, plus"
  echo "  its removed-flag bits; topomesh \`che_mesh_memory().topology\`. RSS growth is the resident-set"
  echo "  growth over one build (/proc/self/statm, after malloc_trim), positions included."
  echo "- Paths: *C API* is one call per element into a caller buffer; *star iterator* is"
  echo "  che_star_begin/next on the stack; *CSR bulk* one call for all rows (time includes the call);"
  echo "  *C++ wrapper* the ranges of topomesh.hpp; *zero-copy* walks the V/O/VH/CH arrays with"
  echo "  che_next/che_prev inline. A sweep visits every element and folds the answers into a"
  echo "  checksum: equal checksums mean every library and path gave the same answers. The"
  echo "  differential tests (ctest -L diff) compare the answers element by element."
  echo "- The Rust core alone: \`cargo bench --bench che\` (criterion; meshes from"
  echo "  \`\$TOPOMESH_MESH_DIR\`, else the cache of \`scripts/fetch-meshes.sh\`) times the build at"
  echo "  levels 1-3 on one thread and on all, and the VV, VF, FF and EF sweeps; it is not recorded here."
  echo "- Exports (\`c-tests/diff_surface/bench_export.cpp\`, on the meshes of \`--export-meshes\`): the"
  echo "  half-edge arrays against building OpenMesh's TriMesh from the arrays, the Laplacian as CSR"
  echo "  against OpenMesh's one-rings and Eigen's triplets, triangle strips against meshoptimizer's"
  echo "  \`meshopt_stripify\` (as given, and after its \`meshopt_optimizeVertexCacheStrip\`), Betti numbers"
  echo "  against the build; same timing rules (CPU time, medians, interleaved rounds)."
  echo "- Level files (\`c-tests/diff_surface/bench_levelfile.cpp\`, on the meshes of \`--levelfile-meshes\`):"
  echo "  the build against \`che_mesh_save\` and \`che_mesh_open\` (mapped or loaded, trusted or verified) and"
  echo "  against OpenMesh reading its binary .om; wall-clock medians (see its section)."
  echo
  echo "## Charts"
  echo
  echo "Drawn by \`tools/plot\` from the tables below (\`scripts/bench.sh --charts-only\` redraws them)."
  echo "Memory against sweep time on the largest mesh (the sweeps every library ran, each at its"
  echo "fastest access path), the build against the mesh size, and topomesh against the faster peer:"
  echo
  echo "![memory against sweep time](docs/bench-surfaces-memory.svg)"
  echo
  echo "![build time against mesh size](docs/bench-surfaces-build.svg)"
  echo
  echo "![ratios to the faster peer](docs/bench-surfaces-ratios.svg)"
  echo
  echo "## Results"
  echo
  echo "Command: \`$cmdline\` ($(date -u +%Y-%m-%d), commit $commit$dirty)."
  echo
  echo "- Machine: $model, $cpus logical CPUs ($threads thread(s) per core), $mem, $os. Load average"
  echo "  (1, 5, 15 min) before the run: $load_before; after: $load_after."
  if awk -v l="${load_before%% *}" -v n="$cpus" 'BEGIN { exit !(l > n) }'; then
    echo "  The machine was busy (load above its $cpus CPUs): the CPU times are the fair comparison;"
    echo "  the wall-clock times include the waits for a core."
  fi
  echo "- C++: $cxx; \`-O2 -DNDEBUG\` (no \`-march=native\`); OpenMesh $om_v (Debian, TriMesh_ArrayKernelT with"
  echo "  double points), CGAL $cgal_v (Surface_mesh of Epick points). Both peers get \`reserve()\` (vertex and face"
  echo "  counts, edges estimated as 3T/2) before the build."
  echo "- topomesh: $rustc_v, cargo release profile (opt-level 3, debug = 1), through the installed"
  echo "  libtopomesh.so; single-threaded."
  echo "- $reps repetitions of each build and sweep."
  cat "$work/tables.md"
  cat "$work/exports.md"
  cat "$work/editing.md"
  cat "$work/levelfile.md"
} > "$work/page.md"
mv "$work/page.md" "$out"
echo "== wrote $out"
charts
