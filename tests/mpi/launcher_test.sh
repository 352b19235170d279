#!/bin/sh
# madd-mpi starts meshing its share before MPI has started, under the rank
# and rank count its launcher put in the environment (docs/mpi.md,
# "Start-up"); a guess that MPI contradicts on any rank, or none at all,
# makes every rank mesh the usual way. Either way the parts are the same,
# byte for byte: here with the launcher's variables right (the early start),
# wrong on every rank, wrong on rank 1 only, and missing; and a run without
# a launcher against one at a single rank. Run by ctest (tests/CMakeLists.txt) as
#   launcher_test.sh MPIEXEC NP MADD_MPI DOMAIN WORKDIR [mesh options...]
set -eu
mpiexec=$1 np=$2 madd_mpi=$3 domain=$4 work=$5
shift 5
rm -rf "$work" && mkdir -p "$work"
root_flag=""
[ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
fail() { echo "launcher_test: $*" >&2; exit 1; }
launch() {  # launch NP PREFIX [command before madd-mpi...]
  n=$1 prefix=$2
  shift 2
  "$mpiexec" $root_flag --oversubscribe -np "$n" "$@" "$madd_mpi" mesh "$domain" -j 1 --quiet -o "$work/$prefix" \
    --report="$work/$prefix.json" $options || fail "$prefix: madd-mpi failed"
}
early() {  # early PREFIX 0|1: the report says whether the share was meshed early
  grep -q "\"early_start\": $2," "$work/$1.json" || fail "$1: early_start is not $2 in its report"
}
options="$*"
same() {  # same PREFIX REFERENCE NP
  last=$(($3 - 1))
  for r in $(seq 0 "$last"); do
    for ext in node ele; do
      [ -s "$work/$1-$r.$ext" ] || fail "$1: rank $r wrote no $1-$r.$ext"
      cmp -s "$work/$1-$r.$ext" "$work/$2-$r.$ext" || fail "$1-$r.$ext differs from $2-$r.$ext"
    done
  done
}
wrong_everywhere='OMPI_COMM_WORLD_SIZE=7 PMI_SIZE=7 MV2_COMM_WORLD_SIZE=7'
launch "$np" right
early right 1
launch "$np" wrong env $wrong_everywhere
same wrong right "$np"
early wrong 0
launch "$np" wrong1 sh -c 'if [ "${OMPI_COMM_WORLD_RANK:-${PMI_RANK:-}}" = 1 ]; then
  export OMPI_COMM_WORLD_SIZE=7 PMI_SIZE=7; fi; exec "$0" "$@"'
same wrong1 right "$np"
early wrong1 0
launch "$np" none env -u OMPI_COMM_WORLD_RANK -u OMPI_COMM_WORLD_SIZE -u PMI_RANK -u PMI_SIZE \
  -u MV2_COMM_WORLD_RANK -u MV2_COMM_WORLD_SIZE
same none right "$np"
early none 0
# Without a launcher: a world of one, as mpiexec -np 1 makes it.
launch 1 one
"$madd_mpi" mesh "$domain" -j 1 --quiet -o "$work/alone" --report="$work/alone.json" $options ||
  fail "alone: madd-mpi failed"
same alone one 1
early one 1
early alone 0
echo "launcher_test: the same parts with the launcher's rank right, wrong everywhere, wrong on rank 1, missing, and alone"
