#!/usr/bin/env bash
# Benchmark of pqmesh mesh --no-boundary-steiner (thesis ch. 5): the
# data/2d corpus, the generated shapes of bench/peers2d/shapes2d.py (random200,
# comb16, plate64, tiny_feature), a regular 1000-gon and a regular 10,000-gon
# (10,000 boundary vertices). Per input: wall and CPU seconds of the whole
# process (read, triangulate, internal verify, CDT baseline, refined
# candidates, check, write .vtu), peak MiB, the pipeline's path and size
# (triangles m), its min angle, the best refined candidate's min angle, the
# CDT's min angle, g(P), the output's min angle, the upper bound (min(60, C g, alpha, segment, fan))
# and output / upper bound, and what was written (path: the pipeline's mesh,
# refined, or cdt-better). Not a test.
#   bench/run_nosteiner.sh            (PQMESH_BIN overrides the binary)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
pqmesh=${PQMESH_BIN:-$root/build/bin/pqmesh}
[[ -x $pqmesh ]] || { echo "run_nosteiner: no pqmesh at $pqmesh (build first or set PQMESH_BIN)"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_nosteiner.XXXXXX")
trap 'rm -rf "$work"' EXIT
python3 "$root/bench/nosteiner_polys.py" ngon 1000 "$work/ngon1000.poly"
python3 "$root/bench/nosteiner_polys.py" ngon 10000 "$work/ngon10000.poly"
shapes=(random200 comb16 plate64 tiny_feature)
for s in "${shapes[@]}"; do python3 "$root/bench/peers2d/shapes2d.py" "$s" "$work/$s.poly"; done
printf '%-14s %8s %7s %8s %-7s %10s %12s %11s %8s %8s %8s %9s %9s %-11s\n' input wall_s cpu_s peak_MiB path triangles pipe_min_deg refined_deg cdt_deg g_deg out_deg bound_deg out/bound output
for f in "$root"/data/2d/*.poly "${shapes[@]/#/$work/}" "$work/ngon1000.poly" "$work/ngon10000.poly"; do
  [[ $f == *.poly ]] || f=$f.poly
  /usr/bin/time -f '%e %U %S %M' -o "$work/time.txt" "$pqmesh" mesh "$f" -o "$work/out.vtu" --no-boundary-steiner >"$work/log"
  read -r w u s k <"$work/time.txt"
  awk -v name="$(basename "$f" .poly)" -v w="$w" -v c="$(awk -v u="$u" -v s="$s" 'BEGIN{print u+s}')" -v k="$k" '
    /^bound g/    { g = $5 }
    /^angles/     { omin = $3; for (i = 1; i <= NF; ++i) { if ($i == "bound" && $(i + 1) == "=") ratio = $(i + 2); if ($i == "(upper") { ub = $(i + 2) } } }
    /^pipeline/   { path = $2; sub(":", "", path); pmin = $4; tri = $10 }
    /^refined /   { rmin = "-"; for (i = 1; i <= NF; ++i) if ($i == "min") rmin = $(i + 1) }
    /^cdt /       { for (i = 1; i <= NF; ++i) if ($i == "min") cdt = $(i + 1) }
    /^path /      { out = $2 }
    END { printf "%-14s %8s %7.2f %8.1f %-7s %10s %12s %11s %8s %8s %8s %9s %9s %-11s\n", name, w, c, k / 1024, path, tri, pmin, rmin, cdt, g, omin, ub, ratio, out }' "$work/log"
done
