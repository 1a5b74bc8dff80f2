#!/usr/bin/env bash
# Quick start: install what is missing, build, and run the main job on a bundled example.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
# The Python module into the site directory of Debian's /usr/bin/python3
# (/usr/local/lib/python3.11/dist-packages): `import pqmesh` from any directory.
cmake --install "$root/build" --component python
"$root/build/bin/pqmesh" mesh "$root/data/2d/comb.poly" -o "$root/build/comb.vtu"
# The 3D mesher on the L-block (checked before it is written;
# docs/algorithm/mesh3d.md).
"$root/build/bin/pqmesh" mesh "$root/data/3d/l_block.poly" -o "$root/build/l_block.vtu"
# The Python module on the same L-block, given as arrays (examples/python/quickstart.py).
(cd / && /usr/bin/python3 "$root/examples/python/quickstart.py" "$root/build/l_block_python.vtu")
