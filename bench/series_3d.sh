#!/usr/bin/env bash
# Doubling series for the 3D jobs: `pqmesh mesh` (the default) or
# `pqmesh octree` (--octree) on one model with
# --max-size H_k = H0 / 2^k. Box sides are powers of two, so finer steps of H
# change nothing between rows; each row multiplies the element count by 4 to
# 8 (4 while boundary boxes dominate). Whole process: read, build, check,
# write binary .vtu (mesh runs with --quiet). Prints the count (tetrahedra or
# leaves), wall and CPU (user + system) seconds, peak RSS (/usr/bin/time -v),
# elements per CPU second and bytes per element. Linear cost shows as flat
# last two columns. Not a test: it only measures.
#
#   bench/series_3d.sh [--octree] [--steps N] [--h0 H] [INPUT.poly]
#
#   --octree    measure `pqmesh octree` (leaves) instead of `pqmesh mesh`
#   --steps N   rows (default 3)
#   --h0 H      the first --max-size (default: 1/32 of the root cube side)
#   INPUT       default data/3d/l_block.poly
#
# Environment: PQMESH_BIN (default build/bin/pqmesh, relative to the repo root).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${PQMESH_BIN:-$root/build/bin/pqmesh}
[[ $bin = /* ]] || bin=$root/$bin
job=mesh
steps=3
h0=
input=$root/data/3d/l_block.poly
while (($#)); do
  case $1 in
    --octree) job=octree; shift ;;
    --steps) steps=$2; shift 2 ;;
    --h0) h0=$2; shift 2 ;;
    -h|--help) sed -n 2,19p "$0"; exit 0 ;;
    *) input=$1; shift ;;
  esac
done
[[ -x $bin ]] || { echo "no pqmesh at $bin (set PQMESH_BIN)" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "needs /usr/bin/time (GNU time) for peak RSS" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The root cube side (the bounding cube rounded up to a power of two), read
# from the summary of a default run: "grid ...; root side S, ..." for mesh,
# "depth ... (root side S)" for octree.
root_side() {
  "$bin" "$job" "$input" -o "$work/probe.vtu" > "$work/probe.txt"
  if [[ $job = mesh ]]; then
    awk '/^grid/ { for (i = 1; i < NF; ++i) if ($i == "side") { gsub(/,/, "", $(i + 1)); print $(i + 1) } }' "$work/probe.txt"
  else
    awk '/^depth/ { gsub(/\)/, "", $NF); print $NF }' "$work/probe.txt"
  fi
}

# The element count of one run, outside the timing: the .vtu header's
# NumberOfCells for mesh, the summary's "leaves N" for octree.
element_count() {
  if [[ $job = mesh ]]; then
    head -c 4096 "$work/m.vtu" | tr ' ' '\n' | awk -F'"' '/^NumberOfCells=/ { print $2; exit }'
  else
    awk '/^leaves/ { print $2 }' "$work/out.txt"
  fi
}

[[ -n $h0 ]] || h0=$(awk -v s="$(root_side)" 'BEGIN { print s / 32 }')
unit=tets one=tet
quiet=(--quiet)
[[ $job = mesh ]] || { unit=leaves; one=leaf; quiet=(); }

printf '# %s, pqmesh %s --max-size H0 / 2^k, H0 = %s\n' "$(basename "$input")" "$job" "$h0"
printf '%3s %12s %10s %8s %8s %10s %10s %8s\n' k max_size "$unit" wall_s cpu_s peak_MiB "$unit/s" "B/$one"
for ((k = 0; k < steps; ++k)); do
  h=$(awk -v h0="$h0" -v k="$k" 'BEGIN { printf "%.17g", h0 / 2 ^ k }')
  /usr/bin/time -v "$bin" "$job" "$input" -o "$work/m.vtu" --max-size "$h" "${quiet[@]}" > "$work/out.txt" 2> "$work/time.txt"
  n=$(element_count)
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s}' "$work/time.txt")
  user=$(awk -F': ' '/User time/ {print $2}' "$work/time.txt")
  sys=$(awk -F': ' '/System time/ {print $2}' "$work/time.txt")
  rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.txt")
  awk -v k="$k" -v h="$h" -v n="$n" -v w="$wall" -v u="$user" -v s="$sys" -v r="$rss" 'BEGIN {
    c = u + s; printf "%3d %12.6g %10d %8.2f %8.2f %10.1f %10.0f %8.0f\n", k, h, n, w, c, r / 1024, n / (c > 0 ? c : 1e-9), r * 1024 / n }'
done
echo "# cpu_s = user + system CPU seconds of the whole run (robust on a shared machine); $unit/s = $unit / cpu_s; B/$one = peak RSS / $unit"
