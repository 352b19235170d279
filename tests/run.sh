#!/bin/sh
# The project's test command (README): installs what a fresh Debian machine
# lacks, builds, and runs every test.
#   tests/run.sh              Release build in build/, all tests
#   tests/run.sh --sanitize   ASan+UBSan build in build-asan/, all tests
#   tests/run.sh [--sanitize] --configure-only
#                             only the configure step (tests/run_sh_test.sh)
# MADD_BUILD_DIR overrides the build directory.
#
# The build directory may already exist, configured by someone else (the
# README's first command configures build/ with -DMADD_BUILD_TESTS=OFF): the
# tests, the CLI (some tests run it) and the benchmark are therefore forced on,
# and ctest fails when it finds no test instead of passing vacuously.
set -eu
cd "$(dirname "$0")/.."

sanitize=0
configure_only=0
for arg in "$@"; do
  case "$arg" in
  --sanitize) sanitize=1 ;;
  --configure-only) configure_only=1 ;;
  *) echo "usage: tests/run.sh [--sanitize] [--configure-only]" >&2; exit 2 ;;
  esac
done

need=""
command -v cmake >/dev/null 2>&1 || need="$need cmake"
command -v g++ >/dev/null 2>&1 || need="$need g++"
[ -f /usr/include/doctest/doctest.h ] || need="$need doctest-dev"
# clang-format checks the code's style (tests/check_format.sh); only the
# configure step's test list depends on it.
command -v clang-format >/dev/null 2>&1 || need="$need clang-format"
if [ -n "$need" ]; then
  apt-get update -qq && apt-get install -y -qq $need
fi
# Python is optional too: with Debian's python3, pybind11 and numpy the
# Python module is built and its pytest suite run (tests/python/; shapely,
# meshio and matplotlib for the conversions and the docs' example).
python_packages="python3-dev pybind11-dev python3-numpy python3-pytest python3-shapely python3-meshio python3-matplotlib"
if [ "$configure_only" = 0 ] && [ "$sanitize" = 0 ]; then
  missing=""
  for p in $python_packages; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
  if [ -n "$missing" ]; then
    (apt-get update -qq && apt-get install -y -qq $missing) >/dev/null 2>&1 || echo "note: the Python packages did not install; the Python module will not be built"
  fi
fi
# gmsh is optional: with it, a test meshes the --geo output and checks that the
# mesh is conforming across subdomains; without it that test is skipped.
if [ "$configure_only" = 0 ] && ! command -v gmsh >/dev/null 2>&1; then
  (apt-get update -qq && apt-get install -y -qq gmsh) >/dev/null 2>&1 || echo "note: gmsh not installed; the gmsh test will be skipped"
fi

jobs=$(nproc 2>/dev/null || echo 2)
on="-DMADD_BUILD_TESTS=ON -DMADD_BUILD_CLI=ON -DMADD_BUILD_BENCH=ON"
if [ "$sanitize" = 1 ]; then
  dir=${MADD_BUILD_DIR:-build-asan}
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMADD_SANITIZE=ON -DMADD_STATIC_CLI=OFF $on
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
else
  dir=${MADD_BUILD_DIR:-build}
  # Debian's python3 (another python3 may come first in PATH, e.g. pyenv's).
  python=""
  [ -x /usr/bin/python3 ] && python="-DPython_EXECUTABLE=/usr/bin/python3"
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release $on $python
fi
[ "$configure_only" = 1 ] && exit 0
cmake --build "$dir" -j"$jobs"
ctest --test-dir "$dir" --output-on-failure --no-tests=error -j"$jobs"
