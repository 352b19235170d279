#!/bin/sh
# The project's test command (README): installs what a fresh Debian machine
# lacks, builds, and runs every test.
#   tests/run.sh              Release build in build/, all tests
#   tests/run.sh --sanitize   ASan+UBSan build in build-asan/, all tests
set -eu
cd "$(dirname "$0")/.."

need=""
command -v cmake >/dev/null 2>&1 || need="$need cmake"
command -v g++ >/dev/null 2>&1 || need="$need g++"
[ -f /usr/include/doctest/doctest.h ] || need="$need doctest-dev"
if [ -n "$need" ]; then
  apt-get update -qq && apt-get install -y -qq $need
fi
# gmsh is optional: with it, a test meshes the --geo output and checks that the
# mesh is conforming across subdomains; without it that test is skipped.
if ! command -v gmsh >/dev/null 2>&1; then
  (apt-get update -qq && apt-get install -y -qq gmsh) >/dev/null 2>&1 || echo "note: gmsh not installed; the gmsh test will be skipped"
fi

jobs=$(nproc 2>/dev/null || echo 2)
if [ "${1:-}" = "--sanitize" ]; then
  dir=build-asan
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMADD_SANITIZE=ON -DMADD_STATIC_CLI=OFF
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
else
  dir=build
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$dir" -j"$jobs"
ctest --test-dir "$dir" --output-on-failure -j"$jobs"
