#!/usr/bin/env bash
# Runs every check of libdbs: set-up (scripts/setup.sh: packages, library, dbs-param and the
# examples), the rest of the Release build (tests and benchmark, build/) and its whole test
# suite; the suite without the heavy shape tests (ctest label `heavy`) under AddressSanitizer
# + UndefinedBehaviorSanitizer (build-asan/); the libFuzzer targets (tests/fuzz, build-fuzz/:
# corpus replayed, then a fixed number of runs with a fixed seed); the thread tests (label
# `threads`) under ThreadSanitizer (build-tsan/); valgrind's memcheck of dbs-param,
# dbs-boundary and the examples; the suite of a build without the optional Draco, Ceres,
# validation and report (build-minimal/); and the outside-consumer check of the installed
# package (shared and static, full and minimal). Exits non-zero if anything fails; the
# summary at the end lists each step with its time (and the number of tests it ran).
#
# usage: scripts/test.sh
set -uo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"
jobs="$(nproc)"
suite_start=$SECONDS
summary=()
failed=0

# step NAME COMMAND...: runs one step, records its outcome and duration (and what the step
# put in step_note: how many tests it ran). Its output is also kept in build-ci-logs/, so that
# the end of the run can repeat why a step failed: a CI log is often read from its end only.
step_note=""
step_logs="$repo/build-ci-logs"
rm -rf "$step_logs" && mkdir -p "$step_logs"
failed_steps=()
step() {
  local name="$1"
  shift
  local start=$SECONDS
  local log
  log="$step_logs/step-$(printf '%02d' "${#summary[@]}").log"
  step_note=""
  echo
  echo "==== $name"
  # The output goes through tee by a process substitution, not a pipe, so that the step runs
  # in this shell and can set step_note; tee is waited for, so the log is whole before the
  # next step prints (or why_failed reads it).
  local out tee_pid status
  exec {out}> >(tee "$log")
  tee_pid=$!
  "$@" >&"$out" 2>&1
  status=$?
  exec {out}>&-
  wait "$tee_pid"
  if [ "$status" -eq 0 ]; then
    summary+=("ok      $(printf '%4d' $((SECONDS - start))) s  $name${step_note:+: $step_note}")
  else
    summary+=("FAILED  $(printf '%4d' $((SECONDS - start))) s  $name${step_note:+: $step_note}")
    failed_steps+=("$name"$'\t'"$log")
    failed=1
  fi
}

# why_failed: for each failed step, the last lines of its output that name a failure.
why_failed() {
  local entry name log
  for entry in "${failed_steps[@]}"; do
    name="${entry%%$'\t'*}"
    log="${entry#*$'\t'}"
    echo "---- why \"$name\" failed (the last lines of its output naming a failure; all of it above and in $log)"
    grep -E 'FAILED|\*\*\*Failed|\[  ERROR   \]|\[   LINE   \]|error:|==[0-9]+==ERROR|SUMMARY: |deadly signal|broke its promise|out-of-memory|ALARM: working|Timeout|LeakSanitizer' "$log" | tail -15
  done
}

# run_ctest DIR [CTEST ARGS...]: the suite of DIR, its closing lines shown; the number of
# tests it ran goes to the summary.
run_ctest() {
  local dir="$1"
  shift
  local log="$dir/ctest-ci.log"
  ctest --test-dir "$dir" --output-on-failure -j"$jobs" --timeout 900 "$@" 2>&1 | tee "$log"
  local status=${PIPESTATUS[0]}
  local ran
  ran="$(grep -o 'tests failed out of [0-9]*' "$log" | grep -o '[0-9]*$')"
  step_note="${ran:-0} tests${*:+ ($*)}"
  return "$status"
}

launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

# The rest of build/ after scripts/setup.sh: the same configuration with the tests and the
# benchmark, so only those are compiled on top of what the set-up built.
build_release() {
  # DBS_WITH_CERES=ON: a missing Ceres fails here instead of leaving the solver out.
  cmake -S "$repo" -B "$repo/build" -DCMAKE_BUILD_TYPE=Release -DDBS_BUILD_EXAMPLES=ON -DDBS_BUILD_TESTS=ON \
    -DDBS_BUILD_BENCH=ON -DDBS_WITH_CERES=ON "${launcher[@]}" &&
    cmake --build "$repo/build" -j"$jobs"
}

build_asan() {
  # -O1 -g1: line numbers in sanitizer reports at a third of the compile time of -O2 -g.
  local flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1"
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_Fortran_FLAGS_RELWITHDEBINFO="-O1 -g1")
  cmake -S "$repo" -B "$repo/build-asan" "${flags[@]}" -DDBS_SANITIZE=ON \
    -DDBS_BUILD_EXAMPLES=ON -DDBS_BUILD_BENCH=OFF "${launcher[@]}" &&
    cmake --build "$repo/build-asan" -j"$jobs"
}

# The minimal build: no Draco, Ceres, validation or report. .ply/.obj/.drc and every validation
# and report function are refused as unsupported, the rest works; libdbs links neither Qhull
# nor libpng (the linked_libraries test).
build_minimal() {
  cmake -S "$repo" -B "$repo/build-minimal" -DCMAKE_BUILD_TYPE=Release -DDBS_WITH_DRACO=OFF -DDBS_WITH_CERES=OFF \
    -DDBS_WITH_VALIDATION=OFF -DDBS_WITH_REPORT=OFF -DDBS_BUILD_BENCH=OFF "${launcher[@]}" &&
    cmake --build "$repo/build-minimal" -j"$jobs"
}

# run_counted LOG PATTERN COMMAND...: runs the command with its output also in LOG; the
# step's note is the count its closing line gives (PATTERN, e.g. "targets run").
run_counted() {
  local log="$1" pattern="$2"
  shift 2
  "$@" 2>&1 | tee "$log"
  local status=${PIPESTATUS[0]}
  step_note="$(grep -o "[0-9]* $pattern" "$log")"
  return "$status"
}

# Every fuzz target: its corpus replayed, then its fixed number of runs (scripts/fuzz.sh).
run_fuzz() { run_counted "$repo/build-fuzz/fuzz-ci.log" "targets run" bash scripts/fuzz.sh ci; }

# valgrind's memcheck of the programs of build/ (scripts/memcheck.sh).
run_memcheck() { run_counted "$repo/build/memcheck.log" "programs run" bash scripts/memcheck.sh build; }

# ThreadSanitizer on the tests where threads of the host and of libdbs meet (ctest label
# `threads`): nothing else is built. Without the optional components: their outside
# libraries are not instrumented, and the thread tests use none of them.
build_tsan() {
  local flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1"
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1")
  cmake -S "$repo" -B "$repo/build-tsan" "${flags[@]}" -DDBS_SANITIZE_THREAD=ON -DDBS_BUILD_TESTS=ON \
    -DDBS_BUILD_EXAMPLES=OFF -DDBS_BUILD_BENCH=OFF -DDBS_WITH_DRACO=OFF -DDBS_WITH_CERES=OFF \
    -DDBS_WITH_VALIDATION=OFF -DDBS_WITH_REPORT=OFF "${launcher[@]}" &&
    cmake --build "$repo/build-tsan" -j"$jobs"
}

step "set-up: packages, library, dbs-param, examples (scripts/setup.sh)" bash scripts/setup.sh
if [ "$failed" -ne 0 ]; then
  echo "test: the set-up failed; nothing else can run" >&2
  why_failed
  exit 1
fi
step "Release build: tests and benchmark (build/)" build_release
step "test suite, Release (build/)" run_ctest build
step "ASan+UBSan build (build-asan/)" build_asan
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# the heavy shape tests ran in the Release suite; under the sanitizers every other test
step "test suite without the heavy tests, ASan+UBSan (build-asan/)" run_ctest build-asan -LE heavy
step "fuzz targets: libFuzzer, clang, ASan+UBSan (build-fuzz/, scripts/fuzz.sh build)" bash scripts/fuzz.sh build
step "fuzz runs: corpus + fixed runs, -seed=1 (scripts/fuzz.sh ci)" run_fuzz
unset ASAN_OPTIONS UBSAN_OPTIONS
step "ThreadSanitizer build: the thread tests only (build-tsan/)" build_tsan
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
step "thread tests, ThreadSanitizer (build-tsan/)" run_ctest build-tsan -L threads
unset TSAN_OPTIONS
step "valgrind memcheck: dbs-param, dbs-boundary, examples (scripts/memcheck.sh)" run_memcheck
step "minimal build: no Draco, Ceres, validation, report (build-minimal/)" build_minimal
step "test suite, minimal build (build-minimal/)" run_ctest build-minimal
step "installed-package consumers (scripts/consumer_check.sh)" bash scripts/consumer_check.sh

echo
echo "==== summary"
printf '%s\n' "${summary[@]}"
echo "total   $(printf '%4d' $((SECONDS - suite_start))) s"
why_failed
exit "$failed"
