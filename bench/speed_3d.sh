#!/usr/bin/env bash
# The 3D speed benchmark at about a million tetrahedra: `pqmesh mesh` with a
# size bound, Debian's TetGen (-pq1.414 with its default optimisation) and Gmsh
# HXT on 2 threads, one after the other in one session, on one input (default
# the unit cube, data/3d/cube.poly). The peers aim at the count pqmesh made
# (its final count, after the improvement stage). Not a test: it measures and
# prints; it never fails because a tool is missing.
#
#   bench/speed_3d.sh [--max-size H] [--repeat R] [--keep] [INPUT.poly]
#
#   --max-size H   pqmesh's size bound (default 0.02: about a million final
#                  tetrahedra on the unit cube)
#   --repeat R     time each run R times, keep the fastest (default 1)
#   --keep         keep the work directory (meshes, logs)
#
# Sizes: TetGen's -a (maximum volume) and HXT's point size are calibrated by
# one trial each from the count pqmesh made (count ~ 1 / a for TetGen, count ~
# size^-3 for HXT, starting from HXT's measured 4.0 tetrahedra per size^3 on
# the cube); they land within about 10% of pqmesh's count.
#
# Columns: wall s and peak MiB from /usr/bin/time -f '%e %M' over the whole
# process (read, mesh, write: TetGen its ASCII .node/.ele/.face, Gmsh binary
# .msh 4.1, pqmesh binary .vtu after its improvement stage and its own exact
# check); tet/s = tetrahedra / wall s; B/tet = peak bytes / tetrahedra; min
# dihedral (degrees) and worst aspect ratio from `pqmesh quality` of each output
# (outside the timing); "peer / pqmesh" = the peer's wall time over pqmesh's,
# the speed-up at (about) equal count. The last lines compare with the targets:
# 3x TetGen, 2x HXT, at most 200 bytes per tetrahedron.
#
# Environment: PQMESH_BIN (default build/bin/pqmesh, relative to the repo root).
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
pqmesh=${PQMESH_BIN:-build/bin/pqmesh}
[[ $pqmesh == /* ]] || pqmesh=$root/$pqmesh
size=0.02 repeat=1 keep=0 input=$root/data/3d/cube.poly
while (($#)); do
  case $1 in
    --max-size) size=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "speed_3d.sh: unknown option $1" >&2; exit 2 ;;
    *) [[ -f $1 ]] || { echo "speed_3d.sh: no such input $1" >&2; exit 2; }
       input=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); shift ;;
  esac
done
[[ -x $pqmesh ]] || { echo "speed_3d.sh: no pqmesh at $pqmesh (set PQMESH_BIN)" >&2; exit 2; }
work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_speed3d.XXXXXX")
if ((keep)); then echo "work directory: $work"; else trap 'rm -rf "$work"' EXIT; fi
have_time=0; [[ -x /usr/bin/time ]] && have_time=1
source "$root/bench/timed.sh"  # timed LOG CMD...: rc, wall, kib

# quality FILE: sets tets, dmin, aspect, volume from `pqmesh quality` (which
# exits non-zero on a mesh with duplicate vertices, as HXT's often has, after
# printing its figures: they are kept, with a note).
quality() {
  tets=n/a dmin=n/a aspect=n/a volume=n/a
  "$pqmesh" quality "$1" >"$work/q.txt" 2>"$work/q.err" || echo "note: pqmesh quality $1 exited $?: $(head -c 200 "$work/q.err")" >&2
  tets=$(awk '/^quality of/ { print $3; exit }' "$work/q.txt")
  dmin=$(awk '/^min dihedral/ { print $4; exit }' "$work/q.txt")
  aspect=$(awk '/^aspect ratio/ { print $5; exit }' "$work/q.txt")
  volume=$(awk '/^total volume/ { print $3; exit }' "$work/q.txt")
}

rows=() walls=()
row() {  # tool tets wall kib dmin aspect
  local tps=n/a bpt=n/a mib=n/a
  if [[ $2 =~ ^[0-9]+$ && $2 -gt 0 && $3 != n/a ]]; then
    tps=$(awk -v n="$2" -v w="$3" 'BEGIN { printf "%.0f", n / (w > 0 ? w : 0.01) }')
    [[ $4 =~ ^[0-9]+$ ]] && bpt=$(awk -v n="$2" -v k="$4" 'BEGIN { printf "%.0f", k * 1024 / n }')
  fi
  [[ $4 =~ ^[0-9]+$ ]] && mib=$(awk -v k="$4" 'BEGIN { printf "%.1f", k / 1024 }')
  rows+=("$1	$2	$3	$mib	$tps	$bpt	$5	$6")
  walls+=("$3")
}

# pqmesh: the timed run sets the count the peers aim at.
dir=$work/pqmesh; mkdir -p "$dir"
want=""
if timed "$dir/log" "$pqmesh" mesh "$input" -o "$dir/m.vtu" --quiet --max-size "$size"; then
  quality "$dir/m.vtu"
  row "pqmesh --max-size $size" "$tets" "$wall" "$kib" "$dmin" "$aspect"
  [[ $tets =~ ^[0-9]+$ ]] && want=$tets
  vol=$volume
else
  row "pqmesh --max-size $size" failed n/a n/a n/a n/a
fi

if command -v tetgen >/dev/null && [[ -n $want ]]; then
  dir=$work/tetgen; mkdir -p "$dir"; cp "$input" "$dir/m.poly"
  a=$(awk -v v="$vol" -v n="$want" 'BEGIN { printf "%.6g", 2 * v / n }')
  (cd "$dir" && tetgen -pq1.414Qa"$a" m.poly >/dev/null 2>&1)
  n0=$(awk 'NR == 1 { print $1 }' "$dir/m.1.ele" 2>/dev/null)
  [[ $n0 =~ ^[0-9]+$ ]] && a=$(awk -v a="$a" -v n="$n0" -v w="$want" 'BEGIN { printf "%.6g", a * n / w }')
  rm -f "$dir"/m.1.*
  if timed "$dir/log" bash -c "cd '$dir' && tetgen -pq1.414Qa$a m.poly"; then
    quality "$dir/m.1.ele"
    row "tetgen -pq1.414a$a" "$tets" "$wall" "$kib" "$dmin" "$aspect"
  else
    row "tetgen -pq1.414a$a" failed n/a n/a n/a n/a
  fi
fi

if command -v gmsh >/dev/null && [[ -n $want ]]; then
  dir=$work/hxt; mkdir -p "$dir"
  lc=$(awk -v v="$vol" -v n="$want" 'BEGIN { printf "%.6g", (4.0 * v / n) ^ (1 / 3) }')
  python3 "$root/bench/peers3d/poly3d.py" geo "$input" "$dir/m.geo" "$lc"
  gmsh -3 "$dir/m.geo" -algo hxt -nt 2 -o "$dir/trial.msh" -format msh41 >/dev/null 2>&1
  quality "$dir/trial.msh"
  [[ $tets =~ ^[0-9]+$ ]] && lc=$(awk -v l="$lc" -v n="$tets" -v w="$want" 'BEGIN { printf "%.6g", l * (n / w) ^ (1 / 3) }')
  rm -f "$dir/trial.msh"
  python3 "$root/bench/peers3d/poly3d.py" geo "$input" "$dir/m.geo" "$lc"
  if timed "$dir/log" gmsh -3 "$dir/m.geo" -algo hxt -nt 2 -o "$dir/m.msh" -format msh41 -bin; then
    gmsh "$dir/m.msh" -0 -o "$dir/ascii.msh" -format msh41 >/dev/null 2>&1
    quality "$dir/ascii.msh"
    row "gmsh hxt -nt 2, size $lc" "$tets" "$wall" "$kib" "$dmin" "$aspect"
  else
    row "gmsh hxt -nt 2, size $lc" failed n/a n/a n/a n/a
  fi
fi

echo "# $(basename "$input"), $(date -u +%Y-%m-%d), $(nproc) cores"
{
  echo "tool	tets	wall s	peak MiB	tet/s	B/tet	min dih	max aspect	peer / pqmesh"
  for i in "${!rows[@]}"; do
    ratio=n/a
    ((i > 0)) && ratio=$(awk -v p="${walls[$i]}" -v q="${walls[0]}" 'BEGIN { if (p + 0 > 0 && q + 0 > 0) printf "%.2f", p / q; else print "n/a" }')
    ((i == 0)) && ratio=1
    echo "${rows[$i]}	$ratio"
  done
} | column -t -s $'\t'
# Targets: TetGen / pqmesh >= 3, HXT / pqmesh >= 2, pqmesh <= 200 B/tet.
bpt=$(awk -F'\t' 'NR == 1 { print $6 }' <<<"${rows[0]}")
echo "targets: TetGen / pqmesh >= 3, HXT / pqmesh >= 2; pqmesh ${bpt} B/tet (target <= 200)"
