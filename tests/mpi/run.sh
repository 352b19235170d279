#!/bin/sh
# The MPI driver's tests (docs/mpi.md): installs Open MPI from Debian when it
# is missing, builds madd-mpi into the Release build directory beside the
# rest (tests/run.sh's build/, or MADD_BUILD_DIR), and runs the mpi_* tests
# (tests/CMakeLists.txt: the union of the parts at 2 and 3 ranks is madd
# mesh's mesh; every failure is all or nothing). .ci/run calls it; the
# README's commands do not need MPI.
set -eu
cd "$(dirname "$0")/../.."
if ! command -v mpicxx >/dev/null 2>&1 || ! command -v mpirun >/dev/null 2>&1; then
  apt-get update -qq && apt-get install -y -qq libopenmpi-dev openmpi-bin
fi
dir=${MADD_BUILD_DIR:-build}
# The build directory may have been configured before MPI was installed
# (.ci/run runs tests/run.sh first): forget what CMake's FindMPI cached then.
cmake -S . -B "$dir" -U 'MPI*' -DCMAKE_BUILD_TYPE=Release -DMADD_BUILD_TESTS=ON -DMADD_BUILD_CLI=ON -DMADD_MPI=ON
cmake --build "$dir" -j"$(nproc 2>/dev/null || echo 2)"
ctest --test-dir "$dir" --output-on-failure --no-tests=error -R '^mpi_'
