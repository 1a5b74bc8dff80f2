#!/usr/bin/env bash
# Configures and builds pqmesh into build/ (or $PQMESH_BUILD_DIR). Extra
# arguments go to cmake's configure step, e.g. -DPQMESH_SANITIZE=ON.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PQMESH_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=${PQMESH_BUILD_TYPE:-Release} "$@" > /dev/null
cmake --build "$build" -j "$(nproc)"
