#!/usr/bin/env bash
# valgrind's memcheck on the programs of a build of libdbs: dbs-param on the example cloud
# shipped in data/ (with its boundary, the boundary detected, a .ply result and the report),
# dbs-boundary, the minimal C example and the Fortran example. Any memory error and any
# leak (definitely or indirectly lost) fails, with valgrind's report printed.
#
# usage: scripts/memcheck.sh [BUILD_DIR]     (default build/, as scripts/setup.sh makes it)
set -uo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-$repo/build}" && pwd)"
examples="$build/examples"
data="$repo/data"
out="$build/memcheck"
if ! command -v valgrind >/dev/null 2>&1; then
  echo "memcheck: valgrind is not installed (scripts/setup.sh installs it)" >&2
  exit 1
fi
rm -rf "$out" && mkdir -p "$out"

runs=0
failed=0
# check NAME EXPECTED PROGRAM ARGS...: one program under memcheck, which exits 0 (EXPECTED
# "ok") or with its own error status (EXPECTED "refuses": a bad input); memcheck's own
# status 99 always fails. Its output in $out/NAME.log.
check() {
  local name="$1" expected="$2"
  shift 2
  local start=$SECONDS status=0
  runs=$((runs + 1))
  valgrind --tool=memcheck --error-exitcode=99 --leak-check=full --show-leak-kinds=definite,indirect \
    --errors-for-leak-kinds=definite,indirect --track-origins=yes --log-file="$out/$name.valgrind" \
    "$@" >"$out/$name.log" 2>&1 || status=$?
  if [ "$status" -ne 99 ] && { { [ "$expected" = ok ] && [ "$status" -eq 0 ]; } || { [ "$expected" = refuses ] && [ "$status" -ne 0 ]; }; }; then
    echo "memcheck: $name ok, exit $status ($((SECONDS - start)) s)"
  else
    echo "memcheck: $name FAILED (exit $status, expected $expected; 99: memcheck found errors or leaks):"
    tail -20 "$out/$name.log"
    cat "$out/$name.valgrind"
    failed=1
  fi
}

check dbs-param ok "$examples/dbs-param" "$data/panel.xyz" "$data/panel_boundary.txt" -o "$out/panel.csv" --threads 2
check dbs-param-ply-report ok "$examples/dbs-param" "$data/panel.xyz" "$data/panel_boundary.txt" -o "$out/panel.ply" \
  --report "$out/report" --max-level 2
check dbs-param-auto-boundary ok "$examples/dbs-param" "$data/panel.xyz" --auto-boundary -o "$out/auto.csv" --max-level 1
check dbs-param-bad-input refuses "$examples/dbs-param" "$data/panel.xyz" "$data/missing_boundary.txt" -o "$out/never.csv"
check dbs-boundary ok "$examples/dbs-boundary" "$data/panel.xyz" -o "$out/boundary.txt"
check minimal ok "$examples/dbs_minimal"
if [ -x "$examples/dbs_fortran_example" ]; then
  check fortran ok "$examples/dbs_fortran_example" "$out/fortran.csv"
fi
echo "memcheck: $runs programs run, $([ "$failed" -eq 0 ] && echo 'no error or leak' || echo 'FAILURES above')"
exit "$failed"
