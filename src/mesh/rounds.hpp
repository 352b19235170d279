#pragma once
// The refinement rounds of a mesh run (docs/mesh.md, "Decoupling"), shared
// by mesh() (every subdomain, on threads) and mesh_share() (one share's
// subdomains, on one process of several).
#include <cstdint>
#include <functional>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "kernel/resource_limits.hpp"
#include "mesh/merge.hpp"
#include "mesh/refine.hpp"
#include "quality/area_bound.hpp"

namespace madd::detail {

// This process's separator ids -> the union over every process meshing the
// same decomposition (the identity for a single process).
using SeparatorUnion = std::function<std::vector<std::uint32_t>(const std::vector<std::uint32_t>&)>;

// The self-check of subdomain k's mesh, run by the thread that made it as
// soon as the mesh is final (no separator piece of it stopped a fix, or the
// last round): throws to stop the run.
using SubdomainCheck = std::function<void(std::uint32_t k, const LocalDomain& local, const SubdomainMesh& piece)>;

// Meshes the subdomains k with mine[k] of the discretised decomposition `d`,
// then, round after round, splits every separator piece that stopped a fix
// (the union over all processes, once for both its sides, in `d`) and meshes
// again those of its subdomains that are `mine`, until no piece blocks or
// max_separator_rounds is reached. `work`: expected triangles per subdomain.
// The meshes land in pieces[k]; the others stay empty. Which pieces are split
// depends on the meshes only, never on threads or processes.
// `regions`: each subdomain's regions (subdomain_regions: region_view's, of
// d or of d before the decoupling, whose split points change no face).
// `check`, when set, checks each final mesh on its thread.
void refine_in_rounds(Decomposition& d, const MeshOptions& options, const AreaBound& field,
                      const std::vector<double>& work, const ResourceGuard& guard, const std::vector<bool>& mine,
                      const SeparatorUnion& union_of, MeshReport& report, std::vector<SubdomainMesh>& pieces,
                      const std::vector<std::vector<Region>>& regions, const SubdomainCheck& check = nullptr);

// Throws InternalError with the first of v's problems (v failed).
[[noreturn]] void throw_failed_check(const Verification& v);

}  // namespace madd::detail
