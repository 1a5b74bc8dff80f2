#!/bin/sh
# Hands every .msh written by pqmesh_write_samples to the real gmsh (headless:
# no DISPLAY, -0 = read the file, write it back, exit) and checks exit status
# 0, no "Error" in gmsh's output, and that pqmesh reads gmsh's re-written
# MSH 4.1 file back with the same vertex/element/boundary counts and markers.
# pqmesh does not read binary .msh, so the rewrite of a binary file (stem
# *_41b) is compared with pqmesh's reading of the ASCII 4.1 file of the same
# mesh (stem without _41b).
# usage: check_gmsh.sh SAMPLES_DIR WRITE_SAMPLES_EXE
# Fails (never skips) when gmsh is missing.
set -u
samples=$1
exe=$2
unset DISPLAY
if ! command -v gmsh >/dev/null 2>&1; then
  echo "FAIL: gmsh not found on PATH (scripts/install-deps.sh installs it)"
  exit 1
fi
gmsh --version 2>&1 | head -n 1
status=0
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for stem in square square_22 square_41b cube cube_22 cube_41b; do
  file=$samples/$stem.msh
  case $stem in square*) dim=2 ;; *) dim=3 ;; esac
  if [ ! -f "$file" ]; then
    echo "FAIL: $file missing"; status=1; continue
  fi
  log=$out/$stem.log
  timeout 120 gmsh "$file" -0 -o "$out/$stem.out.msh" -format msh41 >"$log" 2>&1
  rc=$?
  if [ $rc -ne 0 ] || grep -q "Error" "$log"; then
    echo "FAIL: gmsh on $file (exit $rc):"; cat "$log"; status=1; continue
  fi
  case $stem in *_41b) ascii=$samples/${stem%_41b}.msh ;; *) ascii=$file ;; esac
  ours=$("$exe" --read "$ascii" $dim) || { echo "FAIL: pqmesh cannot read $ascii"; status=1; continue; }
  theirs=$("$exe" --read "$out/$stem.out.msh" $dim) || {
    echo "FAIL: pqmesh cannot read gmsh's rewrite of $file"; cat "$out/$stem.out.msh"; status=1; continue; }
  # gmsh keeps element order within an entity block but may reorder blocks,
  # so markers are compared as sorted lists.
  sorted_ours=$(echo "$ours" | sed -n 2p | tr ' ' '\n' | sort -n | tr '\n' ' ')
  sorted_theirs=$(echo "$theirs" | sed -n 2p | tr ' ' '\n' | sort -n | tr '\n' ' ')
  if [ "$(echo "$ours" | head -n 1)" != "$(echo "$theirs" | head -n 1)" ] || [ "$sorted_ours" != "$sorted_theirs" ]; then
    echo "FAIL: counts/markers differ after gmsh rewrote $file:"
    echo "  pqmesh file: $ours"
    echo "  gmsh file:   $theirs"
    status=1
    continue
  fi
  echo "ok: $file ($(echo "$ours" | head -n 1))"
done
exit $status
