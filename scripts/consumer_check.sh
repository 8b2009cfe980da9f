#!/usr/bin/env bash
# Proves that an installed libdbs can be used by an outside project, shared and static:
#   1. a shared build installed into a temporary prefix, then moved elsewhere (the installed
#      dbs.pc and CMake package must find the moved tree);
#   2. tests/consumer built with find_package(dbs) + dbs::dbs, and consumer.c built with
#      `pkg-config --cflags --libs dbs`; both run; the same for the Fortran module:
#      tests/consumer_fortran (find_package(dbs COMPONENTS fortran) + dbs::fortran) and the
#      example program built with `gfortran ... $(pkg-config --cflags --libs dbs-fortran)`,
#      both against the installed dbs.mod, both run;
#   3. only dbs_* symbols are exported by the installed libdbs.so;
#   4. the same with a static build (-DDBS_BUILD_SHARED=OFF, Ceres required), pkg-config --static;
#      its dbs.pc names Ceres (Libs.private) and glog (Requires.private);
#   5. a static minimal build (no Draco, Ceres, validation, report): its dbs.pc's private
#      libraries name neither Qhull nor libpng (nor Draco, Ceres, glog), and both consumers build and run.
# Build trees go to build-consumer/ (reused by later runs); the prefixes are removed at exit.
#
# usage: scripts/consumer_check.sh
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="$repo/build-consumer"
prefixes="$(mktemp -d)"
trap 'rm -rf "$prefixes"' EXIT
jobs="$(nproc)"
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

# install_libdbs NAME CMAKE_OPTIONS...: builds libdbs alone, installs it into $prefixes/NAME-installed
# and moves that tree to $prefixes/NAME.
install_libdbs() {
  local name="$1"
  shift
  local prefix="$prefixes/$name"
  echo "consumer_check: building and installing a $name libdbs into $prefix"
  cmake -S "$repo" -B "$work/libdbs-$name" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix-installed" \
    -DDBS_BUILD_TESTS=OFF -DDBS_BUILD_EXAMPLES=OFF -DDBS_BUILD_BENCH=OFF "${launcher[@]}" "$@" >/dev/null
  cmake --build "$work/libdbs-$name" -j"$jobs" >/dev/null
  cmake --install "$work/libdbs-$name" >/dev/null
  mv "$prefix-installed" "$prefix"
}

# consume NAME [--static]: builds and runs both consumers against $prefixes/NAME.
consume() {
  local name="$1" static="${2:-}"
  local prefix="$prefixes/$name"
  local pc_dir
  pc_dir="$(dirname "$(find "$prefix" -name dbs.pc -print -quit)")"

  echo "consumer_check: [$name] find_package(dbs) + dbs::dbs"
  rm -rf "$work/cmake-$name"
  cmake -S "$repo/tests/consumer" -B "$work/cmake-$name" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
    -DDBS_REQUIRED_VERSION="$version" >/dev/null
  cmake --build "$work/cmake-$name" >/dev/null
  "$work/cmake-$name/consumer"

  echo "consumer_check: [$name] cc consumer.c \$(pkg-config $static --cflags --libs dbs)"
  local flags libdir
  flags="$(PKG_CONFIG_PATH="$pc_dir" pkg-config $static --cflags --libs dbs)"
  libdir="$(PKG_CONFIG_PATH="$pc_dir" pkg-config --variable=libdir dbs)"
  echo "  pkg-config: $flags"
  # shellcheck disable=SC2086  # the flags are meant to split into words
  cc "$repo/tests/consumer/consumer.c" $flags -lm -Wl,-rpath,"$libdir" -o "$work/pkgconfig-$name"
  "$work/pkgconfig-$name"
}

# consume_fortran NAME [--static]: builds and runs both Fortran consumers against $prefixes/NAME.
consume_fortran() {
  local name="$1" static="${2:-}"
  local prefix="$prefixes/$name"
  local pc_dir
  pc_dir="$(dirname "$(find "$prefix" -name dbs-fortran.pc -print -quit)")"
  if [ "$pc_dir" = "." ]; then
    echo "consumer_check: [$name] cmake --install did not install the Fortran module (dbs-fortran.pc)" >&2
    exit 1
  fi

  echo "consumer_check: [$name] find_package(dbs COMPONENTS fortran) + dbs::fortran"
  rm -rf "$work/cmake-fortran-$name"
  cmake -S "$repo/tests/consumer_fortran" -B "$work/cmake-fortran-$name" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release -DDBS_REQUIRED_VERSION="$version" >/dev/null
  cmake --build "$work/cmake-fortran-$name" >/dev/null
  # the example's last line: its checks passed (a failed one stops it with a non-zero status)
  "$work/cmake-fortran-$name/consumer_fortran" | tail -n 1

  echo "consumer_check: [$name] gfortran example.f90 \$(pkg-config $static --cflags --libs dbs-fortran)"
  local flags libdir
  flags="$(PKG_CONFIG_PATH="$pc_dir" pkg-config $static --cflags --libs dbs-fortran)"
  libdir="$(PKG_CONFIG_PATH="$pc_dir" pkg-config --variable=libdir dbs-fortran)"
  echo "  pkg-config: $flags"
  mkdir -p "$work/pkgconfig-fortran-$name"
  # shellcheck disable=SC2086  # the flags are meant to split into words
  (cd "$work/pkgconfig-fortran-$name" && gfortran "$repo/examples/fortran/example.f90" $flags -Wl,-rpath,"$libdir" -o consumer_fortran)
  "$work/pkgconfig-fortran-$name/consumer_fortran" | tail -n 1
}

mkdir -p "$work"
# major.minor of this tree: what an outside project asks find_package(dbs) for
version="$(sed -n 's/^project(dbs VERSION \([0-9]*\.[0-9]*\).*/\1/p' "$repo/CMakeLists.txt")"

install_libdbs shared -DDBS_BUILD_SHARED=ON
consume shared
consume_fortran shared

echo "consumer_check: [shared] exported symbols"
library="$(find "$prefixes/shared" -name 'libdbs.so.*' -type f -print -quit)"
foreign="$(nm -D --defined-only "$library" | awk '{print $NF}' | grep -v '^dbs_' | grep -v '^DBS_' || true)"
if [ -n "$foreign" ]; then
  echo "consumer_check: $library exports symbols other than dbs_*:" >&2
  echo "$foreign" | head -20 >&2
  exit 1
fi
echo "  $(nm -D --defined-only "$library" | grep -c ' dbs_') dbs_* functions, nothing else"

# The Python package: installed with the library (and moved with it) it imports without
# DBS_LIBRARY; `pip install --no-build-isolation` of the source tree works offline in a venv.
python=""
for candidate in /usr/bin/python3 python3; do
  if [ -z "$python" ] && command -v "$candidate" >/dev/null && "$candidate" -c "import numpy" 2>/dev/null; then python="$(command -v "$candidate")"; fi
done
if [ -z "$python" ]; then
  echo "consumer_check: no python3 with NumPy (scripts/setup.sh installs python3-numpy)" >&2
  exit 1
fi
python_check='import numpy as np, libdbs
g = np.linspace(0.0, 1.0, 21)
x, y = np.meshgrid(g, g)
points = np.column_stack([x.ravel(), y.ravel(), 0.0 * x.ravel()])
side = lambda a, b: np.array([a + t * (np.array(b) - np.array(a)) for t in g])
boundary = libdbs.Boundary(side([0, 0, 0], [1, 0, 0]), side([1, 0, 0], [1, 1, 0]), side([0, 1, 0], [1, 1, 0]), side([0, 0, 0], [0, 1, 0]))
result = libdbs.parameterize(points, boundary, max_level=0)
assert np.abs(result.uv - points[:, :2]).max() < 1e-9
print("  import libdbs from", libdbs.__file__, "with", libdbs.lib._name, ":", result)'
installed="$(find "$prefixes/shared" -name _installed.py -path '*/libdbs/*' -print -quit)"
if [ -z "$installed" ]; then
  echo "consumer_check: cmake --install did not install the Python package" >&2
  exit 1
fi
echo "consumer_check: [shared] the installed Python package"
(cd "$prefixes" && env -u DBS_LIBRARY PYTHONPATH="$(dirname "$(dirname "$installed")")" "$python" -c "$python_check")
echo "consumer_check: pip install --no-build-isolation of python/ into a venv"
cp -r "$repo/python" "$prefixes/python-source"
"$python" -m venv --system-site-packages "$prefixes/venv"
"$prefixes/venv/bin/pip" install -q --no-build-isolation --no-index "$prefixes/python-source"
(cd "$prefixes" && DBS_LIBRARY="$library" "$prefixes/venv/bin/python" -c "$python_check")

install_libdbs static -DDBS_BUILD_SHARED=OFF -DDBS_WITH_CERES=ON
echo "consumer_check: [static] dbs.pc names Ceres and glog for the static link"
pc_file="$(find "$prefixes/static" -name dbs.pc -print -quit)"
if ! grep -q -- '^Libs.private:.*-lceres' "$pc_file" || ! grep -q '^Requires.private:.*libglog' "$pc_file"; then
  echo "consumer_check: $pc_file of a static build with Ceres lacks -lceres or libglog" >&2
  exit 1
fi
consume static --static
consume_fortran static --static

minimal=(-DDBS_WITH_DRACO=OFF -DDBS_WITH_CERES=OFF -DDBS_WITH_VALIDATION=OFF -DDBS_WITH_REPORT=OFF)
install_libdbs minimal-static -DDBS_BUILD_SHARED=OFF "${minimal[@]}"
echo "consumer_check: [minimal-static] dbs.pc lists only what was built"
pc_file="$(find "$prefixes/minimal-static" -name dbs.pc -print -quit)"
private="$(grep '^Libs.private:' "$pc_file")"
echo "  $private"
if grep -qE -- '-l(qhull|png|draco|ceres)' <<<"$private" || grep -q 'libglog' "$pc_file"; then
  echo "consumer_check: $pc_file of a build without validation, report, Draco and Ceres lists their libraries" >&2
  exit 1
fi
consume minimal-static --static

echo "consumer_check: all consumers built and ran"
