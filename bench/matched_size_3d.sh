#!/usr/bin/env bash
# Counts under a size bound against Gmsh HXT at a matched size: for each H,
# `pqmesh mesh INPUT --max-size H` and `gmsh -3 -algo hxt -nt 2` with point
# size H (the same number), then HXT again with its point size scaled so that
# its mean edge length equals pqmesh's (the matched size). Not a test: it
# measures and prints.
#
#   bench/matched_size_3d.sh [INPUT.poly] [H ...]
#
#   INPUT   default data/3d/cube.poly
#   H ...   sizes (default 0.0625 0.05 0.0416667 0.03125)
#
# Why two matches: --max-size H bounds a box side (edges of the improved
# tetrahedra at most sqrt(3) H), while Gmsh's point size is a target edge
# length that its meshes exceed (on the cube, HXT's mean edge is about 1.35
# times its size, and 13-15% of its edges are longer than sqrt(3) times it).
# Columns: tetrahedra, mean edge / H (bench/peers3d/edge_lengths.py), minimum
# dihedral angle (degrees, `pqmesh quality`) for pqmesh, HXT at H and HXT at the
# matched size; "ratio" = pqmesh's count / HXT's at the matched size.
#
# Environment: PQMESH_BIN (default build/bin/pqmesh, relative to the repo root).
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
pqmesh=${PQMESH_BIN:-build/bin/pqmesh}
[[ $pqmesh == /* ]] || pqmesh=$root/$pqmesh
input=$root/data/3d/cube.poly
if [[ ${1:-} == -h || ${1:-} == --help ]]; then sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0; fi
if [[ ${1:-} == *.poly ]]; then input=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); shift; fi
sizes=("$@")
((${#sizes[@]})) || sizes=(0.0625 0.05 0.0416667 0.03125)
[[ -x $pqmesh ]] || { echo "matched_size_3d.sh: no pqmesh at $pqmesh (set PQMESH_BIN)" >&2; exit 2; }
command -v gmsh >/dev/null || { echo "matched_size_3d.sh: needs gmsh" >&2; exit 2; }
work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_matched3d.XXXXXX")
trap 'rm -rf "$work"' EXIT
edges=$root/bench/peers3d/edge_lengths.py

# stats MESH H: "count mean_edge/H min_dihedral" of an ASCII .msh 4.1.
stats() {
  local e d
  e=$(python3 "$edges" "$1" "$2") || { echo "n/a n/a n/a"; return; }
  d=$("$pqmesh" quality "$1" 2>/dev/null | awk '/^min dihedral/ { print $4; exit }')
  awk -v e="$e" -v d="${d:-n/a}" 'BEGIN { split(e, f, " "); printf "%s %s %s\n", f[2], f[6], d }'
}

hxt() {  # SIZE OUT.msh: HXT on 2 threads, ASCII .msh 4.1
  python3 "$root/bench/peers3d/poly3d.py" geo "$input" "$work/m.geo" "$1"
  gmsh -3 "$work/m.geo" -algo hxt -nt 2 -o "$2" -format msh41 >/dev/null 2>&1
}

printf '# %s, %s\n' "$(basename "$input")" "$(date -u +%Y-%m-%d)"
printf '%-10s | %9s %6s %7s | %9s %6s %7s | %9s %9s %7s | %6s\n' H pqmesh mean min_dih "hxt@H" mean min_dih "hxt size" tets min_dih ratio
for h in "${sizes[@]}"; do
  "$pqmesh" mesh "$input" -o "$work/pq.msh" --max-size "$h" --quiet || { echo "$h: pqmesh failed" >&2; continue; }
  read -r pn pm pd < <(stats "$work/pq.msh" "$h")
  hxt "$h" "$work/hx.msh"
  read -r hn hm hd < <(stats "$work/hx.msh" "$h")
  lc=$(awk -v h="$h" -v p="$pm" -v x="$hm" 'BEGIN { printf "%.6g", h * p / x }')
  hxt "$lc" "$work/hm.msh"
  read -r mn _ md < <(stats "$work/hm.msh" "$h")
  ratio=$(awk -v a="$pn" -v b="$mn" 'BEGIN { printf "%.2f", a / b }')
  printf '%-10s | %9s %6s %7s | %9s %6s %7s | %9s %9s %7s | %6s\n' "$h" "$pn" "$pm" "$pd" "$hn" "$hm" "$hd" "$lc" "$mn" "$md" "$ratio"
done
