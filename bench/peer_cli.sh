# Sourced by the peer benchmarks (run_2d.sh, run_3d.sh): their common command
# line, scratch directory and table. Needs in the caller: root (the repo root).
#
# peer_setup DIM ARGS...: the start of both scripts: sets pqmesh (PQMESH_BIN,
# default build/bin/pqmesh, relative to the repo root), then peer_options and
# peer_work below.
peer_setup() {
  pqmesh=${PQMESH_BIN:-build/bin/pqmesh}
  [[ $pqmesh == /* ]] || pqmesh=$root/$pqmesh
  peer_options "$@"
  peer_work "$1"
}

# peer_options DIM ARGS...: parses the options both scripts document in their
# header (--target, --large-target, --no-large, --repeat, --tsv, --keep,
# inputs); sets target, large_target, large, repeat, tsv, keep and inputs
# (absolute paths; default data/DIMd/*.poly). --help prints the caller's
# header comment (line 2 up to `set -uo`) and exits 0; a bad option or a
# missing input exits 2 naming the script.
peer_options() {
  local dim=$1; shift
  local me; me=$(basename "$0")
  target="" large_target=1000000 large=1 repeat=1 tsv="" keep=0 inputs=()
  while (($#)); do
    case $1 in
      --target) target=$2; shift 2 ;;
      --large-target) large_target=$2; shift 2 ;;
      --no-large) large=0; shift ;;
      --repeat) repeat=$2; shift 2 ;;
      --tsv) tsv=$2; shift 2 ;;
      --keep) keep=1; shift ;;
      -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
      -*) echo "$me: unknown option $1" >&2; exit 2 ;;
      *) [[ -f $1 ]] || { echo "$me: no such input $1" >&2; exit 2; }
         inputs+=("$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"); shift ;;
    esac
  done
  ((${#inputs[@]})) || inputs=("$root"/data/"$dim"d/*.poly)
}

# peer_work DIM: sets work to a new scratch directory, removed on exit unless
# --keep (then its path is printed first).
peer_work() {
  work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_bench$1d.XXXXXX")
  if ((keep)); then echo "work directory: $work"; else trap 'rm -rf "$work"' EXIT; fi
}

# peer_table HEADER: prints HEADER and the rows (tab-separated, in the array
# rows) as aligned columns, and with --tsv also writes them to that file.
peer_table() {
  {
    echo "$1"
    printf '%s\n' "${rows[@]}"
  } | column -t -s $'\t'
  if [[ -n $tsv ]]; then
    { echo "$1"; printf '%s\n' "${rows[@]}"; } >"$tsv"
  fi
}
