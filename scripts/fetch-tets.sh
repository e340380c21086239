#!/usr/bin/env bash
# Makes the tetrahedral meshes of the CHF differential tests and the volume benchmark with
# Debian's tetgen, from closed real surfaces of the mesh cache, into
# ${TOPOMESH_MESH_DIR:-$HOME/.cache/topomesh/meshes}/tets/<name>.node and <name>.ele
# (tetgen's format, numbered from 0). Idempotent: a mesh already there is not remade.
#
#   scripts/fetch-tets.sh [--no-large] [--list]
#
#   --no-large  skip the ~1.1M-tetrahedra benchmark mesh (the tests do not need it)
#   --list      print name, source, tetgen flags and purpose, and exit
#
# The surfaces come from scripts/fetch-meshes.sh (called when one is missing); without that
# script, the few needed OFF files are taken directly from Debian's libcgal-demo package the
# same way. Each mesh gets <name>.tetgen.txt: flags, seconds, vertices and tetrahedra.
# Each mesh's tetgen time is recorded in its <name>.tetgen.txt (BENCHMARKS-volumes.md
# prints it).
set -euo pipefail

DIR="${TOPOMESH_MESH_DIR:-$HOME/.cache/topomesh/meshes}"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# name  source-surface  tetgen-flags  purpose  (-p: keep the surface, -q: quality, -a: max
# volume, -z: number from 0, -Q: quiet). The large one is for the benchmark only.
MESHES="
double-torus-2k  double-torus-example  -pqzQ       test:genus-2
blobby-12k       blobby                -pq10zQ     test+bench:10k
knot1-16k        knot1                 -pzQ        test:genus-1
armadillo-101k   armadillo             -pzQ        test+bench:100k
bunny00-1m       bunny00               -pqzQa8e-7  bench:1M
"

LARGE=1
for a in "$@"; do
  case "$a" in
    --no-large) LARGE=0 ;;
    --list) echo "$MESHES" | sed '/^$/d'; exit 0 ;;
    -h|--help) sed -n 2,16p "$0"; exit 0 ;;
    *) echo "fetch-tets.sh: unknown argument $a" >&2; exit 2 ;;
  esac
done
command -v tetgen >/dev/null || { echo "fetch-tets.sh: tetgen is not installed (apt-get install tetgen)" >&2; exit 1; }

selected=()
while read -r name src flags purpose; do
  [[ -z "$name" ]] && continue
  [[ $LARGE == 0 && "$purpose" == bench:* ]] && continue
  selected+=("$name $src $flags")
done <<<"$MESHES"

# The surfaces.
need_src=()
for line in "${selected[@]}"; do
  read -r name src flags <<<"$line"
  [[ -s "$DIR/tets/$name.ele" && -s "$DIR/tets/$name.node" ]] && continue
  [[ -s "$DIR/$src.off" ]] || need_src+=("$src")
done
if ((${#need_src[@]})); then
  if [[ -x "$HERE/fetch-meshes.sh" ]]; then
    "$HERE/fetch-meshes.sh"
  fi
  still=()
  for s in "${need_src[@]}"; do [[ -s "$DIR/$s.off" ]] || still+=("$s"); done
  if ((${#still[@]})); then
    echo "fetch-tets: taking ${still[*]} from Debian's libcgal-demo into $DIR"
    mkdir -p "$DIR"
    work="$(mktemp -d)"
    trap 'rm -rf "$work"' EXIT
    if ! (cd "$work" && apt-get download libcgal-demo >/dev/null 2>&1); then
      apt-get update -qq >/dev/null 2>&1 || true
      (cd "$work" && apt-get download libcgal-demo >/dev/null)
    fi
    dpkg -x "$work"/libcgal-demo_*.deb "$work/x"
    members=()
    for s in "${still[@]}"; do members+=("data/meshes/$s.off"); done
    tar -xzf "$work/x/usr/share/doc/libcgal-dev/data.tar.gz" -C "$work" "${members[@]}"
    for s in "${still[@]}"; do mv "$work/data/meshes/$s.off" "$DIR/$s.off"; done
    rm -rf "$work"; trap - EXIT
  fi
fi

# The tetrahedral meshes.
mkdir -p "$DIR/tets"
for line in "${selected[@]}"; do
  read -r name src flags <<<"$line"
  out="$DIR/tets/$name"
  [[ -s "$out.ele" && -s "$out.node" ]] && continue
  work="$(mktemp -d "$DIR/tets/.work.XXXXXX")"
  cp "$DIR/$src.off" "$work/$name.off"
  echo "fetch-tets: tetgen $flags $src.off -> tets/$name (bunny00-1m: under a minute)"
  t0=$(date +%s.%N)
  (cd "$work" && tetgen "$flags" "$name.off" >/dev/null) || {
    echo "fetch-tets: tetgen failed on $src.off" >&2; rm -rf "$work"; exit 1; }
  t1=$(date +%s.%N)
  read -r nv _ < "$work/$name.1.node"
  read -r nt _ < "$work/$name.1.ele"
  mv "$work/$name.1.node" "$out.node"
  mv "$work/$name.1.ele" "$out.ele"
  printf 'source %s.off\nflags %s\nseconds %.1f\nvertices %s\ntetrahedra %s\n' \
    "$src" "$flags" "$(awk -v a="$t0" -v b="$t1" 'BEGIN{print b-a}')" "$nv" "$nt" > "$out.tetgen.txt"
  rm -rf "$work"
  echo "fetch-tets: tets/$name: $nv vertices, $nt tetrahedra, $(sed -n 's/seconds //p' "$out.tetgen.txt") s"
done
echo "fetch-tets: $DIR/tets ready"
