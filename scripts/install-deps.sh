#!/usr/bin/env bash
# Installs the Debian 12 packages pqmesh needs to build and test, skipping
# those already present. Run as root (or with sudo available).
#   --bench   also the peers the benchmarks compare against (tetgen, triangle, CGAL)
set -euo pipefail

packages=(g++ cmake make libgtest-dev libgmock-dev libgmp-dev python3 python3-numpy python3-meshio gmsh)
if [[ "${1:-}" == "--bench" ]]; then
  packages+=(tetgen triangle-bin libcgal-dev time)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all packages present"
  exit 0
fi

sudo_cmd=()
[[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
echo "install-deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
