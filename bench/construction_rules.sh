#!/usr/bin/env bash
# What the separating splits of thesis 4.1.7 steps 6 and 9 cost and buy:
# `pqmesh mesh` on each model twice, with the default octree (light first,
# separated near bad faces or wholly only when needed) and with
# --full-separation (the thesis's octree), both with --lfs-integral and
# --no-improve (the construction alone, before the improvement stage). Per run:
# the octree used, leaves, tetrahedra, tetrahedra per leaf (the box
# triangulation's cost), tetrahedra / I3 (I3 the integral of 1/lfs^3, a lower
# bound on the count up to a constant), worst aspect ratio, aspect * alpha
# against C = 5500, and meshing seconds; then the thesis / default count ratio.
# Not a test: it only measures; a run over --limit seconds shows "timeout".
#
#   bench/construction_rules.sh [--limit SECONDS] [--no-full] [MODEL ...]
#
#   --limit S   per run (default 300)
#   --no-full   skip the --full-separation runs
#   MODEL       default: data/3d/*.poly
#
# Environment: PQMESH_BIN (default build/bin/pqmesh, relative to the repo root).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${PQMESH_BIN:-build/bin/pqmesh}
[[ $bin == /* ]] || bin=$root/$bin
limit=300 full=1 models=()
while (($#)); do
  case $1 in
    --limit) limit=$2; shift 2 ;;
    --no-full) full=0; shift ;;
    -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "construction_rules.sh: unknown option $1" >&2; exit 2 ;;
    *) [[ -f $1 ]] || { echo "construction_rules.sh: no such model $1" >&2; exit 2; }
       models+=("$1"); shift ;;
  esac
done
((${#models[@]})) || models=("$root"/data/3d/*.poly)
[[ -x $bin ]] || { echo "construction_rules.sh: $bin not found (bash scripts/build.sh)" >&2; exit 2; }
work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_rules.XXXXXX")
trap 'rm -rf "$work"' EXIT

# run MODEL [OPTIONS...]: prints the tab-separated columns of one run.
run() {
  local model=$1; shift
  local log=$work/log
  if ! timeout "$limit" "$bin" mesh "$model" -o "$work/m.vtu" --lfs-integral --no-improve "$@" >"$log" 2>&1; then
    printf 'timeout\t-\t-\t-\t-\t-\t-\t-'
    return
  fi
  awk -v C=5500 '
    /^octree / { o = $2 == "separated" ? "thesis" : $2
                 for (i = 1; i < NF; ++i) if ($i == "near") o = "near " $(i + 1) " faces" }
    /^leaves / { l = $2; sub(":", "", l) }
    /^mesh / { t = $2 }
    /^quality / { q = $5 }
    /^size / { for (i = 1; i <= NF; ++i) if ($i == "I3" && $(i + 1) == "=" && $(i - 1) == "/") r = $(i + 2) }
    /^time / { for (i = 1; i <= NF; ++i) if ($i == "mesh") { s = $(i + 1); sub(",", "", s) } }
    END { printf "%s\t%s\t%s\t%.1f\t%s\t%s\t%s", o, l, t, t / l, r, q, s }' "$log"
}

header="model\toctree\tleaves\ttets\ttets/leaf\ttets/I3\tmax aspect\tmesh s"
((full)) && header+="\tthesis leaves\tthesis tets\tthesis tets/leaf\tthesis tets/I3\tthesis max aspect\tthesis s\tthesis/default"
rows=()
for m in "${models[@]}"; do
  echo "$(basename "$m")..." >&2
  row="$(basename "$m")\t$(run "$m")"
  if ((full)); then
    thesis=$(run "$m" --full-separation | cut -f2-)
    d_tets=$(printf "$row" | cut -f4) t_tets=$(printf '%s' "$thesis" | cut -f2)
    ratio=$(awk -v a="$d_tets" -v b="$t_tets" 'BEGIN { if (a + 0 > 0 && b + 0 > 0) printf "%.1f", b / a; else printf "-" }')
    row+="\t$thesis\t$ratio"
  fi
  rows+=("$row")
done
{ printf '%b\n' "$header"; printf '%b\n' "${rows[@]}"; } | column -t -s $'\t'
