#!/usr/bin/env bash
# The direction check of lib/'s rooms (lib/CMakeLists.txt):
#
#   core < surface < projection < method < io < validation < report   (< capi, include/dbs.h)
#
# Fails, naming the file, the line and the include, when
#   1. a file of lib/ROOM includes a header of a higher room, of capi/ or dbs.h, or includes
#      by a path ("../method/x.hpp", "method/x.hpp") instead of by the header's own name;
#   2. a file name of lib/ stands in two rooms, or a header name in lib/ and capi/ (an
#      include by name would then depend on the include path's order);
#   3. something puts lib/ itself on an include path: a CMake file of the source tree names
#      it, or, given a build directory, a compile line of that build carries -I.../lib.
# The link structure makes such an include fail to compile too; this says which and where.
#
# usage: scripts/check_rooms.sh [--root SOURCE_DIR] [BUILD_DIR]
#        scripts/check_rooms.sh --self-test   (proves that each check fails on a broken copy)
set -uo pipefail

rooms=(core surface projection method io validation report)
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# check ROOT [BUILD_DIR]: prints every violation; returns 1 when there is any.
check() {
  local root="$1" build="${2:-}" failed=0
  local -A rank_of_header=() room_of_name=()
  local rank room file name

  # every header's room, and each file name once (2)
  for rank in "${!rooms[@]}"; do
    room="${rooms[$rank]}"
    [ -d "$root/lib/$room" ] || continue
    for file in "$root/lib/$room"/*; do
      [ -f "$file" ] || continue
      name="$(basename "$file")"
      if [ -n "${room_of_name[$name]:-}" ]; then
        echo "check_rooms: lib/$room/$name: the name is also lib/${room_of_name[$name]}/$name (file names are unique across rooms)"
        failed=1
      fi
      room_of_name[$name]="$room"
      case "$name" in *.hpp | *.h) rank_of_header[$name]="$rank" ;; esac
    done
  done
  local capi_rank="${#rooms[@]}"
  for file in "$root"/capi/*.hpp "$root"/capi/*.h "$root"/include/*.h; do
    [ -f "$file" ] || continue
    name="$(basename "$file")"
    if [ -n "${room_of_name[$name]:-}" ]; then
      echo "check_rooms: ${file#"$root"/}: the header name is also lib/${room_of_name[$name]}/$name"
      failed=1
    fi
    rank_of_header[$name]="$capi_rank"
  done

  # the direction of every include (1)
  local line number header target
  for rank in "${!rooms[@]}"; do
    room="${rooms[$rank]}"
    for file in "$root/lib/$room"/*.hpp "$root/lib/$room"/*.cpp; do
      [ -f "$file" ] || continue
      while IFS=: read -r number line; do
        [[ "$line" =~ \"([^\"]+)\" ]] || continue
        header="${BASH_REMATCH[1]}"
        if [[ "$header" == */* ]]; then
          echo "check_rooms: lib/$room/$(basename "$file"):$number: #include \"$header\": include a room's header by its name, not by a path"
          failed=1
          continue
        fi
        target="${rank_of_header[$header]:-}"
        [ -n "$target" ] || continue  # not ours (a system or third-party header in quotes)
        if [ "$target" -gt "$rank" ]; then
          local where="capi"
          [ "$target" -lt "$capi_rank" ] && where="lib/${rooms[$target]}"
          echo "check_rooms: lib/$room/$(basename "$file"):$number: #include \"$header\" reaches up into $where; lib/$room may include only its own room and the rooms below it"
          failed=1
        fi
      done < <(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file")
    done
  done

  # lib/ itself on an include path (3): in the CMake files ...
  local pattern='(PROJECT_SOURCE_DIR|CMAKE_SOURCE_DIR|dbs_SOURCE_DIR|CMAKE_CURRENT_SOURCE_DIR[}]/\.\.)[}]?/lib/?([[:space:]")>;]|$)'
  while IFS= read -r file; do
    while IFS=: read -r number line; do
      echo "check_rooms: ${file#"$root"/}:$number: puts lib/ itself on an include path: ${line#"${line%%[![:space:]]*}"}"
      failed=1
    done < <(grep -nE "$pattern" "$file")
    if [ "$file" = "$root/lib/CMakeLists.txt" ]; then
      while IFS=: read -r number line; do
        echo "check_rooms: lib/CMakeLists.txt:$number: puts lib/ itself on an include path: ${line#"${line%%[![:space:]]*}"}"
        failed=1
      done < <(grep -nE 'include_directories.*CMAKE_CURRENT_SOURCE_DIR[}]/?([[:space:]")>;]|$)' "$file")
    fi
  done < <(find "$root" -path "$root/build*" -prune -o \( -name CMakeLists.txt -o -name '*.cmake' \) -type f -print)
  # ... and in the compile lines of a build (Makefile and Ninja generators)
  if [ -n "$build" ]; then
    local lib_dir
    lib_dir="$(cd "$root/lib" && pwd)"
    while IFS= read -r file; do
      if grep -qE -- "-(I|isystem )[[:space:]]*$lib_dir/?([[:space:]]|$)" "$file"; then
        echo "check_rooms: ${file#"$build"/}: a compile line of the build has -I$lib_dir"
        failed=1
      fi
    done < <(find "$build" \( -name flags.make -o -name build.ninja \) -type f)
  fi
  return "$failed"
}

# self_test: a copy of lib/, capi/, include/ and the CMake files, broken one way at a time;
# each check must fail, and the intact copy must pass.
self_test() {
  local tmp
  tmp="$(mktemp -d)"
  trap 'rm -rf "$tmp"' RETURN
  local failed=0
  copy() {
    rm -rf "$tmp/src"
    mkdir -p "$tmp/src"
    cp -r "$here/lib" "$here/capi" "$here/include" "$here/CMakeLists.txt" "$tmp/src/"
  }
  # expect NAME REGEX: the broken copy must fail with a line matching REGEX
  expect() {
    local output
    if output="$(check "$tmp/src")"; then
      echo "check_rooms --self-test: $1: passed although it is broken"
      failed=1
    elif ! grep -qE "$2" <<<"$output"; then
      echo "check_rooms --self-test: $1: failed without the expected line /$2/:"
      echo "$output"
      failed=1
    else
      echo "check_rooms --self-test: $1: fails as it should: $(grep -E "$2" <<<"$output" | head -1)"
    fi
  }
  copy
  if ! check "$tmp/src" >/dev/null; then
    echo "check_rooms --self-test: the intact copy fails"
    failed=1
  fi
  local victim
  victim="$(ls "$tmp/src/lib/core"/*.cpp | head -1)"
  sed -i '1a #include "parameterize.hpp"' "$victim"
  expect "core includes method" "lib/core/$(basename "$victim"):2: #include \"parameterize.hpp\" reaches up into lib/method"
  copy
  sed -i '1a #include "firewall.hpp"' "$tmp/src/lib/method/evolve.cpp"
  expect "method includes capi" 'lib/method/evolve.cpp:2: #include "firewall.hpp" reaches up into capi'
  copy
  sed -i '1a #include "../io/text_io.hpp"' "$tmp/src/lib/surface/boundary.cpp"
  expect "an include by path" 'lib/surface/boundary.cpp:2: #include "../io/text_io.hpp": include a room.s header by its name'
  copy
  cp "$tmp/src/lib/core/error.hpp" "$tmp/src/lib/io/error.hpp"
  expect "a repeated file name" 'lib/io/error.hpp: the name is also lib/core/error.hpp'
  copy
  echo 'target_include_directories(dbs_core PUBLIC ${PROJECT_SOURCE_DIR}/lib)' >>"$tmp/src/lib/CMakeLists.txt"
  expect "lib/ on an include path" 'lib/CMakeLists.txt:[0-9]+: puts lib/ itself on an include path'
  return "$failed"
}

root="$here"
build=""
while [ $# -gt 0 ]; do
  case "$1" in
    --self-test) self_test; exit $? ;;
    --root) root="$(cd "$2" && pwd)"; shift 2 ;;
    -h | --help) sed -n '2,16p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) build="$(cd "$1" && pwd)"; shift ;;
  esac
done
if check "$root" "$build"; then
  echo "check_rooms: lib/ includes only downward (${rooms[*]}), file names unique, lib/ on no include path"
else
  exit 1
fi
