#!/usr/bin/env bash
# The libFuzzer targets of libdbs (tests/fuzz), built with clang, ASan and UBSan into
# build-fuzz/.
#
# usage: scripts/fuzz.sh build             configure and build build-fuzz/ (the targets only)
#        scripts/fuzz.sh ci                every target deterministically: its corpus
#                                          (tests/fuzz/corpus/TARGET) replayed, then RUNS
#                                          more inputs (tests/fuzz/CMakeLists.txt) with
#                                          -seed=1; two targets at a time; a crash fails
#        scripts/fuzz.sh TARGET SECONDS    an exploratory run of one target (builds first);
#                                          new inputs go to build-fuzz/explore/TARGET,
#                                          crashes to build-fuzz/artifacts/ (tests/fuzz/README.md
#                                          says what to do with them)
set -uo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$repo/build-fuzz"
corpus="$repo/tests/fuzz/corpus"
# libFuzzer's own limits: a single allocation above 1 GB is a finding (a header's claim
# believed), and so is the whole process above 2 GB: its resident set grows over a run by
# what ASan keeps (the quarantine of freed blocks, the allocator's caches), to 560 MB after
# 4,000 Draco inputs, so 1 GB would judge the sanitizer rather than libdbs
limits=(-malloc_limit_mb=1024 -rss_limit_mb=2048 -timeout=60)
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

build_targets() {
  local launcher=()
  if command -v ccache >/dev/null 2>&1; then
    launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  if ! command -v clang >/dev/null 2>&1 || ! command -v clang++ >/dev/null 2>&1; then
    echo "fuzz: clang is not installed (scripts/setup.sh installs it)" >&2
    return 1
  fi
  # -O1 -g1: line numbers in reports; NDEBUG: no assertion of the header-only libraries in
  # every element access (their comparisons would be traced by the coverage, a third of the
  # time of a run). Ceres and the report are left out: the targets use neither.
  CC=clang CXX=clang++ cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DDBS_BUILD_FUZZ=ON -DDBS_BUILD_TESTS=OFF -DDBS_BUILD_EXAMPLES=OFF -DDBS_BUILD_BENCH=OFF \
    -DDBS_WITH_CERES=OFF -DDBS_WITH_REPORT=OFF "${launcher[@]}" || return 1
  if [ ! -f "$build/fuzz_targets.txt" ]; then
    echo "fuzz: the configuration has no fuzz targets (see the 'Fuzz targets' line above)" >&2
    return 1
  fi
  cmake --build "$build" -j"$(nproc)" --target dbs_fuzz_targets
}

# run_one NAME RUNS DICT: the corpus replayed and RUNS inputs more, quietly; its closing
# lines (or the whole report of a crash) printed.
run_one() {
  local name="$1" runs="$2" dict="$3"
  local scratch="$build/ci-corpus/$name" log="$build/ci-logs/$name.log"
  rm -rf "$scratch" && mkdir -p "$scratch" "$build/artifacts"
  local args=(-runs="$runs" -seed=1 "${limits[@]}" -artifact_prefix="$build/artifacts/$name-" -print_final_stats=1)
  if [ "$dict" != "-" ]; then args+=(-dict="$dict"); fi
  local start=$SECONDS status=0
  "$build/tests/fuzz/$name" "${args[@]}" "$scratch" "$corpus/$name" >"$log" 2>&1 || status=$?
  if [ "$status" -eq 0 ]; then
    local corpus_size
    corpus_size="$(find "$corpus/$name" -type f | wc -l)"
    echo "fuzz: $name ok: $corpus_size corpus inputs replayed + $runs runs, $((SECONDS - start)) s ($(grep -m1 -o 'cov: [0-9]*' <(grep DONE "$log") || echo 'cov: ?'))"
  else
    echo "fuzz: $name FAILED (exit $status) after $((SECONDS - start)) s; the report:"
    grep -v -E '^#[0-9]+\s+(NEW|REDUCE|pulse|INITED|RELOAD)' "$log" | tail -60
    echo "fuzz: the input is saved in $build/artifacts/$name-*; rerun it: $build/tests/fuzz/$name FILE"
  fi
  return "$status"
}

run_ci() {
  local list="$build/fuzz_targets.txt"
  if [ ! -f "$list" ]; then
    echo "fuzz: no $list: run scripts/fuzz.sh build first" >&2
    return 1
  fi
  mkdir -p "$build/ci-logs"
  local pids=() names=() failed=0 count=0 name runs dict
  local width
  width="$(nproc)"
  while read -r name runs dict; do
    [ -n "$name" ] || continue
    run_one "$name" "$runs" "$dict" &
    pids+=($!)
    names+=("$name")
    count=$((count + 1))
    # at most one target per core at a time
    if [ "${#pids[@]}" -ge "$width" ]; then
      wait "${pids[0]}" || failed=1
      pids=("${pids[@]:1}")
    fi
  done <"$list"
  for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
  echo "fuzz: $count targets run, $([ "$failed" -eq 0 ] && echo 'no crash' || echo 'CRASHES above')"
  return "$failed"
}

explore() {
  local name="$1" seconds="$2"
  build_targets || return 1
  local line
  line="$(grep "^$name " "$build/fuzz_targets.txt")" || {
    echo "fuzz: no target '$name'; these exist:" >&2
    cut -d' ' -f1 "$build/fuzz_targets.txt" >&2
    return 1
  }
  local dict
  dict="$(echo "$line" | cut -d' ' -f3)"
  local args=(-max_total_time="$seconds" "${limits[@]}" -artifact_prefix="$build/artifacts/$name-")
  if [ "$dict" != "-" ]; then args+=(-dict="$dict"); fi
  mkdir -p "$build/explore/$name" "$build/artifacts"
  "$build/tests/fuzz/$name" "${args[@]}" "$build/explore/$name" "$corpus/$name"
}

case "${1:-}" in
  build) build_targets ;;
  ci) run_ci ;;
  "" | -h | --help)
    sed -n '2,15p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
    exit 2
    ;;
  *)
    if [ $# -ne 2 ] || ! [[ "$2" =~ ^[0-9]+$ ]]; then
      echo "usage: scripts/fuzz.sh TARGET SECONDS (or build, ci)" >&2
      exit 2
    fi
    explore "$1" "$2"
    ;;
esac
