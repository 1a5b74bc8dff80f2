#!/usr/bin/env bash
# Real closed surfaces from Debian packages, meshed by `pqmesh mesh` (default
# sizes) and by Debian's tetgen (-pq1.414) side by side, every run under a time
# and a memory limit: the CAD and scanned models of CGAL's example data
# (libcgal-demo: data/meshes/*.off inside /usr/share/doc/libcgal-dev/data.tar.gz,
# extracted into the work directory) and Open CASCADE's STL samples (occt-misc:
# /usr/share/opencascade/data/stl/*.stl). Not a test: it measures, prints a
# table and never fails because a tool, a package or a model is missing
# (scripts/install-deps.sh --bench installs both packages).
#
#   bench/real_parts.sh [--limit SECONDS] [--mem GIB] [--tsv FILE] [--keep]
#                       [--no-tetgen] [MODEL ...]
#
#   --limit SECONDS  wall-clock limit of each run (default 60; timeout(1))
#   --mem GIB        address-space limit of each run in GiB (default 4; ulimit -v)
#   --tsv FILE       also write the table as tab-separated values
#   --keep           keep the work directory (extracted models, meshes, logs)
#   --no-tetgen      pqmesh only
#   MODEL ...        only these: a file pqmesh mesh reads (.off, .stl, .obj,
#                    .mesh, .poly, .smesh), or the name of a packaged model with
#                    or without its extension (pinion_small.off, sh1; head is
#                    both head.off and head.stl). Default: every CGAL .off and
#                    every occt .stl except TR12J_OCC64K.stl (TR12J_OCC again,
#                    tessellated finer). Models run sorted by file name.
#
# Runs: pqmesh mesh MODEL -o m.vtu (its summary gives tets, max aspect, min
# dihedral and octree), and tetgen -pq1.414 -Q on a copy of MODEL (a binary
# STL, which Debian's tetgen 1.5 cannot read, is first converted to ASCII STL
# with perl, outside the timing; a format tetgen does not read gets n/a).
# Each under /usr/bin/time -f '%e %M', timeout -k 5 SECONDS and ulimit -v:
# wall s and peak MiB (resident) cover the whole process (read, mesh, check
# for pqmesh, write: pqmesh binary .vtu, tetgen its ASCII .node/.ele/.face/
# .edge/.smesh); the memory limit is on address space, so a run that dies of
# it shows a peak below the limit.
#
# Columns: faces = faces in the OFF header or triangles of the STL; pqmesh and
# tetgen = the outcome: ok (exit 0), refused (pqmesh exit 2: the input is
# rejected with a named error, the first line of which, shortened, is the
# reason column), timeout, mem (std::bad_alloc or another out-of-memory
# message, or killed by SIGKILL before the limit), fail:RC (any other exit
# status; pqmesh's reason = the first line of its stderr), fail:no-mesh (tetgen
# exited 0 but wrote no .ele, as on an open surface), missing (tool absent),
# n/a (tetgen cannot read the format); tets, max aspect, min dih (degrees) and
# octree (light or separated) from pqmesh's summary; tg tets from the .ele
# header; pq/tg = pqmesh tets / tetgen tets. A column without a value shows
# n/a. The last line counts the outcomes per tool. Progress goes to stderr.
#
# Environment: PQMESH_BIN (default build/bin/pqmesh, relative to the repo root).
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
me=$(basename "$0")
cgal_tar=/usr/share/doc/libcgal-dev/data.tar.gz
occt_dir=/usr/share/opencascade/data/stl

pqmesh=${PQMESH_BIN:-build/bin/pqmesh}
[[ $pqmesh == /* ]] || pqmesh=$root/$pqmesh

limit=60 mem_gib=4 tsv="" keep=0 use_tetgen=1 args=()
while (($#)); do
  case $1 in
    --limit|--mem|--tsv)
      (($# >= 2)) || { echo "$me: $1 wants a value" >&2; exit 2; }
      case $1 in --limit) limit=$2 ;; --mem) mem_gib=$2 ;; --tsv) tsv=$2 ;; esac
      shift 2 ;;
    --keep) keep=1; shift ;;
    --no-tetgen) use_tetgen=0; shift ;;
    -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    --) shift; args+=("$@"); break ;;
    -*) echo "$me: unknown option $1" >&2; exit 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
positive() { [[ $1 =~ ^[0-9]+([.][0-9]+)?$ ]] && awk -v x="$1" 'BEGIN { exit !(x > 0) }'; }
if ! positive "$limit"; then echo "$me: --limit wants a positive number of seconds, got '$limit'" >&2; exit 2; fi
if ! positive "$mem_gib"; then echo "$me: --mem wants a positive number of GiB, got '$mem_gib'" >&2; exit 2; fi
mem_kib=$(awk -v g="$mem_gib" 'BEGIN { printf "%d", g * 1048576 }')
if ! (ulimit -v "$mem_kib") 2>/dev/null; then
  echo "note: cannot set ulimit -v $mem_kib here; runs have no memory limit" >&2
  mem_kib=""
fi

have_time=0; [[ -x /usr/bin/time ]] && have_time=1
have_pqmesh=0; [[ -x $pqmesh ]] && have_pqmesh=1
have_tetgen=0; ((use_tetgen)) && command -v tetgen >/dev/null && have_tetgen=1
have_perl=0; command -v perl >/dev/null && have_perl=1
((have_pqmesh)) || echo "note: $pqmesh not found; the pqmesh columns show missing (cmake --build build)" >&2
((use_tetgen && !have_tetgen)) && echo "note: tetgen not found; the tetgen columns show missing" >&2
((have_time)) || echo "note: /usr/bin/time not found (package time); peak MiB is n/a, wall s from date" >&2

work=$(mktemp -d "${TMPDIR:-/tmp}/pqmesh_real_parts.XXXXXX") || { echo "$me: mktemp failed" >&2; exit 1; }
if ((keep)); then echo "work directory: $work"; else trap 'rm -rf "$work"' EXIT; fi
trap 'exit 130' INT
trap 'exit 143' TERM

# packaged: lists every packaged model (CGAL's OFF files extracted into
# $work/models once, occt's STL files in place), one absolute path a line.
extracted=0
packaged() {
  if ((!extracted)); then
    extracted=1
    mkdir -p "$work/models"
    if [[ -f $cgal_tar ]]; then
      tar xzf "$cgal_tar" -C "$work/models" --wildcards 'data/meshes/*.off' 2>/dev/null ||
        echo "note: could not extract the OFF models from $cgal_tar" >&2
    else
      echo "note: $cgal_tar not found (package libcgal-demo); no CGAL models" >&2
    fi
    [[ -d $occt_dir ]] || echo "note: $occt_dir not found (package occt-misc); no occt models" >&2
  fi
  local f
  for f in "$work"/models/data/meshes/*.off "$occt_dir"/*.stl; do
    [[ -f $f ]] && printf '%s\n' "$f"
  done
}

# The models, sorted by file name (then path), without repeats.
list=()
if ((${#args[@]} == 0)); then
  while IFS= read -r f; do
    [[ $(basename "$f") == TR12J_OCC64K.stl ]] || list+=("$f")
  done < <(packaged)
else
  for a in "${args[@]}"; do
    if [[ -f $a ]]; then
      list+=("$(cd "$(dirname "$a")" && pwd)/$(basename "$a")")
      continue
    fi
    found=0
    while IFS= read -r f; do
      b=$(basename "$f")
      if [[ $b == "$a" || ${b%.*} == "$a" ]]; then list+=("$f"); found=1; fi
    done < <(packaged)
    ((found)) || echo "note: model $a not found (neither a file nor a packaged model); skipped" >&2
  done
fi
models=()
while IFS=$'\t' read -r _ f; do models+=("$f"); done < <(
  for f in "${list[@]}"; do printf '%s\t%s\n' "$(basename "$f")" "$f"; done | LC_ALL=C sort -u)
((${#models[@]})) || echo "note: no models to run" >&2

# faces FILE: faces in an OFF header, triangles of an ASCII or binary STL, else n/a.
faces() {
  local f=$1 n=""
  case ${f,,} in
    *.off)
      n=$(awk '{ sub(/#.*/, "") } NF == 0 { next }
               !key { key = 1; if ($1 ~ /OFF$/) { if (NF == 1) next; $1 = ""; $0 = $0 } }
               { print $2; exit }' "$f" 2>/dev/null) ;;
    *.stl)
      if is_binary_stl "$f"; then n=$stl_count; else n=$(grep -ci 'facet[[:space:]]*normal' "$f"); fi ;;
  esac
  [[ $n =~ ^[0-9]+$ ]] && echo "$n" || echo n/a
}

# is_binary_stl FILE: true when FILE's size is 84 + 50 n, n the count at byte
# 80 (how pqmesh's reader recognises one); sets stl_count.
is_binary_stl() {
  local size
  stl_count=""
  size=$(stat -c %s "$1" 2>/dev/null) || return 1
  ((size >= 84)) || return 1
  stl_count=$(od -An -tu4 -j80 -N4 --endian=little "$1" | tr -d ' ')
  [[ $stl_count =~ ^[0-9]+$ ]] && ((size == 84 + 50 * stl_count))
}

# stl_to_ascii IN OUT: a binary STL as ASCII STL (float32 values exactly, %.9g).
stl_to_ascii() {
  perl -e '
    open(my $in, "<:raw", $ARGV[0]) or die "$ARGV[0]: $!\n";
    read($in, my $head, 84) == 84 or die "short header\n";
    my $n = unpack("V", substr($head, 80, 4));
    print "solid m\n";
    for (1 .. $n) {
      read($in, my $rec, 50) == 50 or die "short record\n";
      my @v = unpack("f<12", $rec);
      printf " facet normal %.9g %.9g %.9g\n  outer loop\n", @v[0 .. 2];
      printf "   vertex %.9g %.9g %.9g\n", @v[3 * $_ .. 3 * $_ + 2] for 1 .. 3;
      print "  endloop\n endfacet\n";
    }
    print "endsolid m\n";' "$1" >"$2"
}

# limited DIR OUT ERR CMD...: runs CMD in DIR under the limits (timeout -k 5
# $limit, ulimit -v $mem_kib, no core files), stdout to OUT, stderr to ERR;
# sets rc, wall (s) and mib (peak resident MiB, n/a without GNU time).
limited() {
  local dir=$1 out=$2 err=$3; shift 3
  local t0 t1 kib="" w=""
  rc=0 wall=n/a mib=n/a
  rm -f "$dir/time.txt"
  t0=$(date +%s.%N)
  (
    cd "$dir" || exit 125
    ulimit -c 0
    [[ -z $mem_kib ]] || ulimit -v "$mem_kib"
    ((have_time)) && exec /usr/bin/time -f '%e %M' -o "$dir/time.txt" timeout -k 5 "$limit" "$@"
    exec timeout -k 5 "$limit" "$@"
  ) >"$out" 2>"$err" || rc=$?
  t1=$(date +%s.%N)
  if ((have_time)) && [[ -s $dir/time.txt ]]; then
    read -r w kib < <(tail -n 1 "$dir/time.txt")  # after "Command exited with ..." lines
  fi
  [[ $w =~ ^[0-9.]+$ ]] && wall=$w || wall=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
  [[ $kib =~ ^[0-9]+$ ]] && mib=$(awk -v k="$kib" 'BEGIN { printf "%.1f", k / 1024 }')
  return 0
}

# classify TOOL OUT ERR MODEL: sets outcome from rc and wall, and why (pqmesh
# refused or failed: the first line of ERR, MODEL's directory dropped, shortened).
classify() {
  local tool=$1 out=$2 err=$3 model=$4
  why=""
  if ((rc == 0)); then outcome=ok
  elif ((rc == 124)); then outcome=timeout
  elif [[ $tool == pqmesh ]] && ((rc == 2)); then outcome=refused
  elif grep -qiE 'bad_alloc|out of memory|cannot allocate memory|memory exhausted' "$out" "$err" 2>/dev/null; then
    outcome=mem
  elif ((rc == 137)); then  # SIGKILL: timeout's -k after the limit, else the kernel's OOM killer
    if awk -v w="$wall" -v l="$limit" 'BEGIN { exit !(w + 0 >= l + 0) }'; then outcome=timeout; else outcome=mem; fi
  else outcome=fail:$rc
  fi
  if [[ $tool == pqmesh && ($outcome == refused || $outcome == fail:*) ]]; then
    why=$(awk -v path="$model" -v name="${model##*/}" '
            NF { s = $0; sub(/^pqmesh mesh: /, "", s); gsub(/\t/, " ", s)
                 while ((i = index(s, path)) > 0) s = substr(s, 1, i - 1) name substr(s, i + length(path))
                 if (length(s) > 70) s = substr(s, 1, 67) "..."; print s; exit }' "$err")
  fi
}

declare -A tallies=()
tally() {  # TOOL OUTCOME: one more OUTCOME (fail:RC counts as fail) for TOOL
  local k="$1 ${2%%:*}"
  tallies[$k]=$((${tallies[$k]:-0} + 1))
}

run_pqmesh() {  # dir model; sets pq_* and reason
  local dir=$1 model=$2 sum=$1/pqmesh.out
  pq_out=missing pq_s=n/a pq_mib=n/a pq_tets=n/a pq_aspect=n/a pq_dih=n/a pq_octree=n/a reason=""
  ((have_pqmesh)) || { tally pqmesh missing; return; }
  limited "$dir" "$sum" "$dir/pqmesh.err" "$pqmesh" mesh "$model" -o "$dir/m.vtu"
  classify pqmesh "$sum" "$dir/pqmesh.err" "$model"
  reason=$why pq_out=$outcome pq_s=$wall pq_mib=$mib
  tally pqmesh "$outcome"
  [[ $outcome == ok ]] || return 0
  local v
  v=$(awk '$1 == "mesh" && $3 == "tetrahedra," { print $2; exit }' "$sum")
  [[ $v =~ ^[0-9]+$ ]] && pq_tets=$v
  v=$(awk '$1 == "quality" && $3 == "aspect" { print $5; exit }' "$sum")
  [[ -n $v ]] && pq_aspect=$v
  v=$(awk '$1 == "quality" { for (i = 2; i < NF; ++i) if ($i == "min" && $(i - 1) == "dihedral") { print $(i + 1); exit } }' "$sum")
  [[ -n $v ]] && pq_dih=$v
  v=$(awk '$1 == "octree" { print $2; exit }' "$sum")
  [[ -n $v ]] && pq_octree=$v
}

run_tetgen() {  # dir model; sets tg_*
  local dir=$1/tetgen model=$2 ext
  tg_out=missing tg_s=n/a tg_mib=n/a tg_tets=n/a
  ((use_tetgen)) || return 0
  ((have_tetgen)) || { tally tetgen missing; return; }
  ext=${model##*.}; ext=${ext,,}
  mkdir -p "$dir"
  case $ext in
    off|ply|mesh|vtk) cp "$model" "$dir/m.$ext" ;;
    poly|smesh)  # with the .node file it may name
      cp "$model" "$dir/m.$ext"
      [[ -f ${model%.*}.node ]] && cp "${model%.*}.node" "$dir/m.node" ;;
    stl)
      if ! is_binary_stl "$model"; then cp "$model" "$dir/m.stl"
      elif ((have_perl)) && stl_to_ascii "$model" "$dir/m.stl" 2>"$dir/convert.err"; then :
      else tg_out=n/a; tally tetgen n/a; return
      fi ;;
    *) tg_out=n/a; tally tetgen n/a; return ;;
  esac
  limited "$dir" "$1/tetgen.out" "$1/tetgen.err" tetgen -pq1.414 -Q "m.$ext"
  classify tetgen "$1/tetgen.out" "$1/tetgen.err" "$model"
  [[ $outcome == ok && ! -s $dir/m.1.ele ]] && outcome=fail:no-mesh  # exit 0, no tetrahedra written
  tg_out=$outcome tg_s=$wall tg_mib=$mib
  tally tetgen "$outcome"
  [[ $outcome == ok ]] || return 0
  local v
  v=$(awk 'NR == 1 { print $1; exit }' "$dir/m.1.ele")
  [[ $v =~ ^[0-9]+$ ]] && tg_tets=$v
}

rows=()
i=0
for model in "${models[@]}"; do
  i=$((i + 1))
  name=$(basename "$model")
  echo "[$i/${#models[@]}] $name" >&2
  dir=$work/runs/$(printf '%03d' "$i")
  mkdir -p "$dir"
  n_faces=$(faces "$model")
  run_pqmesh "$dir" "$model"
  run_tetgen "$dir" "$model"
  ratio=n/a
  [[ $pq_tets =~ ^[0-9]+$ && $tg_tets =~ ^[0-9]+$ ]] && ((tg_tets > 0)) &&
    ratio=$(awk -v a="$pq_tets" -v b="$tg_tets" 'BEGIN { printf "%.2f", a / b }')
  if ((use_tetgen)); then
    rows+=("$name	$n_faces	$pq_out	$pq_s	$pq_mib	$pq_tets	$pq_aspect	$pq_dih	$pq_octree	$tg_out	$tg_s	$tg_mib	$tg_tets	$ratio	$reason")
  else
    rows+=("$name	$n_faces	$pq_out	$pq_s	$pq_mib	$pq_tets	$pq_aspect	$pq_dih	$pq_octree	$reason")
  fi
  printf '  %s\n' "${rows[-1]}" >&2  # the row as soon as it is known (stderr)
  ((keep)) || rm -rf "$dir"  # meshes of large models add up
done

header="model	faces	pqmesh	s	MiB	tets	max aspect	min dih	octree"
((use_tetgen)) && header+="	tetgen	tg s	tg MiB	tg tets	pq/tg"
header+="	reason"
# The table as aligned columns (as bench/peer_cli.sh's peer_table), and with --tsv as is.
{ echo "$header"; ((${#rows[@]} == 0)) || printf '%s\n' "${rows[@]}"; } | column -t -s $'\t'
if [[ -n $tsv ]]; then
  { echo "$header"; ((${#rows[@]} == 0)) || printf '%s\n' "${rows[@]}"; } >"$tsv" ||
    echo "note: could not write $tsv" >&2
fi

counts() {  # TOOL OUTCOME...: "outcome N, ..." (missing and n/a only when non-zero)
  local tool=$1 k n out=""; shift
  for k in "$@"; do
    n=${tallies[$tool $k]:-0}
    [[ ($k == missing || $k == n/a) && $n == 0 ]] && continue
    out+="${out:+, }$k $n"
  done
  echo "$out"
}
line="${#models[@]} model$( ((${#models[@]} == 1)) || echo s); pqmesh: $(counts pqmesh ok refused timeout mem fail missing)"
((use_tetgen)) && line+="; tetgen: $(counts tetgen ok timeout mem fail missing n/a)"
echo "$line"
exit 0
