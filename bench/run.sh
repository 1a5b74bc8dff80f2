#!/usr/bin/env bash
# Builds and runs the benchmarks (Release, one thread). Not part of the tests.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
PQMESH_BUILD_DIR=$root/build-bench bash "$root/scripts/build.sh" -DPQMESH_BENCH=ON -DPQMESH_TESTS=OFF
"$root/build-bench/bench/pqmesh_bench_foundation" "$@"
