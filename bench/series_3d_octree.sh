#!/usr/bin/env bash
# Doubling series for the 3D octree (issue 4 item 7): `pqmesh octree` on one
# model with --max-size H_k = H0 / 2^k (halving; box sides are powers of two,
# so finer steps of H change nothing between them), which multiplies the leaf
# count by 4 to 8 from row to row. Prints leaves, wall and user seconds, peak RSS
# (/usr/bin/time -v), leaves per second and bytes per leaf. Linear cost shows
# as flat leaves/s and bytes/leaf columns. Not a test: it only measures.
#
#   bench/series_3d_octree.sh [--steps N] [--h0 H] [INPUT.poly]
#
#   --steps N   rows (default 4)
#   --h0 H      the first --max-size (default: 1/32 of the root cube side)
#   INPUT       default data/3d/l_block.poly
#
# Environment: PQMESH_BIN (default build/bin/pqmesh, relative to the repo root).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${PQMESH_BIN:-$root/build/bin/pqmesh}
[[ $bin = /* ]] || bin=$root/$bin
steps=4
h0=
input=$root/data/3d/l_block.poly
while (($#)); do
  case $1 in
    --steps) steps=$2; shift 2 ;;
    --h0) h0=$2; shift 2 ;;
    -h|--help) sed -n 2,16p "$0"; exit 0 ;;
    *) input=$1; shift ;;
  esac
done
[[ -x $bin ]] || { echo "no pqmesh at $bin (set PQMESH_BIN)" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "needs /usr/bin/time (GNU time) for peak RSS" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [[ -z $h0 ]]; then
  # The largest extent of the input, from the octree summary's root side (the
  # root cube is the bounding cube rounded up to a power of two).
  "$bin" octree "$input" -o "$work/probe.vtu" > "$work/probe.txt"
  root_side=$(awk '/^depth/ {gsub(/\)/, "", $NF); print $NF}' "$work/probe.txt")
  h0=$(awk -v s="$root_side" 'BEGIN { print s / 32 }')
fi

printf '# %s, --max-size H0 / 2^k, H0 = %s\n' "$(basename "$input")" "$h0"
printf '%3s %12s %10s %8s %8s %10s %12s %10s\n' k max_size leaves wall_s user_s peak_MiB leaves/s bytes/leaf
for ((k = 0; k < steps; ++k)); do
  h=$(awk -v h0="$h0" -v k="$k" 'BEGIN { printf "%.17g", h0 / 2 ^ k }')
  /usr/bin/time -v "$bin" octree "$input" -o "$work/boxes.vtu" --max-size "$h" > "$work/out.txt" 2> "$work/time.txt"
  leaves=$(awk '/^leaves/ {print $2}' "$work/out.txt")
  build=$(awk '/^time/ {print $2}' "$work/out.txt")
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s}' "$work/time.txt")
  user=$(awk -F': ' '/User time/ {print $2}' "$work/time.txt")
  rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.txt")
  awk -v k="$k" -v h="$h" -v n="$leaves" -v w="$wall" -v u="$user" -v b="$build" -v r="$rss" 'BEGIN {
    printf "%3d %12.6g %10d %8.2f %8.2f %10.1f %12.0f %10.0f\n", k, h, n, w, u, r / 1024, n / (u > 0 ? u : 1e-9), r * 1024 / n }'
done
echo "# leaves/s = leaves / user CPU seconds of the whole run (reading, octree, writing .vtu; robust on a shared machine); bytes/leaf = peak RSS / leaves"
