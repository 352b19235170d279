#!/bin/sh
# The README's two commands, in order: the first configures build/ with
# -DMADD_BUILD_TESTS=OFF (and builds only the CLI), the second is tests/run.sh,
# which reuses that directory. run.sh must turn the tests, the CLI and the
# benchmark back on, and its ctest must fail rather than pass when it finds no
# test. Checked on a scratch build directory, configure step only (a few
# seconds; no second build in CI).
# Usage: tests/run_sh_test.sh   (ctest runs it; CXX picks the compiler)
set -eu
source_dir=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/madd-run-sh.XXXXXX")
trap 'rm -rf "$work"' EXIT
dir="$work/build"
fail() { echo "run_sh_test: $*" >&2; exit 1; }

# 1. The README's first command, configure step (everything optional off).
cmake -S "$source_dir" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DMADD_BUILD_TESTS=OFF \
      -DMADD_BUILD_CLI=OFF -DMADD_BUILD_BENCH=OFF >"$work/configure-off.log" 2>&1 \
  || { cat "$work/configure-off.log" >&2; fail "configuring with the tests off failed"; }
# Such a directory has no test: ctest alone passes there, run.sh's ctest must not.
grep -q -- '--no-tests=error' "$source_dir/tests/run.sh" || fail "run.sh does not run ctest with --no-tests=error"
if ctest --test-dir "$dir" --no-tests=error >"$work/ctest-off.log" 2>&1; then
  fail "ctest --no-tests=error passed in a build directory without tests"
fi

# 2. tests/run.sh's configure step on that directory.
MADD_BUILD_DIR="$dir" sh "$source_dir/tests/run.sh" --configure-only >"$work/configure-on.log" 2>&1 \
  || { cat "$work/configure-on.log" >&2; fail "tests/run.sh --configure-only failed"; }
for option in MADD_BUILD_TESTS MADD_BUILD_CLI MADD_BUILD_BENCH; do
  grep -q "^$option:BOOL=ON\$" "$dir/CMakeCache.txt" || fail "tests/run.sh left $option off in a reused build directory"
done
count=$(ctest --test-dir "$dir" -N | sed -n 's/^Total Tests: *//p')
[ "${count:-0}" -gt 0 ] || fail "after tests/run.sh's configure step, ctest lists no test"
echo "run_sh_test: ok ($count tests after reconfiguring a tests-off build directory)"
