#!/usr/bin/env bash
# The volume head-to-head benchmark: topomesh's CHF (levels 1-3, per-element C calls, CSR
# bulk calls, the zero-copy O view) against CGAL's Triangulation_3 built by
# CGAL::build_triangulation, in one process, from the same arrays. Writes the whole of
# BENCHMARKS-volumes.md: a short method section and the result tables of this run, with
# the machine, the flags, the commit and this command. The page holds the latest run only;
# what changed between runs, and why, goes to CHANGELOG.md.
#
#   scripts/bench-volumes.sh [--reps N] [--edit-ops N] [--prefix DIR] [--out FILE] [MESH...]
#   scripts/bench-volumes.sh --edit-only [--edit-ops N] [--prefix DIR] [--out FILE] [MESH...]
#   scripts/bench-volumes.sh --charts-only [--out FILE]
#
# MESH: names under <mesh dir>/tets (default: blobby-12k armadillo-101k bunny00-1m; the
# editing section runs on armadillo-101k and bunny00-1m by default, on the MESHes given
# otherwise). Makes the meshes (scripts/fetch-tets.sh: tetgen, the 1M one takes under a
# minute), builds and installs the package into a temporary prefix (or uses --prefix, an
# installed one), builds c-tests/diff_volume's topomesh_bench_vol and topomesh_bench_vol_edit
# (-O2 -DNDEBUG, no -march=native; the CGAL translation unit takes about a minute) and runs
# them (--edit-ops: operations of each editing run, default a million; --edit-only runs the
# editing harness alone and replaces the page's Editing section, keeping the rest). Then writes the charts of the page
# (docs/bench-volumes-*.svg, by tools/plot from the page's tables); --charts-only redraws
# them from the page as it is (adding the charts section if it has none), without running
# anything. Respects CARGO_TARGET_DIR and TOPOMESH_MESH_DIR.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cmdline="scripts/bench-volumes.sh${*:+ $*}"
reps=5
edit_ops=1000000
prefix=""
out="$root/BENCHMARKS-volumes.md"
meshes=()
charts_only=0
edit_only=0
while (($#)); do
  case "$1" in
    --reps) reps="$2"; shift 2 ;;
    --prefix) prefix="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --charts-only) charts_only=1; shift ;;
    --edit-only) edit_only=1; shift ;;
    --edit-ops) edit_ops="$2"; shift 2 ;;
    -h|--help) sed -n 2,25p "$0"; exit 0 ;;
    *) meshes+=("$1"); shift ;;
  esac
done

# The measurements of the page's tables, one per line, as tools/plot reads them
# (tools/plot/src/results.rs): mesh, tetrahedra, library, kind, path, quantity, value. The
# builds are the one-thread ones, as CGAL's.
volume_results() {
  awk -F'|' -v OFS='\t' '
    function trim(s) { gsub(/^[ \t]+|[ \t]+$/, "", s); return s }
    function name(l) {
      if (l ~ /^CGAL/) return "CGAL Triangulation_3"
      sub(/^topomesh /, "CHF ", l); sub(/,.*/, "", l); return l
    }
    function emit(l, path, q, v) {
      print mesh, tets, name(l), (l ~ /^CGAL/) ? "peer" : "topomesh", path, q, v
    }
    /^### / { split(substr($0, 5), h, ":"); mesh = h[1]; split(h[2], w, " "); tets = w[3]; table = ""; next }
    /^\| \| ms \| CGAL/ { table = "build"; next }
    /^\| \| structure \|/ { table = "memory"; next }
    /^\| relation \| library \| access/ { table = "sweep"; next }
    !/^\|/ { table = ""; next }
    /^\|---/ { next }
    table == "build" && (trim($2) ~ /^CGAL/ || trim($2) ~ /, 1 thread$/) { emit(trim($2), "", "build_ms", trim($3)) }
    table == "memory" { emit(trim($2), "", "memory_bytes", sprintf("%.0f", trim($3) * 1048576)) }
    table == "sweep" { emit(trim($3), trim($4), trim($2), trim($5)) }
  ' "$1"
}

charts_section() {
  echo "## Charts"
  echo
  echo "Drawn by \`tools/plot\` from the tables below (\`scripts/bench-volumes.sh --charts-only\` redraws"
  echo "them). Memory against sweep time on the largest mesh (TT, VT, ET and VV, each library at its"
  echo "fastest access path), the one-thread build against the mesh size, and topomesh against CGAL:"
  echo
  echo "![memory against sweep time](docs/bench-volumes-memory.svg)"
  echo
  echo "![build time against mesh size](docs/bench-volumes-build.svg)"
  echo
  echo "![ratios to CGAL](docs/bench-volumes-ratios.svg)"
  echo
}

charts() {
  local results="${TMPDIR:-/tmp}/topomesh-bench-vol-results.$$.tsv"
  volume_results "$out" >"$results"
  (cd "$root" && cargo run -q -p topomesh-plot -- --results "$results" --out-dir "$root/docs" \
    --prefix bench-volumes --element tetrahedron)
  rm -f "$results"
}

# The editing section of the page: method, this run's command and commit, the tables of
# topomesh_bench_vol_edit (its first line, the versions, left out).
editing_section() {
  echo "## Editing"
  echo
  echo "topomesh's editing operations (\`include/detail/volume_edit.hpp\`, the C++ wrapper over the"
  echo "C API) against CGAL's \`Triangulation_3\` built as above from the same tetrahedra, in one process"
  echo "(\`topomesh_bench_vol_edit\`, \`c-tests/diff_volume/bench_vol_edit.cpp\`), with one seeded policy"
  echo "for both sides (\`edit_policy.hpp\`): each operation draws a live tetrahedron uniformly (both"
  echo "sides keep a list of the live ones, updated in O(1) per operation and timed with it)."
  echo "Times are CPU time of the process (every timed run is on one thread): the machine is shared,"
  echo "and the wall clock would count the other processes' turns."
  echo
  echo "- 1-4 splits: the drawn tetrahedron split at its centroid. CGAL: \`Triangulation_3::insert_in_cell\`"
  echo "  on the triangulation built from the same tetrahedra (not from the points: a Delaunay"
  echo "  triangulation of the points is another mesh, and the split is a pure combinatorial"
  echo "  operation there too). It checks nothing; topomesh's \`split\` verifies the operation (the"
  echo "  four new tetrahedra positive, the stars manifold) before doing it. Level 1 edits as level"
  echo "  2 once its first edit has stored \`O\`, \`VH\` and the ids: only that first split is timed"
  echo "  for it (\`--level1\` of the harness runs the whole storm). The CHF floor row: the same"
  echo "  draws on copies of CHF's \`V\` and \`O\` alone (\`floor_chf.hpp\`: unchecked like CGAL's, no"
  echo "  position for the new vertex), what a library built on these arrays cannot beat, in time and"
  echo "  in memory; a target below it cannot be met on them."
  echo "- Flip storm: for each attempt a 2-3 flip of one of the drawn tetrahedron's faces or a 3-2"
  echo "  flip of one of its edges (a coin), checked then done when allowed. CGAL:"
  echo "  \`Triangulation_3::flip(c, i)\` and \`flip(c, i, j)\`, which check (finite, degree 3, convex"
  echo "  position) and return false on a refusal. topomesh: \`can_flip_23\`/\`can_flip_32\` then"
  echo "  \`flip_23\`/\`flip_32\` (the check-then-act pattern of the wrapper, two verifications for an"
  echo "  accepted flip), and the C calls alone (one verification; a refusal is a status). The two"
  echo "  libraries number local faces and edges differently, so their sequences of flips differ:"
  echo "  compare the accepted counts, not only the times. Level 1 is not timed here: before its"
  echo "  first edit a face or edge id costs O(T) below level 2, after it level 1 edits as level 2."
  echo "- Compaction: half the tetrahedra removed (in decreasing x of the centroid; removals that"
  echo "  would pinch a vertex or an edge are refused and skipped), then \`garbage_collect\`."
  echo "  CGAL's \`Triangulation_3\` has no removal of cells that keeps a triangulation, and its"
  echo "  \`Compact_container\` never compacts (freed cells are reused in place): the comparable"
  echo "  operation is building the triangulation of the remaining tetrahedra"
  echo "  (\`build_triangulation\`), which is also what topomesh's \`garbage_collect\` does (a fresh"
  echo "  build of the live tetrahedra plus the old-to-new maps); a fresh topomesh build of the same"
  echo "  tetrahedra is given for reference."
  echo "- Memory after the splits: container sizes (CGAL's cells and vertices as in the build table;"
  echo "  topomesh's \`chf_mesh_memory\` topology, which counts the edit state: marks, face and edge"
  echo "  ids), and the growth of the resident set over build plus edits. A never-edited CHF has"
  echo "  no edit state (one empty pointer: it is made by the first accepted edit, never by a check or"
  echo "  a refused edit); the last line of each mesh checks that its \`chf_mesh_memory\` and resident"
  echo "  set stay put over checks and refused edits."
  echo
  echo "Command: \`$cmdline\` ($(date -u +%Y-%m-%d), commit $commit$dirty); $edit_ops operations per run"
  echo "(one run each; the machine is shared). Load average before: $edit_load_before; after: $edit_load_after."
  cat "$work/edit.md" | sed '1d'
}

if ((charts_only)); then
  if ! grep -q '^## Charts' "$out"; then
    section="$(charts_section)"
    awk -v s="$section" '/^## Results/ { print s; print "" } { print }' "$out" >"$out.new"
    mv "$out.new" "$out"
  fi
  charts
  exit 0
fi
edit_meshes=("${meshes[@]}")
((${#meshes[@]})) || meshes=(blobby-12k armadillo-101k bunny00-1m)
((${#edit_meshes[@]})) || edit_meshes=(armadillo-101k bunny00-1m)
dir="${TOPOMESH_MESH_DIR:-$HOME/.cache/topomesh/meshes}"

"$root/scripts/fetch-tets.sh"

work="$(mktemp -d "${TMPDIR:-/tmp}/topomesh-bench-vol.XXXXXX")"
trap 'rm -rf "$work"' EXIT
if [[ -z "$prefix" ]]; then
  prefix="$work/prefix"
  # shellcheck source=scripts/package.sh
  source "$root/scripts/package.sh"
  install_package "$root" "$prefix" "$work/pkg"
fi
echo "== topomesh_bench_vol, topomesh_bench_vol_edit (the CGAL translation unit compiles slowly: about a minute)"
# An empty build type: the only optimisation flags are the target's -O2 -DNDEBUG.
cmake -S "$root/c-tests/diff_volume" -B "$work/diffvol" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE= \
  -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
  -DTOPOMESH_MESH_DIR="$dir" >/dev/null
cmake --build "$work/diffvol" --target topomesh_bench_vol topomesh_bench_vol_edit >/dev/null

mesh_base() { if [[ -f "$1.ele" ]]; then echo "$1"; else echo "$dir/tets/$1"; fi; }
bases=()
for m in "${meshes[@]}"; do bases+=("$(mesh_base "$m")"); done
edit_bases=()
for m in "${edit_meshes[@]}"; do edit_bases+=("$(mesh_base "$m")"); done
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"
if ((!edit_only)); then
  echo "== running on ${#bases[@]} meshes, $reps repetitions"
  load_before="$load_after"
  "$work/diffvol/topomesh_bench_vol" --reps "$reps" "${bases[@]}" | tee "$work/tables.md"
  load_after="$(cut -d' ' -f1-3 /proc/loadavg)"
fi
echo "== editing on ${#edit_bases[@]} meshes, $edit_ops operations per run"
edit_load_before="$load_after"
"$work/diffvol/topomesh_bench_vol_edit" --ops "$edit_ops" --reps "$reps" "${edit_bases[@]}" | tee "$work/edit.md"
edit_load_after="$(cut -d' ' -f1-3 /proc/loadavg)"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?')"
dirty="$(git -C "$root" status --porcelain 2>/dev/null | grep -q . && echo ' (with local changes)' || true)"
if ((edit_only)); then
  # The page up to its Editing section (the other tables stay those of their own run).
  { awk '/^## Editing/ { exit } { print }' "$out" | sed -e :a -e '/^\n*$/{$d;N;ba' -e '}'; echo; editing_section; } >"$out.new"
  mv "$out.new" "$out"
  echo "== wrote the Editing section of $out"
  exit 0
fi

model="$(lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -1)"
cpus="$(nproc)"
mem="$(free -g | awk '/^Mem:/ {print $2 " GiB"}')"
os="$(. /etc/os-release 2>/dev/null && echo "$PRETTY_NAME" || uname -s)"
cxx="$(c++ --version | head -1)"
rustc_v="$(rustc --version 2>/dev/null || echo '?')"
cgal_v="$(dpkg-query -W -f '${Version}' libcgal-dev 2>/dev/null || echo '?')"
tetgen_v="$(dpkg-query -W -f '${Version}' tetgen 2>/dev/null || echo '?')"

{
  echo "# Benchmarks: volumes"
  echo
  echo "<!-- Written by scripts/bench-volumes.sh: run it again instead of editing this page. -->"
  echo
  echo "topomesh's CHF against CGAL's \`Triangulation_3\`, in one process, built from the same"
  echo "tetrahedra. The latest run only: what changed between runs, and why, is in"
  echo "[CHANGELOG.md](CHANGELOG.md); the surface head-to-head is [BENCHMARKS.md](BENCHMARKS.md)."
  echo
  echo "## Method"
  echo
  echo "- \`scripts/bench-volumes.sh [--reps N] [--prefix DIR] [--out FILE] [MESH...]\` makes the"
  echo "  meshes (\`scripts/fetch-tets.sh\`, Debian's tetgen on closed surfaces of CGAL's demo data),"
  echo "  installs the package into a temporary prefix (or uses an installed one), builds the harness"
  echo "  \`topomesh_bench_vol\` (\`c-tests/diff_volume/\`, \`-O2 -DNDEBUG\`, no \`-march=native\`) and"
  echo "  rewrites this page."
  echo "- CGAL: \`Triangulation_3<Epick, Triangulation_data_structure_3>\` with the plain vertex and"
  echo "  cell bases (plus the no-op setters \`build_triangulation\` calls: the leanest triangulation it"
  echo "  accepts), built by \`CGAL::build_triangulation<Tr, true>\` (CGAL/Mesh_3/tet_soup_to_c3t3.h);"
  echo "  its infinite vertex and cells are left out of every answer. Its build time includes turning"
  echo "  the arrays into its \`Point_3\` vector and positively oriented cells (the conversion time is"
  echo "  given)."
  echo "- topomesh: \`chf_mesh_from_tetrahedra_ex\` with positions (it orients, matches faces, splits"
  echo "  non-manifold vertices, and from level 2 names edges and faces), through the installed"
  echo "  libtopomesh.so, built on one thread (as CGAL's build) and with the default, every thread of"
  echo "  the machine (\`threads\` 0 in \`chf_build_options\`; the memory rows use the default); every"
  echo "  sweep runs on one thread."
  echo "- Each build and sweep runs N times; the tables give the median. Checksums count the"
  echo "  entries a sweep visits (boundary NONE excluded): equal counts mean every library did the"
  echo "  same work. The differential tests (\`c-tests/diff_volume/\`) compare the answers element by"
  echo "  element."
  echo "- The Rust core alone: \`cargo bench --bench chf\` (criterion); it is not recorded here."
  echo
  charts_section
  echo "## Results"
  echo
  echo "Command: \`$cmdline\` ($(date -u +%Y-%m-%d), commit $commit$dirty)."
  echo
  echo "- Machine: $model, $cpus logical CPUs, $mem, $os. Load average (1, 5, 15 min) before the"
  echo "  run: $load_before; after: $load_after."
  echo "- C++: $cxx. CGAL $cgal_v. topomesh: $rustc_v, cargo release profile."
  echo "- $reps repetitions of each build and sweep."
  echo "- Meshes, made with tetgen $tetgen_v:"
  for b in "${bases[@]}"; do
    if [[ -f "$b.tetgen.txt" ]]; then
      echo "  $(basename "$b"): \`tetgen $(sed -n 's/^flags //p' "$b.tetgen.txt") $(sed -n 's/^source //p' "$b.tetgen.txt")\`,"\
           "$(sed -n 's/^seconds //p' "$b.tetgen.txt") s."
    fi
  done
  cat "$work/tables.md" | sed '1d'
  echo
  editing_section
} > "$out.new"
mv "$out.new" "$out"
echo "== wrote $out"
charts
