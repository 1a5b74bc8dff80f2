#!/usr/bin/env bash
# The 3D peer benchmark: tetrahedral meshers side by side in one session on
# the same inputs — Debian's tetgen (-pq1.414), gmsh -3 with its default
# algorithm and with HXT on two threads, and `pqmesh mesh` (a model it
# refuses with exit 2 gets an n/a row). Not a test: it measures,
# prints a table and never fails because a tool is missing.
#
#   bench/run_3d.sh [--target N] [--large-target N] [--no-large] [--repeat R]
#                   [--tsv FILE] [--keep] [INPUT.poly ...]
#
#   --target N        corpus: aim pqmesh at about N tetrahedra, the peers at
#                     pqmesh's count (default:
#                     each tool at its own default size; gmsh's point size is
#                     then a tenth of the model's largest extent)
#   --large-target N  large case (data/3d/plate_holes.poly): about N
#                     tetrahedra, as --target (default 1000000)
#   --no-large        skip the large case
#   --repeat R        time each run R times, report the fastest (default 1)
#   --tsv FILE        also write the table as tab-separated values
#   --keep            keep the work directory (meshes, logs, .geo files)
#   INPUT.poly ...    TetGen .poly inputs instead of data/3d/*.poly
#
# Sizes: pqmesh first: its --max-size moves the count in steps of about 8
# (box sides are powers of two), so trial runs halve H from the root side
# until the next step would pass the target and keep the count nearest it. The peers then aim at
# the count pqmesh made, each calibrated by trial runs and the power law
# count ~ (max volume)^-1 for tetgen -a, count ~ (point size)^-3 for gmsh;
# one calibration step for tetgen, two for gmsh; their counts land within
# about 30% of pqmesh's.
#
# Columns: wall s and peak MiB from /usr/bin/time -f '%e %M' over the whole
# process (read, mesh, write: tetgen its ASCII .node/.ele/.face, gmsh binary
# .msh 4.1, pqmesh binary .vtu after its own check); tet/s = tetrahedra / wall
# s; B/tet = peak bytes / tetrahedra; min and max dihedral (degrees) and the
# worst aspect ratio from `pqmesh quality` on each tool's output (gmsh's
# binary file converted to ASCII first, outside the timing); valid = `pqmesh
# check` of the output against the input domain: the exact checker, which
# accepts a boundary vertex off a slanted facet only when it is a faithful
# rounding (within an ulp, docs/algorithm/quality.md "The validity checker").
# gmsh's vertices inside facets are often a few ulps off the facet plane, and
# gmsh HXT (2 threads, Debian 12's gmsh) varies from run to run and often writes
# two vertices with the same coordinates; those meshes show NO (pqmesh quality
# then also exits non-zero and says so on stderr, the table keeps its figures as
# n/a).
#
# Environment: PQMESH_BIN (default build/bin/pqmesh, relative to the repo root).
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
peers=$root/bench/peers3d
source "$root/bench/peer_cli.sh"  # peer_setup, peer_table
peer_setup 3 "$@"  # pqmesh, the options, work

have_time=0; [[ -x /usr/bin/time ]] && have_time=1
have_pqmesh=0; [[ -x $pqmesh ]] && have_pqmesh=1
have_tetgen=0; command -v tetgen >/dev/null && have_tetgen=1
have_gmsh=0; command -v gmsh >/dev/null && have_gmsh=1
((have_pqmesh)) || echo "note: $pqmesh not found; quality, check and pqmesh columns need it (cmake --build build)" >&2

source "$root/bench/timed.sh"  # timed LOG CMD...

# quality FILE: sets tets, dmin, dmax, aspect from `pqmesh quality`.
quality() {
  tets=n/a dmin=n/a dmax=n/a aspect=n/a
  ((have_pqmesh)) || return 0
  "$pqmesh" quality "$1" >"$work/q.txt" 2>&1 || { echo "quality of $1 failed: $(head -c 300 "$work/q.txt")" >&2; return 0; }
  tets=$(awk '/^quality of/ { print $3; exit }' "$work/q.txt")
  dmin=$(awk '/^min dihedral/ { print $4; exit }' "$work/q.txt")
  dmax=$(awk '/^max dihedral/ { print $6; exit }' "$work/q.txt")
  aspect=$(awk '/^aspect ratio/ { print $5; exit }' "$work/q.txt")
}

# validity MESH DOMAIN: "yes", "NO" or "n/a".
validity() {
  ((have_pqmesh)) || { echo n/a; return; }
  if "$pqmesh" check "$1" --domain "$2" >"$work/check.txt" 2>&1; then echo yes; else echo NO; fi
}

rows=()
row() {  # tool input tets wall kib dmin dmax aspect valid
  local tps=n/a bpt=n/a mib=n/a
  if [[ $3 =~ ^[0-9]+$ && $3 -gt 0 ]]; then
    awk -v w="$4" 'BEGIN { exit !(w > 0) }' && tps=$(awk -v n="$3" -v w="$4" 'BEGIN { printf "%.0f", n / w }')
    [[ $5 =~ ^[0-9]+$ ]] && bpt=$(awk -v n="$3" -v k="$5" 'BEGIN { printf "%.0f", k * 1024 / n }')
  fi
  [[ $5 =~ ^[0-9]+$ ]] && mib=$(awk -v k="$5" 'BEGIN { printf "%.1f", k / 1024 }')
  rows+=("$1	$2	$3	$4	$mib	$tps	$bpt	$6	$7	$8	$9")
}

extent() {  # largest bounding-box extent of a .poly's nodes
  awk 'BEGIN { n = -1 } { sub(/#.*/, "") } NF == 0 { next }
       n < 0 { n = $1; next }
       i < n { for (a = 2; a <= 4; a++) { if (i == 0 || $a < lo[a]) lo[a] = $a; if (i == 0 || $a > hi[a]) hi[a] = $a }; i++ }
       END { e = 0; for (a = 2; a <= 4; a++) if (hi[a] - lo[a] > e) e = hi[a] - lo[a]; print e }' "$1"
}

run_tetgen() {  # name input target
  local name=$1 in=$2 want=$3 dir=$work/tetgen_$1 area=""
  mkdir -p "$dir"; cp "$in" "$dir/m.poly"
  if [[ -n $want ]]; then  # calibrate -a from a trial at the default size
    (cd "$dir" && tetgen -pq1.414Q m.poly >/dev/null 2>&1)
    local n0 vol
    n0=$(awk 'NR == 1 { print $1 }' "$dir/m.1.ele" 2>/dev/null)
    vol=$("$pqmesh" quality "$dir/m.1.ele" 2>/dev/null | awk '/^total volume/ { print $3 }')
    [[ -n $n0 && -n $vol ]] && area=$(awk -v v="$vol" -v n="$want" 'BEGIN { printf "%.6g", 2 * v / n }')
    rm -f "$dir"/m.1.*
  fi
  if ! timed "$dir/log" bash -c "cd '$dir' && tetgen -pq1.414Q${area:+a$area} m.poly"; then
    row tetgen "$name" failed n/a n/a n/a n/a n/a n/a; return
  fi
  quality "$dir/m.1.ele"
  row tetgen "$name" "$tets" "$wall" "$kib" "$dmin" "$dmax" "$aspect" "$(validity "$dir/m.1.ele" "$in")"
}

run_gmsh() {  # name input target label extra-args...
  local name=$1 in=$2 want=$3 label=$4; shift 4
  local dir=$work/${label}_$name lc
  mkdir -p "$dir"
  lc=$(awk -v e="$(extent "$in")" 'BEGIN { printf "%.6g", e / 10 }')
  python3 "$peers/poly3d.py" geo "$in" "$dir/m.geo" "$lc" || { row "$label" "$name" failed n/a n/a n/a n/a n/a n/a; return; }
  if [[ -n $want ]]; then  # calibrate the point size: two steps (boundary-dominated trials undershoot)
    local step
    for step in 1 2; do
      gmsh -3 "$dir/m.geo" -o "$dir/trial.msh" -format msh41 "$@" >/dev/null 2>&1
      quality "$dir/trial.msh"
      [[ $tets =~ ^[0-9]+$ ]] && lc=$(awk -v l="$lc" -v n="$tets" -v w="$want" 'BEGIN { printf "%.6g", l * (n / w) ^ (1 / 3) }')
      python3 "$peers/poly3d.py" geo "$in" "$dir/m.geo" "$lc"
    done
  fi
  if ! timed "$dir/log" gmsh -3 "$dir/m.geo" -o "$dir/m.msh" -format msh41 -bin "$@"; then
    row "$label" "$name" failed n/a n/a n/a n/a n/a n/a; return
  fi
  gmsh "$dir/m.msh" -0 -o "$dir/ascii.msh" -format msh41 >/dev/null 2>&1
  quality "$dir/ascii.msh"
  row "$label" "$name" "$tets" "$wall" "$kib" "$dmin" "$dmax" "$aspect" "$(validity "$dir/ascii.msh" "$in")"
}

# pqmesh_trial IN [H]: sets n (tetrahedra of `pqmesh mesh IN [--max-size H]`,
# empty on failure) and side (the root cube side from the summary).
pqmesh_trial() {
  local out
  out=$("$pqmesh" mesh "$1" -o "$work/trial.vtu" ${2:+--max-size "$2"} 2>/dev/null)
  n=$(awk '/^mesh/ { print $2; exit }' <<<"$out")
  side=$(awk '/^grid/ { for (i = 1; i < NF; ++i) if ($i == "side") { gsub(/,/, "", $(i + 1)); print $(i + 1) } }' <<<"$out")
}

# pqmesh_size IN TARGET: sets size to the --max-size (empty: none) whose count
# is nearest TARGET in ratio. --max-size only refines the default mesh, and box
# sides are powers of two, so the count is flat in H between powers of two and
# grows about 8-fold per halving once H binds. From the default run, H starts
# at the root side and halves; a trial is run only while the count it would
# give (8 times the last, once binding) is not farther from TARGET than the
# last count (no 8x overshoot trials).
pqmesh_size() {
  local in=$1 want=$2 h last k prev_h="" n side
  size=""
  pqmesh_trial "$in"
  [[ $n =~ ^[0-9]+$ && $side =~ ^[0-9.e+-]+$ ]] || return 0
  last=$n h=$side
  for ((k = 0; k < 16; k++)); do
    # Stop when the next step (x8) would land farther from the target.
    awk -v n="$last" -v w="$want" 'BEGIN { exit !(w * w <= 8 * n * n) }' && { size=$prev_h; return 0; }
    h=$(awk -v h="$h" 'BEGIN { printf "%.6g", h / 2 }')
    pqmesh_trial "$in" "$h"
    [[ $n =~ ^[0-9]+$ ]] || { size=$prev_h; return 0; }
    ((n == last)) && continue  # H does not bind yet
    if ((n >= want)); then  # bracketed: the nearer of the two
      awk -v a="$last" -v b="$n" -v w="$want" 'BEGIN { exit !(w / a <= b / w) }' && size=$prev_h || size=$h
      return 0
    fi
    last=$n prev_h=$h
  done
  size=$prev_h
}

run_pqmesh() {  # name input target; sets pq_tets (count meshed, for the peers)
  local name=$1 in=$2 want=$3 dir=$work/pqmesh_$1 size=""
  pq_tets=""
  mkdir -p "$dir"
  ((have_pqmesh)) || { row pqmesh "$name" missing n/a n/a n/a n/a n/a n/a; return; }
  "$pqmesh" mesh "$in" -o "$dir/probe.vtu" --quiet >/dev/null 2>&1
  if [[ $? -eq 2 ]]; then row pqmesh "$name" "n/a (not supported)" n/a n/a n/a n/a n/a n/a; return; fi
  local opts=()
  if [[ -n $want ]]; then
    pqmesh_size "$in" "$want"
    [[ -n $size ]] && opts=(--max-size "$size")
  fi
  if ! timed "$dir/log" "$pqmesh" mesh "$in" -o "$dir/m.vtu" --quiet "${opts[@]}"; then
    row pqmesh "$name" failed n/a n/a n/a n/a n/a n/a; return
  fi
  quality "$dir/m.vtu"
  [[ $tets =~ ^[0-9]+$ ]] && pq_tets=$tets
  row pqmesh "$name" "$tets" "$wall" "$kib" "$dmin" "$dmax" "$aspect" yes  # pqmesh checks before writing
}

run_all() {  # name input target
  run_pqmesh "$@"
  # With a target, the peers aim at the count pqmesh actually made (its
  # sizes come in steps of about 8x), so all rows compare equal counts.
  local want=$3
  [[ -n $want && -n $pq_tets ]] && want=$pq_tets
  if ((have_tetgen)); then run_tetgen "$1" "$2" "$want"; else row tetgen "$1" missing n/a n/a n/a n/a n/a n/a; fi
  if ((have_gmsh)); then
    run_gmsh "$1" "$2" "$want" gmsh-default
    run_gmsh "$1" "$2" "$want" gmsh-hxt -algo hxt -nt 2
  else
    row gmsh "$1" missing n/a n/a n/a n/a n/a n/a
  fi
}

for in in "${inputs[@]}"; do
  run_all "$(basename "$in" .poly)" "$in" "$target"
done
((large)) && run_all "plate_holes@${large_target}" "$root/data/3d/plate_holes.poly" "$large_target"

header="tool	input	tets	wall s	peak MiB	tet/s	B/tet	min dih	max dih	max aspect	valid"
peer_table "$header"
