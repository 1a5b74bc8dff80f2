#!/usr/bin/env bash
# Configures and builds pqmesh (library, CLI, tests) into build/ (or
# $PQMESH_BUILD_DIR), warnings as errors. The quick start and the test command
# both call this with the same flags, so the test command finds everything
# built and only runs the tests. Extra arguments go to cmake's configure step,
# e.g. -DPQMESH_SANITIZE=ON.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PQMESH_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=${PQMESH_BUILD_TYPE:-Release} -DPQMESH_WERROR=ON "$@" > /dev/null
cmake --build "$build" -j "$(nproc)"
