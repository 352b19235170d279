// A subdomain's mesh on its own (mesh/subdomain_check.hpp).
#include "mesh/subdomain_check.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <unordered_map>

#include "mesh/merge.hpp"
#include "mesh/rounds.hpp"
#include "quality/verify_mesh_bounded.hpp"

namespace madd::detail {

namespace {

// Subdomain k of `d` as a domain of its own, every ring segment a boundary
// piece (a separator's marker 0 becomes 1, as an unmarked boundary), its
// interior pieces and isolated vertices its own, and its regions, so that
// verify_mesh can check its mesh alone.
struct SubdomainAlone {
  Pslg domain;
  Decomposition decomposition;
};

SubdomainAlone subdomain_alone(const Decomposition& d, std::uint32_t k, const std::vector<Region>& regions) {
  const LocalDomain local = local_domain(d, k);
  SubdomainAlone out;
  out.domain = local.pslg;
  out.domain.regions = regions;  // the subdomain's own regions (mesh/subdomain_regions.hpp)
  for (Segment& s : out.domain.segments)
    if (s.marker == 0) s.marker = 1;
  Decomposition& dk = out.decomposition;
  dk.points = out.domain.points;
  dk.segments = out.domain.segments;
  dk.segment_origin.resize(dk.segments.size());
  std::iota(dk.segment_origin.begin(), dk.segment_origin.end(), 0u);
  dk.holes = out.domain.holes;
  dk.regions = out.domain.regions;
  dk.separator_angle_deg = d.separator_angle_deg;
  Subdomain s = d.subdomains[k];
  // Every vertex is the local point of its global id: local_domain lists a
  // vertex once where rings touch (a vertex twice on a ring, or on two), so
  // ring positions are no point ids. Its segments are one per ring
  // position, in ring order, then the interior pieces in order.
  std::unordered_map<std::uint32_t, std::uint32_t> local_of;
  for (std::uint32_t v = 0; v < local.to_global.size(); ++v) local_of.emplace(local.to_global[v], v);
  std::uint32_t next = 0;
  for (std::size_t r = 0; r < s.rings.size(); ++r)
    for (std::size_t i = 0; i < s.rings[r].size(); ++i) {
      s.rings[r][i] = local_of.at(s.rings[r][i]);
      s.ring_segments[r][i] = next++;
    }
  for (std::uint32_t& j : s.interior_segments) j = next++;
  for (std::uint32_t& v : s.interior_points) v = local_of.at(v);
  std::sort(s.interior_points.begin(), s.interior_points.end());
  dk.subdomains.push_back(std::move(s));
  return out;
}

}  // namespace

Verification check_subdomain(const Decomposition& d, std::uint32_t k, const std::vector<Region>& regions,
                             const SubdomainMesh& piece, double min_triangle_angle_deg, const AreaBound& field) {
  const SubdomainAlone alone = subdomain_alone(d, k, regions);
  std::vector<SubdomainMesh> one{piece};
  const Mesh m = merge(alone.decomposition, one, min_triangle_angle_deg);
  const Verification v = verify_mesh(m, alone.domain, field);
  Verification named;
  for (const std::string& p : v.problems) named.problems.push_back("subdomain " + std::to_string(k) + ": " + p);
  return named;
}

void verify_subdomain(const Decomposition& d, std::uint32_t k, const std::vector<Region>& regions,
                      const SubdomainMesh& piece, double min_triangle_angle_deg, const AreaBound& field) {
  const Verification v = check_subdomain(d, k, regions, piece, min_triangle_angle_deg, field);
  if (!v.ok()) throw_failed_check(v);
}

}  // namespace madd::detail
