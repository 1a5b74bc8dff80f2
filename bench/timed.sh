# Sourced by the peer benchmarks (run_2d.sh, run_3d.sh): one timing helper.
# Needs in the caller: repeat (runs per call), have_time (1 when GNU time is
# at /usr/bin/time), work (a scratch directory).
#
# timed LOG CMD...: runs CMD $repeat times; sets rc, wall (fastest run) and
# kib (peak RSS of that run, "n/a" without GNU time); LOG keeps the fastest
# run's own output.
timed() {
  local log=$1; shift
  local r w k best="" bestk="n/a"
  rc=0
  for ((r = 0; r < repeat; r++)); do
    if ((have_time)); then
      /usr/bin/time -f '%e %M' -o "$work/time.txt" "$@" >"$log" 2>&1 || rc=$?
      read -r w k <"$work/time.txt"
    else
      local t0 t1
      t0=$(date +%s.%N); "$@" >"$log" 2>&1 || rc=$?; t1=$(date +%s.%N)
      w=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }'); k="n/a"
    fi
    ((rc == 0)) || return "$rc"
    if [[ -z $best ]] || awk -v a="$w" -v b="$best" 'BEGIN { exit !(a < b) }'; then
      best=$w bestk=$k; cp "$log" "$log.best"
    fi
  done
  mv "$log.best" "$log"
  wall=$best kib=$bestk
}
