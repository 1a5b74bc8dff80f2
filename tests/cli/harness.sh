# Shared by the *_test.sh scripts here (sourced, not a test itself): a scratch
# directory removed on exit, pass/fail counters and the checks below. A script
# ends with `finish NAME`, whose exit status is the verdict.
set -u
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

ok() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect CODE DESCRIPTION -- COMMAND...: runs COMMAND, checks the exit code,
# leaves stdout in $work/out and stderr in $work/err.
expect() {
  local want=$1 what=$2
  shift 3
  "$@" > "$work/out" 2> "$work/err"
  local got=$?
  if [[ $got -eq $want ]]; then ok; else fail "$what: exit $got, expected $want; stderr: $(head -c 400 "$work/err")"; fi
}
contains() {  # contains FILE PATTERN DESCRIPTION
  if grep -qE -- "$2" "$1"; then ok; else fail "$3: '$2' not in $(head -c 600 "$1")"; fi
}
lacks() {  # lacks FILE PATTERN DESCRIPTION: no line of FILE matches PATTERN
  if grep -qE -- "$2" "$1"; then fail "$3: '$2' found in $(head -c 600 "$1")"; else ok; fi
}
absent() {  # absent PATH DESCRIPTION
  if [[ -e $1 ]]; then fail "$2: $1 exists"; else ok; fi
}
empty() {  # empty FILE DESCRIPTION
  if [[ -s $1 ]]; then fail "$2: $(head -c 300 "$1")"; else ok; fi
}
finish() {  # finish NAME: prints the counts; succeeds only if nothing failed
  echo "$1: $passed passed, $failed failed"
  [[ $failed -eq 0 ]]
}
