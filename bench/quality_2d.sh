#!/usr/bin/env bash
# Quality meshes side by side: every tool at its own angle setting and no size
# bound, on data/2d/*.poly and the generated shapes of bench/peers2d/shapes2d.py.
# Prints triangles and smallest angle per input and tool, and pqmesh's count
# over the reference peer's (Triangle when the machine has it, else CGAL).
# Not a test: a missing tool prints "missing".
#
#   bench/quality_2d.sh [--min-angle A] [--tsv FILE] [INPUT.poly ...]
#
#   --min-angle A  pqmesh --min-angle A, Triangle -pqA, CGAL shape bound
#                  sin^2(A) (default: each tool's default: pqmesh 20,
#                  Triangle -pq (20), CGAL 20.7)
#   --tsv FILE     also write the table as tab-separated values
#
# pqmesh's columns: the output, and the construction before the improvement
# stage (`--no-improve`). Environment: PQMESH_BIN (default build/bin/pqmesh),
# CXX for the CGAL program (built into build-bench/peers2d, as run_2d.sh does).
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
pqmesh=${PQMESH_BIN:-build/bin/pqmesh}
[[ $pqmesh == /* ]] || pqmesh=$root/$pqmesh
angle="" tsv="" inputs=()
while (($#)); do
  case $1 in
    --min-angle) angle=$2; shift 2 ;;
    --tsv) tsv=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "quality_2d.sh: unknown option $1" >&2; exit 2 ;;
    *) [[ -f $1 ]] || { echo "quality_2d.sh: no such input $1" >&2; exit 2; }
       inputs+=("$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"); shift ;;
  esac
done
work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_quality2d.XXXXXX")
trap 'rm -rf "$work"' EXIT
if ((${#inputs[@]} == 0)); then
  inputs=("$root"/data/2d/*.poly)
  for shape in $(python3 "$root/bench/peers2d/shapes2d.py" --list); do
    python3 "$root/bench/peers2d/shapes2d.py" "$shape" "$work/$shape.poly"
    inputs+=("$work/$shape.poly")
  done
fi

cgal=$root/build-bench/peers2d/cgal_mesh2
if [[ ! -x $cgal || $cgal -ot $root/bench/peers2d/cgal_mesh2.cpp ]] && [[ -d /usr/include/CGAL ]]; then
  mkdir -p "$(dirname "$cgal")"
  "${CXX:-g++}" -std=c++17 -O2 -DNDEBUG -o "$cgal" "$root/bench/peers2d/cgal_mesh2.cpp" -lgmp -lmpfr 2>"$work/cgal_build.log" ||
    echo "CGAL program failed to build; CGAL columns say missing" >&2
fi
have_triangle=0; command -v triangle >/dev/null && have_triangle=1

# pqmesh_run POLY [OPTIONS...]: "triangles min_angle" from the summary.
pqmesh_run() {
  local poly=$1; shift
  "$pqmesh" mesh "$poly" -o "$work/out.vtu" ${angle:+--min-angle "$angle"} "$@" >"$work/pq.log" 2>&1 || { echo "failed -"; return; }
  awk '/^mesh / { n = $2 } /^angles / { a = $3 } END { print n, a }' "$work/pq.log"
}
triangle_run() {
  ((have_triangle)) || { echo "missing -"; return; }
  cp "$1" "$work/t.poly"
  triangle -pq"${angle}" -V -N -E -P "$work/t.poly" >"$work/tri.log" 2>&1 || { echo "failed -"; return; }
  awk '/Mesh triangles:/ { n = $3 } /Smallest angle:/ { a = $3 } END { print n, a }' "$work/tri.log"
}
cgal_run() {
  [[ -x $cgal ]] || { echo "missing -"; return; }
  "$cgal" "$1" 0 ${angle:+"$angle"} >"$work/cgal.log" 2>&1 || { echo "failed -"; return; }
  awk '{ for (i = 1; i < NF; i++) { if ($i == "triangles") n = $(i + 1); if ($i == "min_angle") a = $(i + 1) } } END { print n, a }' "$work/cgal.log"
}

header=$'input\tpqmesh\tmin angle\tbuilt\tbuilt min\ttriangle\tmin angle\tcgal\tmin angle\tpqmesh / ref'
rows=()
for poly in "${inputs[@]}"; do
  name=$(basename "$poly" .poly)
  read -r pq pqa <<<"$(pqmesh_run "$poly")"
  read -r built builta <<<"$(pqmesh_run "$poly" --no-improve)"
  read -r tri tria <<<"$(triangle_run "$poly")"
  read -r cg cga <<<"$(cgal_run "$poly")"
  ref=$tri; [[ $ref =~ ^[0-9]+$ ]] || ref=$cg
  ratio=$(awk -v a="$pq" -v b="$ref" 'BEGIN { if (a ~ /^[0-9]+$/ && b ~ /^[0-9]+$/ && b > 0) printf "%.2f", a / b; else print "-" }')
  rows+=("$name"$'\t'"$pq"$'\t'"$pqa"$'\t'"$built"$'\t'"$builta"$'\t'"$tri"$'\t'"$tria"$'\t'"$cg"$'\t'"$cga"$'\t'"$ratio")
done
reference="CGAL (no Triangle on this machine)"
((have_triangle)) && reference=Triangle
echo "angle setting: ${angle:-the default of each tool}; reference: $reference"
{ echo "$header"; printf '%s\n' "${rows[@]}"; } | column -t -s $'\t'
[[ -z $tsv ]] || { echo "$header"; printf '%s\n' "${rows[@]}"; } >"$tsv"
exit 0
