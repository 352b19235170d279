#!/bin/sh
# Proves both ways of consuming madd as a library work:
#   1. install madd (cmake --install) into a temporary prefix, then build and
#      run find_package/ against it (find_package(madd) + madd::madd);
#   2. build and run add_subdirectory/, which vendors this source tree.
# Usage: tests/consumers/run.sh [BUILD_DIR]
#   BUILD_DIR: an already built madd build tree to install from (ctest passes
#   its own); without it, the library is configured and built here first.
# Environment: CXX (compiler), MADD_CONFIG (multi-config builds),
#   MADD_CONSUMER_CXX_FLAGS (e.g. sanitizer flags the library was built with),
#   MADD_KEEP=1 keeps the temporary directory.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/../.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/madd-consumers.XXXXXX")
if [ "${MADD_KEEP:-0}" = 1 ]; then
  echo "run.sh: keeping $work"
else
  trap 'rm -rf "$work"' EXIT
fi
config=${MADD_CONFIG:-Release}
flags=${MADD_CONSUMER_CXX_FLAGS:-}
compiler=""
if [ -n "${CXX:-}" ]; then compiler="-DCMAKE_CXX_COMPILER=$CXX"; fi

step() { echo "==> $*"; }
# Runs a command with its output in a log file, shown only when it fails.
quietly() {
  log=$1
  shift
  "$@" > "$log" 2>&1 || { cat "$log" >&2; exit 1; }
}

# docs/api.md shows find_package/main.cpp verbatim: the example must compile.
sed -n '/^<!-- example: tests\/consumers\/find_package\/main.cpp -->$/,/^```$/p' "$source_dir/docs/api.md" |
  sed '1,2d;$d' > "$work/api-example.cpp"
if ! cmp -s "$work/api-example.cpp" "$here/find_package/main.cpp"; then
  echo "run.sh: the example in docs/api.md differs from tests/consumers/find_package/main.cpp:" >&2
  diff "$work/api-example.cpp" "$here/find_package/main.cpp" >&2 || true
  exit 1
fi

if [ $# -ge 1 ]; then
  build=$1
else
  build=$work/madd-build
  step "building madd (library and CLI) in $build"
  quietly "$work/madd-configure.log" cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE="$config" \
          -DMADD_BUILD_TESTS=OFF -DMADD_BUILD_BENCH=OFF $compiler
  cmake --build "$build" --config "$config" -j2
fi

step "installing $build into $work/prefix"
quietly "$work/install.log" cmake --install "$build" --config "$config" --prefix "$work/prefix"
for f in include/madd/madd.hpp include/madd/output_formats.hpp share/man/man1/madd.1; do
  if [ ! -f "$work/prefix/$f" ]; then
    echo "run.sh: $f was not installed" >&2
    exit 1
  fi
done

step "find_package consumer"
quietly "$work/fp-configure.log" cmake -S "$here/find_package" -B "$work/find_package" \
        -DCMAKE_BUILD_TYPE="$config" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_CXX_FLAGS="$flags" $compiler
quietly "$work/fp-build.log" cmake --build "$work/find_package" --config "$config" -j2
# A multi-config generator puts the program in a per-config directory.
run_consumer() {
  if [ -x "$1/consumer" ]; then "$1/consumer"; else "$1/$config/consumer"; fi
}
run_consumer "$work/find_package" > "$work/fp.out" || { cat "$work/fp.out"; exit 1; }
head -n 1 "$work/fp.out"

# Debug (-O0) keeps this second build of the library quick; the program's own
# checks do not depend on optimisation.
step "add_subdirectory consumer (builds the library from source)"
quietly "$work/as-configure.log" cmake -S "$here/add_subdirectory" -B "$work/add_subdirectory" \
        -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DCMAKE_CXX_FLAGS="$flags" $compiler
config=Debug
quietly "$work/as-build.log" cmake --build "$work/add_subdirectory" --config Debug -j2
if [ -e "$work/add_subdirectory/madd-build/tests" ] || [ -e "$work/add_subdirectory/madd-build/madd" ]; then
  echo "run.sh: add_subdirectory built madd's tests or CLI; only the library should be built" >&2
  exit 1
fi
run_consumer "$work/add_subdirectory" > "$work/as.out" || { cat "$work/as.out"; exit 1; }
head -n 1 "$work/as.out"
step "consumers OK"
