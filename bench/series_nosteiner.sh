#!/usr/bin/env bash
# Doubling series for pqmesh mesh --no-boundary-steiner (thesis §5.5.2: time
# O(m log m) in the output size m). Regular n-gons, n = 125 * 2^i: the
# pipeline's mesh size m roughly doubles with n (R's quadtree mesh dominates).
# Prints n, m (the construction's triangles, before the quality pass), the library's stage times from the
# summary (R = shrink + quad_mesh, Q-to-R, the quality post-pass, verify), total library seconds,
# process CPU seconds, and CPU time / (m log m) growth against the previous row
# (near 1 when O(m log m); CPU, not wall: wall is noisy on a shared machine). Not a test.
#   bench/series_nosteiner.sh [STEPS]    (default 5: n = 125 .. 2000)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
pqmesh=${PQMESH_BIN:-$root/build/bin/pqmesh}
[[ -x $pqmesh ]] || { echo "series_nosteiner: no pqmesh at $pqmesh (build first or set PQMESH_BIN)"; exit 1; }
steps=${1:-5}
work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_nsseries.XXXXXX")
trap 'rm -rf "$work"' EXIT
printf '%7s %10s %8s %8s %8s %8s %9s %8s %14s\n' n m R_s QtoR_s pass_s verify_s total_s cpu_s 't/(mlogm)_growth'
prev=""
for ((i = 0; i < steps; i++)); do
  n=$((125 << i))
  python3 "$root/bench/nosteiner_polys.py" ngon "$n" "$work/p.poly"
  /usr/bin/time -f '%U %S' -o "$work/time.txt" "$pqmesh" mesh "$work/p.poly" -o "$work/out.vtu" --no-boundary-steiner >"$work/log"
  read -r u s <"$work/time.txt"
  line=$(awk -v n="$n" -v cpu="$(awk -v u="$u" -v s="$s" 'BEGIN{print u+s}')" '
    /^post-pass/ { m = $6 }  # the construction'"'"'s size (before the quality pass)
    /^time/     { gsub(",", ""); gsub(";", ""); for (i = 1; i <= NF; ++i) { if ($i == "R") r = $(i+1); if ($i == "Q-to-R") qr = $(i+1); if ($i == "pass") ps = $(i+1); if ($i == "verify") v = $(i+1); if ($i == "total") t = $(i+1) } }
    END { print n, m, r, qr, ps, v, t, cpu }' "$work/log")
  read -r n m r qr ps v t cpu <<<"$line"
  growth=$(awk -v m="$m" -v t="$cpu" -v p="$prev" 'BEGIN { if (p == "") { print "-"; exit } split(p, a, " "); printf "%.2f", (t / (m * log(m))) / (a[2] / (a[1] * log(a[1]))) }')
  printf '%7s %10s %8s %8s %8s %8s %9s %8s %14s\n' "$n" "$m" "$r" "$qr" "$ps" "$v" "$t" "$cpu" "$growth"
  prev="$m $cpu"
done
