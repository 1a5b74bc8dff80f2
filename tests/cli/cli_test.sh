#!/usr/bin/env bash
# End-to-end tests of the pqmesh command line: exit codes, messages naming ids
# and lines, help for every subcommand, and no partial output on failure.
# usage: cli_test.sh PQMESH_BINARY DATA_DIR FIXTURE_DIR
set -u
pqmesh=$1 data=$2 fixtures=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

ok() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect CODE DESCRIPTION -- COMMAND...: runs COMMAND, checks the exit code,
# leaves stdout in $work/out and stderr in $work/err.
expect() {
  local want=$1 what=$2
  shift 3
  "$@" > "$work/out" 2> "$work/err"
  local got=$?
  if [[ $got -eq $want ]]; then ok; else fail "$what: exit $got, expected $want; stderr: $(head -c 400 "$work/err")"; fi
}
contains() {  # contains FILE PATTERN DESCRIPTION
  if grep -qE -- "$2" "$1"; then ok; else fail "$3: '$2' not in $(head -c 400 "$1")"; fi
}

# Help for the tool and every subcommand.
expect 0 "top-level help" -- "$pqmesh" --help
for c in info check quality convert; do
  expect 0 "$c --help" -- "$pqmesh" "$c" --help
  contains "$work/out" "usage: pqmesh $c" "$c --help text"
done
expect 64 "unknown command" -- "$pqmesh" frobnicate
expect 64 "unknown option" -- "$pqmesh" info --frobnicate "$data/3d/cube.poly"

# info on every good domain of the corpus: valid, and alpha is printed.
for f in "$data"/3d/* "$data"/2d/*; do
  expect 0 "info $(basename "$f")" -- "$pqmesh" info "$f"
  contains "$work/out" "^alpha +alpha = [0-9.]+ deg" "alpha line for $(basename "$f")"
done
expect 0 "info cube" -- "$pqmesh" info "$data/3d/cube.poly"
contains "$work/out" "alpha = 90 deg" "cube alpha is 90 degrees"
contains "$work/out" "^volume +1$" "cube volume is 1"
expect 0 "info cube with cavity" -- "$pqmesh" info "$data/3d/cube_cavity.poly"
contains "$work/out" "1 cavities" "cube_cavity has one floater"

# Bad input: exit 2, a message naming the error kind (ids and lines are
# checked by test_regression against data/bad/MANIFEST.tsv).
while IFS=$'\t' read -r file code line ids; do
  [[ $file == file ]] && continue
  expect 2 "info $file" -- "$pqmesh" info "$data/$file"
  contains "$work/err" "error \[$code\]" "error kind for $file"
  [[ $line != 0 ]] && contains "$work/err" ":$line: " "line number for $file"
done < "$data/bad/MANIFEST.tsv"

# check: a valid mesh passes, broken ones fail with the kind named.
expect 0 "check Kuhn cube" -- "$pqmesh" check "$fixtures/cube_kuhn.mesh" --domain "$data/3d/cube.poly"
contains "$work/out" "^valid" "check report says valid"
expect 1 "check flipped tet" -- "$pqmesh" check "$fixtures/cube_flipped.mesh" --domain "$data/3d/cube.poly"
contains "$work/out" "orientation" "flipped tet reported as orientation"
expect 1 "check mesh with a hole" -- "$pqmesh" check "$fixtures/cube_missing.mesh" --domain "$data/3d/cube.poly"
contains "$work/out" "boundary-face|volume" "missing tet reported"
expect 0 "check 2D square" -- "$pqmesh" check "$fixtures/square_two.mesh" --domain "$data/2d/square.poly"
expect 1 "2D mesh against the L domain" -- "$pqmesh" check "$fixtures/square_two.mesh" --domain "$data/2d/l_shape.poly"
expect 64 "check without --domain" -- "$pqmesh" check "$fixtures/cube_kuhn.mesh"
expect 2 "check with a bad domain" -- "$pqmesh" check "$fixtures/cube_kuhn.mesh" --domain "$data/bad/open_boundary.poly"

# quality: the report and an SVG histogram.
expect 0 "quality Kuhn cube" -- "$pqmesh" quality "$fixtures/cube_kuhn.mesh" --svg "$work/hist.svg"
contains "$work/out" "aspect" "quality report mentions aspect ratio"
contains "$work/hist.svg" "<svg" "histogram is an SVG"
expect 1 "quality of a mesh with a flipped tet" -- "$pqmesh" quality "$fixtures/cube_flipped.mesh"

# convert: every output format, re-read by check; byte-identical reruns.
for ext in vtu msh mesh node; do
  expect 0 "convert to .$ext" -- "$pqmesh" convert "$fixtures/cube_kuhn.mesh" "$work/cube.$ext"
  expect 0 "check converted .$ext" -- "$pqmesh" check "$work/cube.$ext" --domain "$data/3d/cube.poly"
done
expect 0 "convert to msh 2.2" -- "$pqmesh" convert "$fixtures/cube_kuhn.mesh" "$work/cube22.msh" --msh22
expect 0 "check converted msh 2.2" -- "$pqmesh" check "$work/cube22.msh" --domain "$data/3d/cube.poly"
expect 0 "convert again" -- "$pqmesh" convert "$fixtures/cube_kuhn.mesh" "$work/again.vtu"
if cmp -s "$work/cube.vtu" "$work/again.vtu"; then ok; else fail "convert output is not deterministic"; fi
expect 0 "convert 2D to svg" -- "$pqmesh" convert "$fixtures/square_two.mesh" "$work/square.svg"
contains "$work/square.svg" "<svg" "2D picture is an SVG"

# A failed run leaves no output file.
expect 2 "convert a missing file" -- "$pqmesh" convert "$work/nope.mesh" "$work/never.vtu"
if [[ ! -e $work/never.vtu ]]; then ok; else fail "failed convert left an output file"; fi
expect 2 "convert to an unknown extension" -- "$pqmesh" convert "$fixtures/cube_kuhn.mesh" "$work/never.xyz"
if [[ -z $(ls "$work" | grep -E '^never') ]]; then ok; else fail "failed convert left a file: $(ls "$work")"; fi

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
