#!/usr/bin/env bash
# Builds pqmesh (warnings are errors) and runs the whole test suite.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PQMESH_BUILD_DIR:-$root/build}
PQMESH_BUILD_DIR=$build bash "$root/scripts/build.sh" -DPQMESH_WERROR=ON "$@"
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure --timeout 600
