#!/bin/sh
# madd-mpi's coastal model files (rank 0 writes them from the gathered
# parts) are byte for byte `madd mesh`'s for the same input and options, at
# NP ranks: a GeoJSON coast with islands, its depth grid, fort.14,
# hgrid.gr3/.ll and .2dm. Run by ctest (tests/CMakeLists.txt) as
#   model_test.sh MPIEXEC NP MADD MADD_MPI COAST_DIR WORKDIR
set -eu
mpiexec=$1 np=$2 madd=$3 madd_mpi=$4 coast=$5 work=$6
rm -rf "$work" && mkdir -p "$work/one" "$work/parts"
# This field and N = 16 put two of the bay's touching rings into one
# subdomain: each rank's check of its subdomains once failed there (exit 70).
set -- "$coast/bay.geojson" --clip -70.0,43.5,-69.5,43.9 --hmin 50 --hmax 3000 --distance-rate 0.15 \
  --cells-across 3 --gradation 0.2 --depth "$coast/depth.asc" --wavelength-cells 50 -n 16 -j 1 --quiet
"$madd" mesh "$@" -o "$work/one/m" --fort14 "$work/one/m.14" --gr3 "$work/one/m.gr3" --2dm "$work/one/m.2dm"
root_flag=""
[ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
"$mpiexec" $root_flag --oversubscribe -np "$np" "$madd_mpi" mesh "$@" -o "$work/parts/m" \
  --fort14 "$work/parts/m.14" --gr3 "$work/parts/m.gr3" --2dm "$work/parts/m.2dm"
for f in m.14 m.gr3 m.ll m.2dm; do
  [ -s "$work/one/$f" ] || { echo "model_test: madd mesh wrote no $f" >&2; exit 1; }
  cmp "$work/one/$f" "$work/parts/$f" || { echo "model_test: $f differs at $np ranks" >&2; exit 1; }
done
"$madd" check "$work/parts/m.14" --quiet
echo "model_test: the model files at $np ranks are madd mesh's"
