#!/bin/sh
# madd-mpi fails all or nothing: bad input (every rank sees it) gives exit 3
# and one message; a part one rank cannot write gives exit 5 and no rank's
# files; a memory limit met while meshing gives exit 6 and no files; a bad
# command line gives exit 2. Earlier files stay as they were. Run by ctest as
#   failure_test.sh MPIEXEC NP MADD_MPI DATA_DIR WORKDIR
set -eu
mpiexec=$1 np=$2 madd_mpi=$3 data=$4 work=$5
root_flag=""
[ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
fail() { echo "failure_test: $*" >&2; exit 1; }
run() {  # expected-code name args...: runs madd-mpi, checks the exit code, keeps stderr in $work/NAME.err
  expected=$1 name=$2
  shift 2
  set +e
  "$mpiexec" $root_flag --oversubscribe -np "$np" "$madd_mpi" "$@" > "$work/$name.out" 2> "$work/$name.err"
  code=$?
  set -e
  [ "$code" = "$expected" ] || fail "$name: exit $code, expected $expected ($(head -3 "$work/$name.err"))"
}
only_the_sentinel() {  # nothing but sentinel.txt (and the directories the test made) in $work/out
  left=$(ls "$work/out" | grep -v -x -e sentinel.txt -e 'm-1.node' || true)
  [ -z "$left" ] || fail "$1 left files behind: $left"
  [ "$(cat "$work/out/sentinel.txt")" = "earlier" ] || fail "$1 changed an earlier file"
}
rm -rf "$work" && mkdir -p "$work/out"
echo earlier > "$work/out/sentinel.txt"

run 2 usage mesh "$data/key.poly" -q 30       # -n is required
grep -q -- "-n N is required" "$work/usage.err" || fail "usage: no message about -n"
# madd mesh's option table: the flag as typed, the separators' angle apart from the triangles'
run 2 usage_phi mesh "$data/key.poly" -n 4 --min-angle 95
grep -q -- "--min-angle must lie strictly between 0 and 90" "$work/usage_phi.err" || fail "usage: --min-angle not named"
run 2 usage_q mesh "$data/key.poly" -n 4 -q 95
grep -q -- "-q must lie in \[0, 60)" "$work/usage_q.err" || fail "usage: -q not named"
run 2 usage_msh mesh "$data/key.poly" -n 4 --msh
grep -q -- "option '--msh' is not available here" "$work/usage_msh.err" || fail "usage: --msh not refused by name"

run 3 bad_input mesh "$data/bad/crossing.poly" -n 4 -o "$work/out/m"
[ "$(grep -c 'crossing.poly:' "$work/bad_input.err")" = 1 ] || fail "bad input: expected one located message, got: $(cat "$work/bad_input.err")"
only_the_sentinel "bad input"

mkdir "$work/out/m-1.node"  # rank 1's file cannot be written: no rank's may be
run 5 unwritable mesh "$data/key.poly" -n 8 -a 0.01 --vtu -o "$work/out/m"
grep -q "m-1.node: is a directory" "$work/unwritable.err" || fail "unwritable: rank 1 did not say why"
only_the_sentinel "an unwritable part"
rmdir "$work/out/m-1.node"

run 6 limit mesh "$data/key.poly" -n 8 -a 0.000005 --max-memory 80 -o "$work/out/m"
grep -q "memory limit" "$work/limit.err" || fail "limit: no message about the memory limit"
only_the_sentinel "a limit"
echo "failure_test: $np ranks: usage 2, bad input 3, unwritable part 5, limit 6, nothing written"
