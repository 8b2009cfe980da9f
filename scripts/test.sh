#!/usr/bin/env bash
# Runs every check of libdbs: set-up and Release build (build/) and its test suite, the whole
# suite again under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/), the suite of a
# build without the optional Draco and Ceres (build-minimal/), and the outside-consumer check
# of the installed package (shared and static). Exits non-zero if
# anything fails; the summary at the end lists each step with its time.
#
# usage: scripts/test.sh
set -uo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"
jobs="$(nproc)"
suite_start=$SECONDS
summary=()
failed=0

# step NAME COMMAND...: runs one step, records its outcome and duration.
step() {
  local name="$1"
  shift
  local start=$SECONDS
  echo
  echo "==== $name"
  if "$@"; then
    summary+=("ok      $(printf '%4d' $((SECONDS - start))) s  $name")
  else
    summary+=("FAILED  $(printf '%4d' $((SECONDS - start))) s  $name")
    failed=1
  fi
}

run_ctest() {
  ctest --test-dir "$1" --output-on-failure -j"$jobs" --timeout 900
}

launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

build_asan() {
  # -O1 -g1: line numbers in sanitizer reports at a third of the compile time of -O2 -g.
  local flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1"
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_Fortran_FLAGS_RELWITHDEBINFO="-O1 -g1")
  cmake -S "$repo" -B "$repo/build-asan" "${flags[@]}" -DDBS_SANITIZE=ON \
    -DDBS_BUILD_EXAMPLES=ON -DDBS_BUILD_BENCH=OFF "${launcher[@]}" &&
    cmake --build "$repo/build-asan" -j"$jobs"
}

# Without the optional dependencies: .ply/.obj/.drc are refused as unsupported, the rest works.
build_minimal() {
  cmake -S "$repo" -B "$repo/build-minimal" -DCMAKE_BUILD_TYPE=Release -DDBS_WITH_DRACO=OFF -DDBS_WITH_CERES=OFF \
    -DDBS_BUILD_BENCH=OFF "${launcher[@]}" &&
    cmake --build "$repo/build-minimal" -j"$jobs"
}

step "set-up and Release build (scripts/setup.sh)" bash scripts/setup.sh
if [ "$failed" -ne 0 ]; then
  echo "test: the set-up failed; nothing else can run" >&2
  exit 1
fi
step "test suite, Release (build/)" run_ctest build
step "ASan+UBSan build (build-asan/)" build_asan
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
step "test suite, ASan+UBSan (build-asan/)" run_ctest build-asan
unset ASAN_OPTIONS UBSAN_OPTIONS
step "build without Draco and Ceres (build-minimal/)" build_minimal
step "test suite, without Draco and Ceres (build-minimal/)" run_ctest build-minimal
step "installed-package consumers (scripts/consumer_check.sh)" bash scripts/consumer_check.sh

echo
echo "==== summary"
printf '%s\n' "${summary[@]}"
echo "total   $(printf '%4d' $((SECONDS - suite_start))) s"
exit "$failed"
