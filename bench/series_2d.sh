#!/usr/bin/env bash
# Doubling series for the 2D quadtree mesher (time and memory should be
# linear in the output). Meshes the benchmark plate (bench/peers2d/poly2d.py plate:
# unit square with 5 circular holes) with --max-size halved at each step, so
# the triangle count roughly quadruples; prints triangles, wall seconds, CPU
# seconds (user + system: steadier than wall on a shared machine), peak MiB,
# triangles per CPU second, bytes per triangle, and the growth of CPU time and
# memory against the growth of the count (both near 1 when linear). Whole
# process: read, mesh, check, write binary .vtu, one thread. Not a test.
#   bench/series_2d.sh [STEPS] [REPEAT]   (default 5 steps from max-size 1/64, 1 run each)
# With REPEAT > 1 each step runs REPEAT times and the run with the least CPU
# time is reported (the machine may be shared: CPU time of the fastest run is
# the steadiest figure); user_s is that run's user time.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
pqmesh=${PQMESH_BIN:-$root/build/bin/pqmesh}
[[ -x $pqmesh ]] || { echo "series_2d: no pqmesh at $pqmesh (build first or set PQMESH_BIN)"; exit 1; }
steps=${1:-5}
repeat=${2:-1}
work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_series2d.XXXXXX")
trap 'rm -rf "$work"' EXIT
python3 "$root/bench/peers2d/poly2d.py" plate "$work/plate.poly"
printf '%-12s %10s %8s %8s %8s %9s %10s %7s %12s %12s\n' max-size triangles wall_s user_s cpu_s peak_MiB tri/cpu_s B/tri time_growth mem_growth
size=0.015625 prev_n="" prev_t="" prev_m=""
for ((i = 0; i < steps; i++)); do
  best=""
  for ((r = 0; r < repeat; r++)); do
    /usr/bin/time -f '%e %U %S %M' -o "$work/time.txt" "$pqmesh" mesh "$work/plate.poly" -o "$work/out.vtu" --max-size "$size" --quiet
    read -r w u s k <"$work/time.txt"
    c=$(awk -v u="$u" -v s="$s" 'BEGIN { printf "%.2f", u + s }')
    if [[ -z $best ]] || awk -v a="$c" -v b="$best" 'BEGIN { exit !(a < b) }'; then
      best=$c wall=$w user=$u kib=$k
    fi
  done
  cpu=$best
  n=$("$pqmesh" quality "$work/out.vtu" | awk '/^quality of/ { print $3; exit }')
  python3 - "$size" "$n" "$wall" "$user" "$cpu" "$kib" "${prev_n:-0}" "${prev_t:-0}" "${prev_m:-0}" <<'PY'
import sys
size, n, wall, user, cpu, kib, pn, pt, pm = sys.argv[1:]
n, wall, user, cpu, kib, pn, pt, pm = int(n), float(wall), float(user), float(cpu), int(kib), int(pn), float(pt), int(pm)
rate = n / cpu if cpu > 0 else float('nan')
growth = lambda now, before: '%.2f' % ((now / before) / (n / pn)) if pn and before else '-'
print('%-12s %10d %8.2f %8.2f %8.2f %9.1f %10.3g %7.0f %12s %12s' % (size, n, wall, user, cpu, kib / 1024, rate, kib * 1024 / n, growth(cpu, pt), growth(kib, pm)))
PY
  prev_n=$n prev_t=$cpu prev_m=$kib
  size=$(python3 -c "print($size / 2)")
done
