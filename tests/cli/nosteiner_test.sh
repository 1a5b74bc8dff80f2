#!/usr/bin/env bash
# pqmesh mesh --no-boundary-steiner (thesis ch. 5): every data/2d input is
# meshed, the summary has its lines, the written mesh passes
# 'pqmesh check --no-boundary-steiner' on its own, and failures write nothing.
# usage: nosteiner_test.sh PQMESH_BINARY DATA_DIR FIXTURE_DIR
pqmesh=$1 data=$2
source "$(dirname "$0")/harness.sh"

for f in "$data"/2d/*.poly; do
  b=$(basename "$f" .poly)
  expect 0 "mesh --no-boundary-steiner $b" -- "$pqmesh" mesh "$f" -o "$work/$b.vtu" --no-boundary-steiner
  cp "$work/out" "$work/$b.summary"
  contains "$work/$b.summary" "^bound g +g\(P\) = [0-9.e+-]+ deg; .* <= min\(60, 5\.319 \* g, alpha = [0-9.e+-]+, segment = [0-9.e+-]+, fan = [0-9.e+-]+\) = " "g line $b"
  contains "$work/$b.summary" "^angles +min [0-9.e+-]+ deg; achieved / upper bound = [0-9.e+-]+ \(upper bound [0-9.e+-]+ deg\); achieved / g = " "angles line $b"
  contains "$work/$b.summary" "^refined +best refined candidate .* min [0-9.e+-]+ deg" "refined line $b"
  contains "$work/$b.summary" "^cdt +constrained Delaunay .* min [0-9.e+-]+ deg" "cdt line $b"
  contains "$work/$b.summary" "^path +(full|q-only|cdt|cdt-better|refined)" "path line $b"
  contains "$work/$b.summary" "^check +valid \(no boundary Steiner\)" "check line $b"
  # The written file, checked independently by the checker subcommand.
  expect 0 "check --no-boundary-steiner $b" -- "$pqmesh" check "$work/$b.vtu" --domain "$f" --no-boundary-steiner
done

# --fixed-boundary is accepted (the plain mode already keeps the boundary), --quiet prints nothing.
expect 0 "fixed-boundary synonym" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/fb.vtu" --no-boundary-steiner --fixed-boundary --quiet
[[ -s $work/out ]] && fail "--quiet printed: $(head -c 200 "$work/out")" || ok
# A straight angle on the boundary (subdivided side) is kept: the checker finds no boundary Steiner point.
printf '5 2 0 0\n1 0 0\n2 1 0\n3 2 0\n4 2 1\n5 0 1\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 1\n0\n' >"$work/straight.poly"
expect 0 "straight angle" -- "$pqmesh" mesh "$work/straight.poly" -o "$work/straight.vtu" --no-boundary-steiner
expect 0 "straight angle check" -- "$pqmesh" check "$work/straight.vtu" --domain "$work/straight.poly" --no-boundary-steiner

# --pipeline keeps the pipeline's mesh (path full, never cdt-better); --thesis-fans connects Q to R by
# the thesis's fans and keeps that mesh. Both outputs pass the checker.
expect 0 "square --pipeline" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/pl.vtu" --no-boundary-steiner --pipeline
contains "$work/out" "^path +full" "--pipeline writes the pipeline's mesh"
expect 0 "square --pipeline check" -- "$pqmesh" check "$work/pl.vtu" --domain "$data/2d/square.poly" --no-boundary-steiner
expect 0 "comb --thesis-fans" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/fans.vtu" --no-boundary-steiner --thesis-fans
contains "$work/out" "^mode .*connected by the thesis's fans" "--thesis-fans named in the mode line"
contains "$work/out" "^path +full" "--thesis-fans keeps the fans' mesh"
expect 0 "comb --thesis-fans check" -- "$pqmesh" check "$work/fans.vtu" --domain "$data/2d/comb.poly" --no-boundary-steiner
# The quality post-pass (on by default) raises the comb's min angle; --no-quality-pass keeps the
# construction's mesh. Both pass the checker.
expect 0 "comb --no-quality-pass" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/nopass.vtu" --no-boundary-steiner --no-quality-pass
contains "$work/out" "^post-pass .*quality pass off" "--no-quality-pass named in the post-pass line"
expect 0 "comb --no-quality-pass check" -- "$pqmesh" check "$work/nopass.vtu" --domain "$data/2d/comb.poly" --no-boundary-steiner
expect 0 "comb with the quality pass" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/pass.vtu" --no-boundary-steiner
contains "$work/out" "^post-pass .*quality pass on" "the quality pass runs by default"
expect 64 "--no-quality-pass without --no-boundary-steiner" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/never_pass.vtu" --no-quality-pass
[[ -e $work/never_pass.vtu ]] && fail "output written after a usage error" || ok
expect 64 "--thesis-fans without --no-boundary-steiner" -- "$pqmesh" mesh "$data/2d/comb.poly" -o "$work/never_fans.vtu" --thesis-fans
[[ -e $work/never_fans.vtu ]] && fail "output written after a usage error" || ok

# --min-angle A: reached on the square (its CDT has 45 degrees); on the 1-degree spike 10 degrees
# is above the upper bound and reported as not reachable. Both outputs pass the checker.
expect 0 "square --min-angle 30" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/ma.vtu" --no-boundary-steiner --min-angle 30
contains "$work/out" "^target +30 deg: reached" "--min-angle reached"
expect 0 "spike_1deg --min-angle 10" -- "$pqmesh" mesh "$data/2d/spike_1deg.poly" -o "$work/ma1.vtu" --no-boundary-steiner --min-angle 10
contains "$work/out" "^target +10 deg: not reached; best [0-9.e+-]+ deg; 10 not reachable: upper bound [0-9.e+-]+ deg" "--min-angle not reachable"
expect 0 "spike_1deg --min-angle check" -- "$pqmesh" check "$work/ma1.vtu" --domain "$data/2d/spike_1deg.poly" --no-boundary-steiner
expect 64 "bad --min-angle" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/bad_ma.vtu" --no-boundary-steiner --min-angle 0
[[ -e $work/bad_ma.vtu ]] && fail "output written after a usage error" || ok

# Failures write nothing: a missing -o, a bad option value, an invalid input.
expect 64 "missing -o" -- "$pqmesh" mesh "$data/2d/square.poly" --no-boundary-steiner
expect 64 "bad --refine-angle" -- "$pqmesh" mesh "$data/2d/square.poly" -o "$work/bad.vtu" --no-boundary-steiner --refine-angle 45
[[ -e $work/bad.vtu ]] && fail "output written after a usage error" || ok
printf '3 2 0 0\n1 0 0\n2 1 0\n3 2 0\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n' >"$work/flat.poly"
expect 2 "degenerate input" -- "$pqmesh" mesh "$work/flat.poly" -o "$work/flat.vtu" --no-boundary-steiner
[[ -e $work/flat.vtu ]] && fail "output written for an invalid input" || ok

finish nosteiner_test
