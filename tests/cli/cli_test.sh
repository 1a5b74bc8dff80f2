#!/usr/bin/env bash
# End-to-end tests of the pqmesh command line: exit codes, messages naming ids
# and lines, help for every subcommand, and no partial output on failure.
# usage: cli_test.sh PQMESH_BINARY DATA_DIR FIXTURE_DIR
pqmesh=$1 data=$2 fixtures=$3
source "$(dirname "$0")/harness.sh"

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
  # Domains go through `info`, meshes (.vtu) through `quality`, which reads a mesh.
  reader=info
  [[ $file == *.vtu ]] && reader=quality
  expect 2 "$reader $file" -- "$pqmesh" "$reader" "$data/$file"
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

# An output that cannot be written (no such directory, a read-only one) exits
# 73 with "cannot write PATH", before any meshing for the meshing commands.
missing_dir=$work/no_such_dir
for job in "mesh $data/2d/square.poly" "mesh $data/3d/cube.poly" "mesh --no-boundary-steiner $data/2d/square.poly" \
  "octree $data/3d/cube.poly"; do
  read -r -a job_args <<< "$job"
  expect 73 "${job_args[0]} into a missing directory" -- "$pqmesh" "${job_args[@]}" -o "$missing_dir/m.vtu"
  contains "$work/err" "cannot write $missing_dir/m.vtu: no directory $missing_dir" "${job}: the error names the output path"
done
expect 73 "convert into a missing directory" -- "$pqmesh" convert "$fixtures/cube_kuhn.mesh" "$missing_dir/c.vtu"
contains "$work/err" "cannot write $missing_dir/c.vtu" "convert: the error names the output path"
if [[ ! -e $missing_dir ]]; then ok; else fail "a refused write created $missing_dir"; fi

# mesh: the 2D quadtree mesher end to end. Every written mesh passes
# 'pqmesh check'; a refused run (3D input, bad options, bad size field)
# exits with its code and leaves no output file.
expect 0 "mesh --help" -- "$pqmesh" mesh --help
contains "$work/out" "usage: pqmesh mesh" "mesh --help text"
for f in square comb; do
  for ext in vtu msh node; do
    expect 0 "mesh $f to .$ext" -- "$pqmesh" mesh "$data/2d/$f.poly" -o "$work/m_$f.$ext"
    contains "$work/out" "^check +valid" "mesh $f summary reports a valid check"
    expect 0 "check mesh of $f (.$ext)" -- "$pqmesh" check "$work/m_$f.$ext" --domain "$data/2d/$f.poly"
    contains "$work/out" "^valid" "check of the $f mesh (.$ext) says valid"
  done
done
# The summary's counts are those 'pqmesh check' finds in the written file.
expect 0 "mesh square summary" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/sq.vtu"
cp "$work/out" "$work/summary"
contains "$work/summary" "^alpha +alpha = 90 deg" "square alpha in the mesh summary"
contains "$work/summary" "^bound +min angle >= min\(" "bound line in the mesh summary"
contains "$work/summary" "^angles +min [0-9.e+-]+ deg .*bound holds" "square mesh meets the bound"
lacks "$work/summary" "^size " "no size estimate without --lfs-integral"
expect 0 "mesh square --lfs-integral" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/sq_lfs.vtu" --lfs-integral
contains "$work/out" "^size +I = integral of 1/lfs\^2 over P = [0-9.e+]+ .*triangles / I = [0-9.e+]+" "size estimate on request"
contains "$work/out" "^time \(s\) .*, lfs [0-9.]+" "lfs time on request"
expect 0 "check square mesh" -- "$pqmesh" check "$work/sq.vtu" --domain "$data/2d/square.poly"
summary_counts=$(sed -nE 's/^mesh +([0-9]+) triangles, ([0-9]+) vertices.*/\1 \2/p' "$work/summary")
check_counts=$(sed -nE 's/^valid: ([0-9]+) triangles, ([0-9]+) vertices.*/\1 \2/p' "$work/out")
if [[ -n $summary_counts && $summary_counts == "$check_counts" ]]; then ok; else
  fail "mesh summary counts '$summary_counts' differ from check's '$check_counts'"; fi
# Every other 2D input of the corpus meshes to a valid mesh.
for f in "$data"/2d/*.poly; do
  b=$(basename "$f" .poly)
  [[ $b == square || $b == comb ]] && continue
  expect 0 "mesh $b" -- "$pqmesh" mesh "$f" -o "$work/c_$b.vtu" --quiet
  expect 0 "check mesh of $b" -- "$pqmesh" check "$work/c_$b.vtu" --domain "$f"
done
# The improvement stage: its summary lines, --no-improve, and --min-angle
# (the comb's construction meets 30 degrees, so its improved mesh does too;
# out-of-range values and --min-angle with --refine-angle are refused).
expect 0 "mesh comb improved" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/imp.vtu"
contains "$work/out" "^improve +target 20 deg: [0-9]+ -> [0-9]+ triangles" "improve line in the summary"
contains "$work/out" "^  built +[0-9 ]+$" "histogram of the construction"
contains "$work/out" "^  output +[0-9 ]+$" "histogram of the output"
expect 0 "mesh comb --no-improve" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/noimp.vtu" --no-improve
contains "$work/out" "^improve +off" "--no-improve in the summary"
expect 0 "mesh comb --min-angle 30" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/a30.vtu" --min-angle 30
contains "$work/out" "^angles +min (3[0-9]|[4-9][0-9])(\\.[0-9]+)? deg" "--min-angle 30 reaches 30 degrees on the comb"
expect 0 "check --min-angle 30 mesh" -- "$pqmesh" check "$work/a30.vtu" --domain "$data/2d/comb.poly"
for bad in 0 34 x; do
  expect 64 "--min-angle $bad refused" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/bad_angle.vtu" --min-angle "$bad"
  absent "$work/bad_angle.vtu" "--min-angle $bad writes nothing"
done
expect 64 "--min-angle with --refine-angle refused" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/bad_angle.vtu" \
  --min-angle 25 --refine-angle 25
# --quiet prints nothing on stdout, and still writes the mesh.
expect 0 "mesh --quiet" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/quiet.msh" --quiet
if [[ ! -s $work/out ]]; then ok; else fail "mesh --quiet printed: $(head -c 200 "$work/out")"; fi
if [[ -s $work/quiet.msh ]]; then ok; else fail "mesh --quiet wrote no mesh"; fi
# --format overrides the extension; sizing options give a valid (finer) mesh.
expect 0 "mesh --format msh" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/fmt.out" --format msh
[[ -e $work/fmt.out ]] && contains "$work/fmt.out" "^\\\$MeshFormat" "--format msh writes Gmsh"
printf '# refine near the origin\n0 0 0.01\n\n1 1 0.25 # coarse corner\n' > "$work/field.txt"
expect 0 "mesh with --max-size and --size-field" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/sized.vtu" \
  --max-size 0.1 --size-field "$work/field.txt"
expect 0 "check sized mesh" -- "$pqmesh" check "$work/sized.vtu" --domain "$data/2d/square.poly"
# Deterministic: two runs give byte-identical files.
for ext in vtu msh node; do
  expect 0 "mesh comb again (.$ext)" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/again_comb.$ext" --quiet
done
for ext in vtu msh node ele poly; do
  if [[ ! -e $work/m_comb.$ext || ! -e $work/again_comb.$ext ]]; then fail "no comb .$ext meshes to compare"
  elif cmp -s "$work/m_comb.$ext" "$work/again_comb.$ext"; then ok; else fail "mesh .$ext output is not deterministic"; fi
done
# Refused runs: exit code, message, no output file.
# 3D runs are tested in mesh3d_test.sh; here only that 3D input reaches them.
expect 0 "mesh 3D input" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/cube_3d.vtu" --quiet
for bad in 0 -1 abc inf nan 1e999; do
  expect 64 "mesh --max-size $bad" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/never_size.vtu" --max-size "$bad"
  contains "$work/err" "max-size" "--max-size $bad message names the option"
done
expect 64 "mesh without -o" -- "$pqmesh" mesh "$data/2d/square.poly"
expect 64 "mesh with an unknown --format" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/never_fmt.vtu" --format xyz
expect 2 "mesh to an unknown extension" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/never_ext.xyz"
expect 2 "mesh a bad 2D domain" -- "$pqmesh" mesh "$data/bad/2d_self_crossing.poly" -o "$work/never_bad.vtu"
contains "$work/err" "error \[self-intersecting-facet\]" "bad 2D domain error kind"
printf '0 0 0.1\n# two fields on line 3\n1 1\n' > "$work/field_fields.txt"
printf '0 0 0.1\n\n0.5 0.5 0\n' > "$work/field_zero.txt"
printf '0 0 0.1\n0 x 0.1\n' > "$work/field_text.txt"
printf '0 0 0.1\n0 0 0.1\n0 0 inf\n# end\n' > "$work/field_inf.txt"
for case in fields:3 zero:3 text:2 inf:3; do
  name=${case%%:*} line=${case##*:}
  expect 2 "mesh with bad size field ($name)" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/never_field.vtu" \
    --size-field "$work/field_$name.txt"
  contains "$work/err" "field_$name.txt:$line: " "bad size field ($name) names line $line"
done
expect 2 "mesh with a missing size field" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/never_field.vtu" \
  --size-field "$work/no_such_field.txt"
if [[ -z $(ls "$work" | grep -E '^never') ]]; then ok; else fail "refused mesh runs left files: $(ls "$work" | grep -E '^never')"; fi

# pqmesh octree: leaf boxes as VTK hexahedra.
expect 0 "octree cube" -- "$pqmesh" octree "$data/3d/cube.poly" -o "$work/cube_boxes.vtu"
contains "$work/cube_boxes.vtu" "UnstructuredGrid" "octree writes a .vtu"
contains "$work/cube_boxes.vtu" "Name=\"level\"" "octree .vtu has the level field"
contains "$work/cube_boxes.vtu" "Name=\"cone_kind\"" "octree .vtu has the cone kind field"
contains "$work/cube_boxes.vtu" "Name=\"protected_by\"" "octree .vtu has the protection step field"
contains "$work/out" "^kinds .* other 0$" "every cube octree leaf is one of the thesis kinds"
if /usr/bin/python3 -c "import meshio, sys; m = meshio.read(sys.argv[1]); sys.exit(0 if m.cells[0].type == 'hexahedron' and len(m.cells[0].data) > 0 else 1)" "$work/cube_boxes.vtu" 2>/dev/null; then ok; else fail "meshio does not read the octree boxes as hexahedra"; fi
# --light is the octree `pqmesh mesh` tries first: on the cube, which keeps
# it, both report the same leaves.
expect 0 "mesh cube" -- "$pqmesh" mesh "$data/3d/cube.poly" -o "$work/cube_light.vtu"
contains "$work/out" "^octree +lightest" "the cube's mesh comes from the lightest octree"
mesh_leaves=$(sed -n 's/^leaves *\([0-9]*\):.*/\1/p' "$work/out")
expect 0 "octree --light cube" -- "$pqmesh" octree "$data/3d/cube.poly" --generic-grid --light -o "$work/cube_light_boxes.vtu"
light_leaves=$(sed -n 's/^leaves *\([0-9]*\) .*/\1/p' "$work/out")
if [[ -n $mesh_leaves && $mesh_leaves == "$light_leaves" ]]; then ok; else fail "octree --light has '$light_leaves' leaves, mesh's octree '$mesh_leaves'"; fi
expect 2 "octree of a 2D input" -- "$pqmesh" octree "$data/2d/square.poly" -o "$work/never_octree.vtu"
expect 64 "octree without -o" -- "$pqmesh" octree "$data/3d/cube.poly"
if [[ ! -e $work/never_octree.vtu ]]; then ok; else fail "refused octree run left a file"; fi
# Size control (thesis §1.1): --max-size and a 3D size field (x y z size).
expect 0 "octree cube --max-size" -- "$pqmesh" octree "$data/3d/cube.poly" -o "$work/cube_boxes_h.vtu" --max-size 0.125
contains "$work/out" "^splits     size [1-9]" "octree --max-size splits in the size phase"
contains "$work/out" "^phases" "octree summary has the per-phase line"
contains "$work/out" "edge-separate [1-9].*facet-separate [1-9]" "octree summary counts the separating splits (thesis 4.1.7 steps 6, 9)"
contains "$work/out" "facet-protect [1-9]" "octree summary has the facet-protect phase"
printf '# x y z size\n0.5 0.5 0.9 0.01\n' > "$work/field3.txt"
expect 0 "octree cube --size-field" -- "$pqmesh" octree "$data/3d/cube.poly" -o "$work/cube_boxes_f.vtu" --size-field "$work/field3.txt"
contains "$work/out" "^splits     size [1-9]" "octree --size-field splits in the size phase"
printf '0.5 0.5 0.01\n' > "$work/field3_short.txt"
expect 2 "octree with a 2D size field" -- "$pqmesh" octree "$data/3d/cube.poly" -o "$work/never_octree_f.vtu" --size-field "$work/field3_short.txt"
contains "$work/err" "field3_short.txt:1: " "bad 3D size field names its line"
expect 64 "octree --max-size 0" -- "$pqmesh" octree "$data/3d/cube.poly" -o "$work/never_octree_h.vtu" --max-size 0
if [[ ! -e $work/never_octree_f.vtu && ! -e $work/never_octree_h.vtu ]]; then ok; else fail "refused octree size runs left a file"; fi

finish cli_test
