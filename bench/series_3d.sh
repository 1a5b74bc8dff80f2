#!/usr/bin/env bash
# Doubling series for the 3D mesher (issue 5 item 9): `pqmesh mesh` on one
# model with --max-size H_k = H0 / 2^k (halving; box sides are powers of two,
# so finer steps of H change nothing between them), which multiplies the
# tetrahedron count by 4 to 8 from row to row (4 while boundary boxes
# dominate). Whole process as in bench/run_3d.sh: read, mesh, check, write
# binary .vtu (with --quiet: no summary). Prints tetrahedra, wall and CPU
# (user + system) seconds, peak RSS (/usr/bin/time -v), tetrahedra per CPU
# second and bytes per tetrahedron. Linear cost shows as flat tets/s and
# bytes/tet columns. Not a test: it only measures.
#
#   bench/series_3d.sh [--steps N] [--h0 H] [INPUT.poly]
#
#   --steps N   rows (default 3)
#   --h0 H      the first --max-size (default: 1/32 of the root cube side)
#   INPUT       default data/3d/l_block.poly
#
# Environment: PQMESH_BIN (default build/bin/pqmesh, relative to the repo root).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${PQMESH_BIN:-$root/build/bin/pqmesh}
[[ $bin = /* ]] || bin=$root/$bin
steps=3
h0=
input=$root/data/3d/l_block.poly
while (($#)); do
  case $1 in
    --steps) steps=$2; shift 2 ;;
    --h0) h0=$2; shift 2 ;;
    -h|--help) sed -n 2,17p "$0"; exit 0 ;;
    *) input=$1; shift ;;
  esac
done
[[ -x $bin ]] || { echo "no pqmesh at $bin (set PQMESH_BIN)" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "needs /usr/bin/time (GNU time) for peak RSS" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [[ -z $h0 ]]; then
  # The root cube side from the summary of a default run ("grid ...; root
  # side S, depth D"): the bounding cube rounded up to a power of two.
  "$bin" mesh "$input" -o "$work/probe.vtu" > "$work/probe.txt"
  root_side=$(awk '/^grid/ { for (i = 1; i < NF; ++i) if ($i == "side") { gsub(/,/, "", $(i + 1)); print $(i + 1) } }' "$work/probe.txt")
  h0=$(awk -v s="$root_side" 'BEGIN { print s / 32 }')
fi

printf '# %s, pqmesh mesh --max-size H0 / 2^k, H0 = %s\n' "$(basename "$input")" "$h0"
printf '%3s %12s %10s %8s %8s %10s %10s %8s\n' k max_size tets wall_s cpu_s peak_MiB tets/s B/tet
for ((k = 0; k < steps; ++k)); do
  h=$(awk -v h0="$h0" -v k="$k" 'BEGIN { printf "%.17g", h0 / 2 ^ k }')
  /usr/bin/time -v "$bin" mesh "$input" -o "$work/m.vtu" --max-size "$h" --quiet > /dev/null 2> "$work/time.txt"
  # The count from the .vtu header (NumberOfCells), outside the timing.
  tets=$(head -c 4096 "$work/m.vtu" | tr ' ' '\n' | awk -F'"' '/^NumberOfCells=/ { print $2; exit }')
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s}' "$work/time.txt")
  user=$(awk -F': ' '/User time/ {print $2}' "$work/time.txt")
  sys=$(awk -F': ' '/System time/ {print $2}' "$work/time.txt")
  rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.txt")
  awk -v k="$k" -v h="$h" -v n="$tets" -v w="$wall" -v u="$user" -v s="$sys" -v r="$rss" 'BEGIN {
    c = u + s; printf "%3d %12.6g %10d %8.2f %8.2f %10.1f %10.0f %8.0f\n", k, h, n, w, c, r / 1024, n / (c > 0 ? c : 1e-9), r * 1024 / n }'
done
echo "# cpu_s = user + system CPU seconds of the whole run (robust on a shared machine); tets/s = tetrahedra / cpu_s; B/tet = peak RSS / tetrahedra"
