#!/usr/bin/env bash
# Builds pqmesh (warnings are errors; nothing to rebuild after the quick start)
# and runs the whole test suite. Extra arguments go to cmake's configure step.
# PQMESH_CTEST_ARGS adds ctest arguments, e.g. "-LE slow" to leave out the
# tests labelled slow (tests/slow_tests.cmake).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PQMESH_BUILD_DIR:-$root/build}
PQMESH_BUILD_DIR=$build bash "$root/scripts/build.sh" "$@"
# shellcheck disable=SC2086  # PQMESH_CTEST_ARGS is a list of words
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure --timeout 600 ${PQMESH_CTEST_ARGS:-}
