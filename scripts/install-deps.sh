#!/usr/bin/env bash
# Installs the Debian packages the tests need (as root, or through sudo), only when missing.
set -euo pipefail
packages=(cmake g++ make pkg-config valgrind libopenmesh-dev libcgal-dev libgmp-dev libmpfr-dev
  libboost-dev tetgen libeigen3-dev libmeshoptimizer-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
