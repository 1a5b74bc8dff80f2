#!/usr/bin/env bash
# Benchmark of pqmesh mesh --no-boundary-steiner (thesis ch. 5): the
# data/2d corpus, a regular 1000-gon and a regular 10,000-gon (10,000 boundary
# vertices). Per input: wall and CPU seconds of the whole process (read,
# triangulate, internal verify, CDT baseline, check, write .vtu), peak MiB, the
# pipeline's path and size (triangles m), its min angle, g(P), the CDT's min
# angle, and what was written (the pipeline's mesh or, where larger-angled,
# the CDT: path cdt-better). Not a test.
#   bench/run_nosteiner.sh            (PQMESH_BIN overrides the binary)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
pqmesh=${PQMESH_BIN:-$root/build/bin/pqmesh}
[[ -x $pqmesh ]] || { echo "run_nosteiner: no pqmesh at $pqmesh (build first or set PQMESH_BIN)"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_nosteiner.XXXXXX")
trap 'rm -rf "$work"' EXIT
python3 "$root/bench/nosteiner_polys.py" ngon 1000 "$work/ngon1000.poly"
python3 "$root/bench/nosteiner_polys.py" ngon 10000 "$work/ngon10000.poly"
printf '%-14s %8s %7s %8s %-7s %10s %12s %10s %10s %-10s\n' input wall_s cpu_s peak_MiB path triangles pipe_min_deg g_deg cdt_deg output
for f in "$root"/data/2d/*.poly "$work/ngon1000.poly" "$work/ngon10000.poly"; do
  /usr/bin/time -f '%e %U %S %M' -o "$work/time.txt" "$pqmesh" mesh "$f" -o "$work/out.vtu" --no-boundary-steiner >"$work/log"
  read -r w u s k <"$work/time.txt"
  awk -v name="$(basename "$f" .poly)" -v w="$w" -v c="$(awk -v u="$u" -v s="$s" 'BEGIN{print u+s}')" -v k="$k" '
    /^bound g/    { g = $5 }
    /^pipeline/   { path = $2; sub(":", "", path); pmin = $4; tri = $10 }
    /^cdt /       { for (i = 1; i <= NF; ++i) if ($i == "min") cdt = $(i + 1) }
    /^path /      { out = $2 }
    END { printf "%-14s %8s %7.2f %8.1f %-7s %10s %12s %10s %10s %-10s\n", name, w, c, k / 1024, path, tri, pmin, g, cdt, out }' "$work/log"
done
