#pragma once
// Every rank's MeshPart brought to rank 0, for the files of the whole mesh
// that one rank writes (the coastal model files: docs/mpi.md). The parts'
// meshes and ids travel as bytes, in chunks of at most 1 GiB (MPI counts are
// ints); a part's decomposition does not travel (every rank has the same).
#include <vector>

#include "madd/mesh_share.hpp"

namespace madd::mpi {

// On rank 0: the parts of ranks 0..size-1, in rank order (its own first);
// elsewhere: empty. Every rank must call it. `own` is this rank's part.
std::vector<MeshPart> gather_parts(const MeshPart& own, int rank, int size);

}  // namespace madd::mpi
