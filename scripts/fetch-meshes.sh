#!/usr/bin/env bash
# Fetches the real meshes used by the differential tests and the benchmark into a cache
# outside the repository, and generates the large benchmark meshes.
#
#   scripts/fetch-meshes.sh [--list]
#
# Cache: ${TOPOMESH_MESH_DIR:-$HOME/.cache/topomesh/meshes}. Idempotent: does nothing when
# every file is present. Sources: Debian's libcgal-demo package (apt-get download, no
# install); its data.tar.gz holds data/meshes/*.off. Files without a notice there are CC0;
# bunny, armadillo and dragon come from the Stanford repository: never commit them.
#
# Generated: bunny00-sub2.off (1,206,528 triangles) and bunny00-sub3.off (4,826,112), by
# 1-to-4 midpoint subdivision of bunny00 (c-tests/diff_surface/subdivide.cpp, built with g++).
# Tetrahedral meshes are made from these surfaces by scripts/fetch-tets.sh.
# --list: print the selected meshes and exit.
set -euo pipefail

DIR="${TOPOMESH_MESH_DIR:-$HOME/.cache/topomesh/meshes}"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
SUBDIVIDE_SRC="$HERE/../c-tests/diff_surface/subdivide.cpp"

# The selection: c-tests/diff_surface/meshes.txt (one name a line, with what each one is for).
LIST="$HERE/../c-tests/diff_surface/meshes.txt"
mapfile -t MESHES < <(sed 's/#.*//; s/[[:space:]]//g; /^$/d' "$LIST")
GENERATED=(bunny00-sub2 bunny00-sub3)
for a in "$@"; do
  case "$a" in
    --list) printf '%s\n' "${MESHES[@]}"; exit 0 ;;
    -h|--help) sed -n 2,14p "$0"; exit 0 ;;
    *) echo "fetch-meshes.sh: unknown argument $a" >&2; exit 2 ;;
  esac
done

missing=()
for m in "${MESHES[@]}"; do [[ -s "$DIR/$m.off" ]] || missing+=("$m"); done

if ((${#missing[@]})); then
  mkdir -p "$DIR"
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
  echo "fetch-meshes: downloading libcgal-demo for ${#missing[@]} meshes into $DIR"
  if ! (cd "$work" && apt-get download libcgal-demo >/dev/null 2>&1); then
    apt-get update -qq >/dev/null 2>&1 || true
    (cd "$work" && apt-get download libcgal-demo >/dev/null)
  fi
  dpkg -x "$work"/libcgal-demo_*.deb "$work/x"
  data="$work/x/usr/share/doc/libcgal-dev/data.tar.gz"
  [[ -f "$data" ]] || { echo "fetch-meshes: $data not in the package" >&2; exit 1; }
  members=()
  for m in "${missing[@]}"; do members+=("data/meshes/$m.off"); done
  tar -xzf "$data" -C "$work" "${members[@]}"
  for m in "${missing[@]}"; do
    mv "$work/data/meshes/$m.off" "$DIR/$m.off.part" && mv "$DIR/$m.off.part" "$DIR/$m.off"
  done
  rm -rf "$work"; trap - EXIT
fi

need_gen=0
for g in "${GENERATED[@]}"; do [[ -s "$DIR/$g.off" ]] || need_gen=1; done
if ((need_gen)); then
  tool="$DIR/.subdivide"
  if [[ ! -x "$tool" || "$SUBDIVIDE_SRC" -nt "$tool" ]]; then
    "${CXX:-g++}" -std=c++17 -O2 -o "$tool" "$SUBDIVIDE_SRC"
  fi
  echo "fetch-meshes: generating bunny00-sub2 and bunny00-sub3 (1-to-4 subdivision)"
  "$tool" "$DIR/bunny00.off" "$DIR/bunny00-sub2.off.part" 2
  mv "$DIR/bunny00-sub2.off.part" "$DIR/bunny00-sub2.off"
  "$tool" "$DIR/bunny00-sub2.off" "$DIR/bunny00-sub3.off.part" 1
  mv "$DIR/bunny00-sub3.off.part" "$DIR/bunny00-sub3.off"
fi

echo "fetch-meshes: $DIR ready"
