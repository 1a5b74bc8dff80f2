#!/usr/bin/env bash
# The 2D peer benchmark: pqmesh's quadtree mesher against Triangle, gmsh and
# CGAL Mesh_2 on every data/2d/*.poly plus one large case (a unit square plate
# with 5 circular holes, meshed by pqmesh into >= 1 million triangles). Not a
# test: it measures, prints a table and never fails because a tool is missing.
#
#   bench/run_2d.sh [--target N] [--large-target N] [--no-large] [--repeat R]
#                   [--tsv FILE] [--keep] [INPUT.poly ...]
#
#   --target N        corpus: run pqmesh with --max-size sqrt(2 area / N) and aim
#                     the peers at N triangles when pqmesh is missing
#                     (default: pqmesh without --max-size; see "Sizes" below)
#   --large-target N  large case: the peers' count when pqmesh is missing (default 1000000)
#   --no-large        skip the large case
#   --repeat R        time each run R times, report the fastest (default 1)
#   --tsv FILE        also write the table as tab-separated values
#   --keep            keep the work directory (meshes, logs, .geo files)
#   INPUT.poly ...    inputs instead of data/2d/*.poly
#
# Sizes: pqmesh's triangle count on an input is the target of the peers on
# that input; each peer's size parameter (Triangle -a area, gmsh point size,
# CGAL longest-edge bound) is calibrated by one trial run at N triangles (N/4
# above 400000) and the power law count ~ area^-1 ~ length^-2. With no pqmesh and
# no --target, the corpus runs Triangle and CGAL with no size bound (quality
# only) and gmsh aimed at Triangle's count. Triangle runs as `triangle -pqQ`
# (20 degrees) without output files; CGAL with shape bound 0.125 (20.7 degrees).
#
# Columns: wall s and peak MiB from /usr/bin/time -f '%e %M' over the whole
# process (reading, meshing, writing: pqmesh writes binary .vtu and runs its
# check, gmsh writes binary .msh 4.1, Triangle and CGAL write nothing); mesh s
# is the tool's own meshing time where it reports one (Triangle -V total,
# gmsh "Done meshing 2D" wall, CGAL triangulate+refine); tri/s = triangles /
# wall s; B/tri = peak bytes / triangles; min angle in degrees (pqmesh:
# `pqmesh quality`; gmsh: computed from the .msh by poly2d.py msh-stats;
# Triangle: -V statistics; CGAL: its own output).
#
# Environment: PQMESH_BIN (default build/bin/pqmesh, relative to the repo root),
# CXX (default g++) for the CGAL program, built into build-bench/peers2d.
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
peers=$root/bench/peers2d
source "$root/bench/peer_cli.sh"  # peer_setup, peer_table
peer_setup 2 "$@"  # pqmesh, the options, work

# ---------------------------------------------------------------- tools
# A python with meshio and numpy, for gmsh's .msh (Debian's python3-meshio
# lives in /usr/bin/python3, which a pyenv python3 on PATH may hide).
py=python3 py_meshio=""
for cand in python3 /usr/bin/python3; do
  if command -v "$cand" >/dev/null && "$cand" -c 'import meshio, numpy' 2>/dev/null; then py_meshio=$cand; break; fi
done
command -v python3 >/dev/null || py=/usr/bin/python3
have_time=0; [[ -x /usr/bin/time ]] && have_time=1
have_pqmesh=0; [[ -x $pqmesh ]] && have_pqmesh=1
have_triangle=0; command -v triangle >/dev/null && have_triangle=1
have_gmsh=0; command -v gmsh >/dev/null && have_gmsh=1

cgal=$root/build-bench/peers2d/cgal_mesh2
have_cgal=0
if [[ -x $cgal && $cgal -nt $peers/cgal_mesh2.cpp ]]; then
  have_cgal=1
elif [[ -d /usr/include/CGAL ]]; then
  mkdir -p "$(dirname "$cgal")"
  echo "building $cgal ..." >&2
  if "${CXX:-g++}" -std=c++17 -O2 -DNDEBUG -o "$cgal" "$peers/cgal_mesh2.cpp" -lgmp -lmpfr 2>"$work/cgal_build.log"; then
    have_cgal=1
  else
    echo "CGAL program failed to build (see below); CGAL column will say missing" >&2
    head -20 "$work/cgal_build.log" >&2
  fi
fi

# ---------------------------------------------------------------- helpers
source "$root/bench/timed.sh"  # timed LOG CMD...

# Value after LABEL in a "label value label value" line (the CGAL program's output).
field() { awk -v key="$1" '{ for (i = 1; i < NF; i++) if ($i == key) { print $(i + 1); exit } }' "$2"; }

# trial_size N: the triangle count of a calibration run aimed at N triangles:
# N itself up to 100000, else a quarter of N (at least 100000).
trial_size() { local n=$1; ((n <= 100000)) && echo "$n" || echo $((n / 4 > 100000 ? n / 4 : 100000)); }

# calc EXPR: floating-point arithmetic in awk.
calc() { awk "BEGIN { printf \"%.15g\", $1 }"; }

rows=()
# row TOOL INPUT TRIANGLES WALL KIB MESH_S MIN_ANGLE [NOTE]
row() {
  local tool=$1 input=$2 tris=$3 w=$4 k=$5 ms=$6 ang=$7 note=${8:-}
  rows+=("$(awk -v t="$tool" -v i="$input" -v n="$tris" -v w="$w" -v k="$k" -v ms="$ms" -v a="$ang" -v note="$note" 'BEGIN {
    num = "^[0-9.]+$"
    mib = (k ~ num) ? sprintf("%.1f", k / 1024) : "n/a"
    tps = (n ~ num && w ~ num && w > 0) ? sprintf("%.3g", n / w) : "n/a"
    bpt = (n ~ num && k ~ num && n > 0) ? sprintf("%.0f", k * 1024 / n) : "n/a"
    if (ms ~ num) ms = sprintf("%.3f", ms)
    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s", t, i, n, w, ms, mib, tps, bpt, a, note }')")
}
absent() { rows+=("$1"$'\t'"$2"$'\tmissing\t\t\t\t\t\t\t'"${3:-}"); }
failed() { rows+=("$1"$'\t'"$2"$'\tfailed\t\t\t\t\t\t\t'"$3"); }

# ---------------------------------------------------------------- peers
# Each run_* takes NAME DIR POLY AREA TARGET (TARGET empty: no size bound) and
# sets peer_count (triangles, or empty on failure) for the next peer's target.

run_triangle() {
  local name=$1 dir=$2 poly=$3 area=$4 n=$5 a="" flags=()
  peer_count=""
  if [[ -n $n ]]; then
    # Quality triangles average about 0.6 of the -a bound; one trial run corrects the guess.
    local nc; nc=$(trial_size "$n")
    a=$(calc "$area / (0.6 * $nc)")
    triangle -pq -a"$(printf '%.15f' "$a")" -V -N -E -P "$poly" >"$dir/tri_trial.log" 2>&1
    local got; got=$(awk '/Mesh triangles:/ { print $3 }' "$dir/tri_trial.log")
    [[ -n $got ]] && a=$(calc "$a * $got / $n")
    flags=(-a"$(printf '%.15f' "$a")")
  fi
  # Figures from a -V run, the time and memory from a quiet run of the same mesh.
  triangle -pq "${flags[@]}" -V -N -E -P "$poly" >"$dir/tri_stats.log" 2>&1
  if ! timed "$dir/tri.log" triangle -pqQ "${flags[@]}" -N -E -P "$poly"; then
    failed triangle "$name" "exit $rc"; return
  fi
  local tris ang ms
  tris=$(awk '/Mesh triangles:/ { print $3 }' "$dir/tri_stats.log")
  ang=$(awk '/Smallest angle:/ { print $3 }' "$dir/tri_stats.log")
  ms=$(awk '/Total running milliseconds:/ { print $4 / 1000 }' "$dir/tri_stats.log")
  row triangle "$name" "${tris:-n/a}" "$wall" "$kib" "${ms:-n/a}" "${ang:-n/a}" "${a:+-a $(printf '%.3g' "$a")}"
  peer_count=$tris
}

run_cgal() {
  local name=$1 dir=$2 poly=$3 area=$4 n=$5 s=0
  peer_count=""
  if [[ -n $n ]]; then
    # Longest-edge bound about 1.3 equilateral sides; one trial run corrects the guess.
    local nc got; nc=$(trial_size "$n")
    s=$(calc "1.3 * sqrt(4 * $area / (sqrt(3) * $nc))")
    "$cgal" "$poly" "$s" >"$dir/cgal_trial.log" 2>&1
    got=$(field triangles "$dir/cgal_trial.log")
    [[ -n $got ]] && s=$(calc "$s * sqrt($got / $n)")
  fi
  if ! timed "$dir/cgal.log" "$cgal" "$poly" "$s"; then failed cgal "$name" "exit $rc"; return; fi
  local tris; tris=$(field triangles "$dir/cgal.log")
  row cgal "$name" "${tris:-n/a}" "$wall" "$kib" "$(field seconds "$dir/cgal.log")" \
    "$(field min_angle "$dir/cgal.log")" "$([[ $s == 0 ]] && echo "no size bound" || printf 'size %.3g' "$s")"
  peer_count=$tris
}

run_gmsh() {
  local name=$1 dir=$2 poly=$3 area=$4 n=$5
  [[ -n $n ]] || n=1000
  # Equilateral side for the target count; one trial run (log's element count,
  # which also counts boundary lines and points) corrects the guess.
  local nc lc got; nc=$(trial_size "$n")
  lc=$(calc "sqrt(4 * $area / (sqrt(3) * $nc))")
  if ! "$py" "$peers/poly2d.py" geo "$poly" "$dir/in.geo" "$lc" 2>"$dir/geo.log"; then
    failed gmsh "$name" "no .geo: $(tail -1 "$dir/geo.log")"; return
  fi
  gmsh -2 -format msh41 -bin "$dir/in.geo" -o "$dir/trial.msh" >"$dir/gmsh_trial.log" 2>&1
  got=$(awk '/nodes .* elements/ { print $(NF - 1) }' "$dir/gmsh_trial.log" | tail -1)
  rm -f "$dir/trial.msh"
  [[ -n $got ]] && lc=$(calc "$lc * sqrt($got / $n)")
  "$py" "$peers/poly2d.py" geo "$poly" "$dir/in.geo" "$lc"
  if ! timed "$dir/gmsh.log" gmsh -2 -format msh41 -bin "$dir/in.geo" -o "$dir/out.msh"; then
    failed gmsh "$name" "exit $rc"; return
  fi
  local ms tris="n/a" ang="n/a"
  ms=$(sed -n 's/.*Done meshing 2D (Wall \([0-9.e+-]*\)s.*/\1/p' "$dir/gmsh.log" | tail -1)
  if [[ -n $py_meshio ]] && "$py_meshio" "$peers/poly2d.py" msh-stats "$dir/out.msh" >"$dir/msh_stats.txt" 2>&1; then
    tris=$(field triangles "$dir/msh_stats.txt"); ang=$(field min_angle "$dir/msh_stats.txt")
  fi
  row gmsh "$name" "$tris" "$wall" "$kib" "${ms:-n/a}" "$ang" "lc $(printf '%.3g' "$lc")$([[ -n $py_meshio ]] || echo ', no meshio')"
  rm -f "$dir/out.msh"
}

# pqmesh first: its count is the peers' target. Sets pq_count.
run_pqmesh() {
  local name=$1 dir=$2 poly=$3 max_size=$4 min_count=$5 opts=() tries=0
  pq_count=""
  while :; do
    opts=(); [[ -n $max_size ]] && opts=(--max-size "$max_size")
    if ! timed "$dir/pqmesh.log" "$pqmesh" mesh "$poly" -o "$dir/out.vtu" --quiet "${opts[@]}"; then
      failed pqmesh "$name" "exit $rc: $(tail -1 "$dir/pqmesh.log")"; return
    fi
    [[ -s $dir/out.vtu ]] || { failed pqmesh "$name" "exit 0 but wrote no .vtu"; return; }
    "$pqmesh" quality "$dir/out.vtu" >"$dir/quality.txt" 2>&1
    pq_count=$(awk '/^quality of/ { print $3; exit }' "$dir/quality.txt")
    # Large case: halve the box size until the mesh has min_count triangles.
    if [[ -n $min_count && -n $pq_count && $pq_count -lt $min_count && $tries -lt 3 ]]; then
      max_size=$(calc "$max_size / 2"); tries=$((tries + 1)); continue
    fi
    break
  done
  local ang note; ang=$(awk '/^min angle \(deg\)/ { print $4; exit }' "$dir/quality.txt")
  note=${max_size:+max-size $(printf '%.3g' "$max_size")}
  # Size against the lower-bound estimate I = integral of 1/lfs^2 (untimed
  # second run with the summary; only meaningful without a size cap).
  if [[ -z $max_size ]]; then
    local ratio; ratio=$("$pqmesh" mesh "$poly" -o "$dir/summary.vtu" --lfs-integral 2>/dev/null | sed -n 's/.*triangles \/ I = \([0-9.e+-]*\).*/\1/p')
    note="triangles/I ${ratio:-n/a}"; rm -f "$dir/summary.vtu"
  fi
  grep -q INVALID "$dir/quality.txt" && note="$note topology INVALID"
  row pqmesh "$name" "${pq_count:-n/a}" "$wall" "$kib" "n/a" "${ang:-n/a}" "$note"
  rm -f "$dir/out.vtu"
}

bench_input() {
  local poly_src=$1 name=$2 is_large=$3
  local dir=$work/$name; mkdir -p "$dir"
  cp "$poly_src" "$dir/in.poly"  # Triangle writes beside its input; keep data/ clean
  local poly=$dir/in.poly area
  area=$("$py" "$peers/poly2d.py" info "$poly" | awk '{ print $2 }')
  echo "== $name (area $area)" >&2

  local n="" max_size="" min_count=""
  if ((is_large)); then
    n=$large_target; min_count=1000000
    max_size=$(calc "sqrt(2 * $area / $min_count)")  # about two triangles per box
  elif [[ -n $target ]]; then
    n=$target; max_size=$(calc "sqrt(2 * $area / $target)")
  fi
  if ((have_pqmesh)); then
    run_pqmesh "$name" "$dir" "$poly" "$max_size" "$min_count"
    [[ -n $pq_count ]] && n=$pq_count
  else
    absent pqmesh "$name" "$pqmesh"
  fi

  local natural=""
  if ((have_triangle)); then run_triangle "$name" "$dir" "$poly" "$area" "$n"; natural=$peer_count
  else absent triangle "$name"; fi
  if ((have_cgal)); then run_cgal "$name" "$dir" "$poly" "$area" "$n"; [[ -n $natural ]] || natural=$peer_count
  else absent cgal "$name"; fi
  if ((have_gmsh)); then run_gmsh "$name" "$dir" "$poly" "$area" "${n:-$natural}"
  else absent gmsh "$name"; fi
}

# ---------------------------------------------------------------- run
for input in "${inputs[@]}"; do bench_input "$input" "$(basename "$input" .poly)" 0; done
if ((large)); then
  "$py" "$peers/poly2d.py" plate "$work/plate_holes.poly"
  bench_input "$work/plate_holes.poly" plate_holes 1
fi

header=$'tool\tinput\ttriangles\twall s\tmesh s\tpeak MiB\ttri/s\tB/tri\tmin angle\tnote'
peer_table "$header"
exit 0
