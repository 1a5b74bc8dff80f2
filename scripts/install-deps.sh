#!/usr/bin/env bash
# Installs the Debian 12 packages pqmesh needs to build and test, skipping
# those already present. Run as root (or with sudo available).
#   --bench   also the peers the benchmarks compare against (tetgen, CGAL, and
#             Triangle when the machine's apt sources have Debian's non-free
#             section, where triangle-bin lives; without it the benchmark prints
#             "missing" for Triangle), and the real CAD and scanned surfaces of
#             bench/real_parts.sh (libcgal-demo: CGAL's example OFF files;
#             occt-misc: Open CASCADE's sample STL files), optional as well
set -euo pipefail

# The library, its tests and the file-format clients (meshio, gmsh, VTK below).
packages=(g++ cmake make libgtest-dev libgmock-dev libgmp-dev python3 python3-numpy python3-meshio gmsh zlib1g-dev liblz4-dev liblzma-dev)
# The Python module (python/) and its tests.
packages+=(pybind11-dev python3-dev python3-pytest python3-vtk9)
optional=()
if [[ "${1:-}" == "--bench" ]]; then
  packages+=(tetgen libcgal-dev time)
  optional+=(triangle-bin libcgal-demo occt-misc)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo_cmd=()
[[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
if ((${#missing[@]} == 0)); then
  echo "install-deps: all packages present"
else
  echo "install-deps: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

for p in "${optional[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" && continue
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "$p" ||
    echo "install-deps: optional package $p is not available from this machine's apt sources (skipped)"
done
