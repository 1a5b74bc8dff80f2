#!/usr/bin/env bash
# End-to-end tests of `pqmesh mesh` on 3D input: exit codes, no
# output file on failure, the summary lines, deterministic bytes.
# usage: mesh3d_test.sh PQMESH_BINARY DATA_DIR FIXTURE_DIR
pqmesh=$1 data=$2
source "$(dirname "$0")/harness.sh"

# Grid-aligned models mesh completely on the aligned grid.
for m in cube l_block; do
  expect 0 "mesh $m" -- "$pqmesh" mesh "$data/3d/$m.poly" -o "$work/$m.vtu" --aligned-grid --lfs-integral
  [[ -s $work/$m.vtu ]] && ok || fail "mesh $m wrote no file"
  empty "$work/err" "mesh $m: stderr is not a terminal, so no progress and no message"
  for pat in "^input +.*$m.poly \(3D, [0-9]+ vertices" "^alpha +alpha = 90 deg" \
             "^mesh +[0-9]+ tetrahedra, [0-9]+ vertices, [0-9]+ boundary triangles" \
             "^quality +max aspect ratio [0-9.]+ \(tetrahedron [0-9]+; measured bound C / alpha = [0-9.e+]+, C = 5500\), dihedral min [0-9.]+ deg, max [0-9.]+ deg" \
             "^size +I3 = integral of 1/lfs\^3 over P = [0-9.e+]+ .*tetrahedra / I3 = [0-9.e+]+" \
             "^grid +aligned" "^leaves +[0-9]+: outside [0-9]+, empty [0-9]+, vertex [0-9]+, edge [0-9]+, facet [0-9]+" \
             "^boxes +[0-9]+ empty" "^time \(s\) +octree [0-9.]+, classify [0-9.]+, tetrahedra [0-9.]+, boundary [0-9.]+" \
             "^check +valid: [0-9]+ tetrahedra" "^output +.*$m.vtu \(vtu\)"; do
    contains "$work/out" "$pat" "mesh $m summary"
  done
  # The file reads back and passes the checker on its own.
  expect 0 "check the $m mesh" -- "$pqmesh" check "$work/$m.vtu" --domain "$data/3d/$m.poly"
done

# Every 3D format; twice each: byte-identical files (deterministic).
for ext in vtu msh mesh node; do
  for run in a b; do
    expect 0 "mesh cube .$ext ($run)" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/$run.$ext" --aligned-grid --quiet
    empty "$work/out" "--quiet prints nothing (.$ext)"
  done
  if cmp -s "$work/a.$ext" "$work/b.$ext"; then ok; else fail "mesh .$ext output is not deterministic"; fi
done
expect 0 "mesh cube --format msh22" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/f.out" --format msh22 --aligned-grid --quiet
[[ -s $work/f.out ]] && ok || fail "--format msh22 wrote no file"

# The summary's I3 estimate (--lfs-integral; cmd_mesh3.cpp, kLfsRefine3 = 1/2)
# on the unit cube, against the library's fine quadrature: refine 1/8 gives
# 4.616 and 1/4 gives 4.562 (docs/MEASUREMENTS.md "The size estimate's
# quadrature"; 1/8 is within 0.4% of the brute-force midpoint reference 4.634
# of tests/unit/lfs3d/lfs3d_integral_test.cpp). The quadrature converges from
# below about like refine^2 (the errors at 1/4, 1/8, 1/16 shrink by 4x and
# more), so with I(r) = I - C r^2 the deficit of refine 1/2 against 1/8 is
# (1/4 - 1/64) / (1/16 - 1/64) = 5 times the 1/4 -> 1/8 step: the tolerance,
# 5 x 0.054 = 0.27 (5.8%). A coarser refine leaves it (refine 1: 21 steps by
# the same rule, 3.955 in the table).
expect 0 "mesh cube --lfs-integral" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/lfs.vtu" --lfs-integral
i3=$(sed -nE 's/^size +I3 = integral of 1\/lfs\^3 over P = ([0-9.e+]+) .*/\1/p' "$work/out")
if awk -v x="$i3" -v fine=4.616 -v quarter=4.562 \
     'BEGIN { tol = 5 * (fine - quarter); exit !(x != "" && x >= fine - tol && x <= fine + tol) }'; then ok
else fail "cube I3 '$i3' not within 5 x (4.616 - 4.562) of 4.616"; fi

# Sizing: --max-size and a 3D size field refine the mesh.
expect 0 "mesh cube --max-size" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/ms.vtu" --aligned-grid --max-size 0.125
contains "$work/out" "^sizing +max size 0.125" "sizing line"
contains "$work/out" "^check +valid" "--max-size mesh is valid"
coarse=$(grep -E '^mesh ' <("$pqmesh" mesh "$data/3d/cube.poly" -o "$work/c.vtu" --aligned-grid) | awk '{print $2}')
fine=$(grep -E '^mesh ' "$work/out" | awk '{print $2}')
if [[ -n $coarse && -n $fine && $fine -gt $coarse ]]; then ok; else fail "--max-size 0.125 gives $fine tetrahedra, no more than $coarse"; fi
printf '# x y z size\n0.5 0.5 0.5 0.02\n' > "$work/field.txt"
expect 0 "mesh cube --size-field" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/sf.vtu" --aligned-grid --size-field "$work/field.txt"
contains "$work/out" "^sizing +size field .*field.txt \(1 point\)" "size field line"
printf '0.5 0.5 0.02\n' > "$work/field2d.txt"
expect 2 "mesh cube with a 2D size field" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/never_sf.vtu" --aligned-grid --size-field "$work/field2d.txt"
contains "$work/err" "field2d.txt" "size field error names the file"
absent "$work/never_sf.vtu" "no output after a bad size field"

# On the aligned grid only empty and facet boxes are meshed: exit 2, the
# leaf and its kind named, nothing written.
expect 2 "mesh schoenhardt (vertex boxes on the aligned grid)" -- "$pqmesh" mesh "$data/3d/schoenhardt.poly" -o "$work/never_s.vtu" --aligned-grid
contains "$work/err" "leaf [0-9]+ .*kind [a-z-]+, not supported by the 3D mesher" "unsupported leaf message"
absent "$work/never_s.vtu" "no output for an unsupported leaf"

# The default (generic grid): a valid mesh, or a refusal that writes nothing.
expect 0 "mesh cube (generic grid)" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/gen.vtu"
contains "$work/out" "^grid +generic, planes shifted by" "generic grid line"
contains "$work/out" "^check +valid" "generic grid mesh is valid"

# Coplanar facets (docs/algorithm/input.md "Merging coplanar facets"): cube.obj
# has a vertex in the middle of a straight edge (two facets share two collinear
# edges).
expect 0 "mesh cube.obj" -- "$pqmesh" mesh "$data/3d/cube.obj" -o "$work/obj.vtu" --quiet
expect 0 "check the cube.obj mesh" -- "$pqmesh" check "$work/obj.vtu" --domain "$data/3d/cube.obj"
# The unit cube with its bottom given as two triangles: same marker -> merged
# into one facet and meshed; different markers -> two facets and a flat edge
# between them, meshed, with both markers on the bottom's boundary triangles.
split_bottom() {  # $1 = marker of the second bottom triangle
  printf '8 3 0 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n'
  printf '7 1\n1 0 1\n3 1 3 2\n1 0 %s\n3 1 4 3\n' "$1"
  printf '1 0 2\n4 5 6 7 8\n1 0 3\n4 1 2 6 5\n1 0 4\n4 2 3 7 6\n1 0 5\n4 3 4 8 7\n1 0 6\n4 4 1 5 8\n0\n0\n'
}
split_bottom 1 > "$work/split_same.poly"
expect 0 "mesh a cube with a split bottom, one marker" -- "$pqmesh" mesh "$work/split_same.poly" -o "$work/split_same.vtu"
contains "$work/out" "^check +valid" "merged split bottom is valid"
split_bottom 7 > "$work/split_diff.poly"
expect 0 "mesh a cube with a split bottom, two markers" -- "$pqmesh" mesh "$work/split_diff.poly" -o "$work/split_diff.mesh"
contains "$work/out" "^check +valid" "split bottom with two markers is valid"
expect 0 "check the split-bottom mesh" -- "$pqmesh" check "$work/split_diff.mesh" --domain "$work/split_diff.poly"
# Medit triangles are "a b c marker": markers 1 and 7 both on z = 0.
awk '/^Triangles/{t=1; getline; next} /^[A-Z]/{t=0} t && NF==4 {print $4}' "$work/split_diff.mesh" | sort -u | tr '\n' ' ' >"$work/markers"
contains "$work/markers" "^1 2 3 4 5 6 7 $" "every facet marker on the boundary, 1 and 7 on the split bottom"

# Bad input and bad command lines.
expect 2 "mesh a bad 3D domain" -- "$pqmesh" mesh "$data/bad/open_boundary.poly" -o "$work/never_bad.vtu"
contains "$work/err" "error \[open-boundary\]" "bad 3D domain error kind"
absent "$work/never_bad.vtu" "no output for a bad domain"
expect 64 "3D mesh without -o" -- "$pqmesh" mesh "$data/3d/cube.poly"
expect 64 "3D mesh as svg" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/never.svg"
expect 64 "3D mesh --format svg" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/never.vtu" --format svg
expect 64 "3D mesh --refine-angle" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/never.vtu" --refine-angle 20
expect 64 "3D mesh --protect-edges" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/never.vtu" --protect-edges
expect 64 "3D mesh --max-size 0" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/never.vtu" --max-size 0
expect 2 "3D mesh to an unknown extension" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/never.xyz"
expect 64 "2D mesh --aligned-grid" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/never2d.vtu" --aligned-grid
absent "$work/never.vtu" "no output after a refused command line"

# --min-dihedral: the improve line names the target and the counted boundary
# flips; the mesh is checked; out-of-range values are refused with nothing written.
# Without it the target is 20 degrees, none with --max-size; 0 turns it off.
expect 0 "mesh l_block default target" -- "$pqmesh" mesh "$data/3d/l_block.poly" -o "$work/md.vtu"
contains "$work/out" "^improve .*min dihedral 20 deg" "default target in the improve line"
expect 0 "mesh l_block --min-dihedral 0" -- "$pqmesh" mesh "$data/3d/l_block.poly" -o "$work/md.vtu" --min-dihedral 0
contains "$work/out" "^improve .*\(target aspect 8\), " "no target with --min-dihedral 0"
expect 0 "mesh l_block --max-size" -- "$pqmesh" mesh "$data/3d/l_block.poly" -o "$work/md.vtu" --max-size 0.5
contains "$work/out" "^improve .*\(target aspect 8\), " "no default target with --max-size"
expect 0 "mesh l_block --min-dihedral 20" -- "$pqmesh" mesh "$data/3d/l_block.poly" -o "$work/md.vtu" --min-dihedral 20
contains "$work/out" "^improve .*min dihedral 20 deg.*flips \([0-9]+ on the boundary\)" "--min-dihedral in the improve line"
expect 0 "check --min-dihedral mesh" -- "$pqmesh" check "$work/md.vtu" --domain "$data/3d/l_block.poly"
for bad in -1 70.6 x; do
  expect 64 "--min-dihedral $bad refused" -- "$pqmesh" mesh "$data/3d/l_block.poly" -o "$work/md_bad.vtu" --min-dihedral "$bad"
  absent "$work/md_bad.vtu" "--min-dihedral $bad writes nothing"
done

# pqmesh octree --generic-grid: the grid line.
expect 0 "octree --generic-grid" -- "$pqmesh" octree "$data/3d/cube.poly" -o "$work/oct.vtu" --generic-grid
contains "$work/out" "^grid +generic, planes shifted by" "octree --generic-grid line"
expect 0 "octree aligned" -- "$pqmesh" octree "$data/3d/cube.poly" -o "$work/oct2.vtu"
contains "$work/out" "^grid +aligned" "octree grid line"

finish mesh3d_test
