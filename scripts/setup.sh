#!/usr/bin/env bash
# Installs the Debian packages libdbs needs (only when some are missing) and builds what the
# README's first command uses into build/ (Release): libdbs, dbs-param and the examples, no
# tests and no benchmark (scripts/test.sh builds those into the same build/).
#
# usage: scripts/setup.sh            (from anywhere; safe to run again)
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$repo/build"

packages=(
  build-essential cmake pkg-config ccache gfortran python3 binutils
  libeigen3-dev libnanoflann-dev libceres-dev libdraco-dev
  libcmocka-dev libqhull-dev libpng-dev locales
  python3-numpy python3-pytest python3-setuptools python3-venv python3-pip
  clang libclang-rt-dev valgrind
)
# clang and libclang-rt-dev (libFuzzer and clang's sanitizer runtimes of Debian's default
# clang): the fuzz targets (scripts/fuzz.sh); valgrind: the memcheck of the examples
# (scripts/memcheck.sh).

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
if dpkg -s "${packages[@]}" >/dev/null 2>&1; then
  echo "setup: all ${#packages[@]} Debian packages are installed"
else
  echo "setup: installing ${packages[*]}"
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get update
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${packages[@]}"
fi
# A locale with a decimal comma, for the test that libdbs writes numbers the same under it
# (tests/capi/test_locale.c); only this one is compiled.
if ! locale -a 2>/dev/null | grep -qix 'de_DE.utf8'; then
  echo "setup: compiling the de_DE.UTF-8 locale"
  $sudo localedef -i de_DE -f UTF-8 de_DE.UTF-8
fi

launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDBS_BUILD_EXAMPLES=ON -DDBS_BUILD_TESTS=OFF \
  -DDBS_BUILD_BENCH=OFF "${launcher[@]}"
# dbs_examples: libdbs, dbs-param and the example programs (examples/CMakeLists.txt), nothing else
cmake --build "$build" -j"$(nproc)" --target dbs_examples
echo "setup: built libdbs, dbs-param and the examples into $build"
