// mesh_share(): one process's share of mesh() (include/madd/mesh_share.hpp,
// docs/mpi.md). The same steps as mesh_decomposition(), on the subdomains of
// this share only; the vertex and triangle numbers are those mesh() gives,
// from the per-subdomain counts every share contributes once at the end.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <numeric>
#include <string>
#include <thread>
#include <unordered_map>

#include "kernel/resource_limits.hpp"
#include "kernel/stopwatch.hpp"
#include "kernel/threads.hpp"
#include "madd/mesh_share.hpp"
#include "mesh/discretise.hpp"
#include "quality/verify_mesh_bounded.hpp"
#include "mesh/merge.hpp"
#include "mesh/rounds.hpp"
#include "mesh/subdomain_check.hpp"
#include "quality/area_bound.hpp"
#include "mesh/work.hpp"

namespace madd {

std::vector<std::uint32_t> assign_shares(const std::vector<double>& expected_triangles, std::uint32_t shares) {
  const auto n = static_cast<std::uint32_t>(expected_triangles.size());
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return expected_triangles[a] > expected_triangles[b]; });
  std::vector<double> load(std::max(shares, 1u), 0.0);
  std::vector<std::uint32_t> owner(n, 0);
  for (const std::uint32_t k : order) {
    const auto least = static_cast<std::uint32_t>(std::min_element(load.begin(), load.end()) - load.begin());
    owner[k] = least;
    load[least] += expected_triangles[k];
  }
  return owner;
}

namespace {

std::vector<std::uint64_t> exclusive_sums(const std::vector<std::uint64_t>& counts, std::size_t first, std::size_t n,
                                          std::uint64_t& total) {
  std::vector<std::uint64_t> out(n);
  total = 0;
  for (std::size_t k = 0; k < n; ++k) {
    out[k] = total;
    total += counts[first + k];
  }
  return out;
}

// merge()'s mesh of the share's subdomains, which numbers the vertices as
// the whole mesh would, taken apart: the decomposition to the part, the
// rest to its local mesh (keep_used_points numbers it locally).
void take_merged(Mesh&& merged, MeshPart& part) {
  part.decomposition = std::move(merged.decomposition);
  LocalMesh& m = part.mesh;
  m.points = std::move(merged.points);
  m.point_markers = std::move(merged.point_markers);
  m.triangles = std::move(merged.triangles);
  m.neighbours = std::move(merged.neighbours);
  m.triangle_subdomain = std::move(merged.triangle_subdomain);
  m.triangle_attribute = std::move(merged.triangle_attribute);
  m.subdomain_first_triangle = std::move(merged.subdomain_first_triangle);
  m.segments = std::move(merged.segments);
  m.shortfall = merged.shortfall;
  m.min_triangle_angle_deg = merged.min_triangle_angle_deg;
}

// The part's mesh keeps only the vertices its triangles and segments use.
void keep_used_points(MeshPart& part, std::vector<std::uint64_t>& ids) {
  LocalMesh& m = part.mesh;
  std::vector<std::uint32_t> renumber(m.points.size(), no_index);
  for (const auto& tri : m.triangles)
    for (const std::uint32_t v : tri) renumber[v] = 0;
  for (const MeshSegment& s : m.segments) renumber[s.a] = renumber[s.b] = 0;
  std::uint32_t next = 0;
  for (std::uint32_t v = 0; v < m.points.size(); ++v) {
    if (renumber[v] == no_index) continue;
    renumber[v] = next;
    m.points[next] = m.points[v];
    m.point_markers[next] = m.point_markers[v];
    ids[next] = ids[v];
    ++next;
  }
  m.points.resize(next);
  m.point_markers.resize(next);
  ids.resize(next);
  for (auto& tri : m.triangles)
    for (std::uint32_t& v : tri) v = renumber[v];
  for (MeshSegment& s : m.segments) {
    s.a = renumber[s.a];
    s.b = renumber[s.b];
  }
}

// Per vertex of the decomposition: the lowest share whose subdomains have it
// (every decomposition vertex a subdomain mesh uses is on its rings, on its
// interior pieces or one of its isolated vertices).
std::vector<std::uint32_t> decomposition_point_owner(const Decomposition& d, const std::vector<std::uint32_t>& owner) {
  std::vector<std::uint32_t> out(d.points.size(), no_index);
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    const Subdomain& s = d.subdomains[k];
    const auto take = [&](std::uint32_t v) { out[v] = std::min(out[v], owner[k]); };
    for (const auto& ring : s.rings)
      for (const std::uint32_t v : ring) take(v);
    for (const std::uint32_t j : s.interior_segments) {
      take(d.segments[j].a);
      take(d.segments[j].b);
    }
    for (const std::uint32_t v : s.interior_points) take(v);
  }
  return out;
}

}  // namespace

MeshPartRun mesh_share(const Decomposition& decomposition, const Pslg& domain, const MeshOptions& options,
                       std::uint32_t share, std::uint32_t shares, const ShareExchange& exchange) {
  // Each subdomain is checked against its own boundary (the union is
  // mesh()'s, checked there); the domain is what the size field is built on.
  check_options(options);
  if (shares == 0 || share >= shares) throw OptionError("share", "must be < shares (and shares >= 1)");
  MeshPartRun run;
  MeshReport& report = run.report;
  MeshPart& part = run.part;
  detail::Stopwatch clock;
  const auto n = static_cast<std::uint32_t>(decomposition.subdomains.size());
  const detail::ResourceGuard guard(
      {options.decomposition.time_limit_seconds, options.decomposition.max_memory_bytes, n});
  // Every share builds the same field from the same domain (deterministic):
  // no exchange needed.
  const detail::AreaBound field(options.size, &domain, options.decomposition.threads);
  if (!field.field().empty()) report.phases.push_back({"size field", clock.lap()});
  // The subdomains' regions, found once: the decoupling's split points change no face.
  const detail::RegionView view = detail::region_view(decomposition, options.decomposition.threads);
  Decomposition d = detail::discretise(decomposition, field, false, &guard, options.decomposition.threads, &view);
  report.phases.push_back({"discretise", clock.lap()});
  report.expected_triangles =
      detail::expected_triangles(d, detail::DomainWork(domain, field, options.decomposition.threads),
                                 options.decomposition.threads, &decomposition, &view);
  report.phases.push_back({"estimate", clock.lap()});

  part.share = share;
  part.shares = shares;
  part.owner = assign_shares(report.expected_triangles, shares);
  std::vector<bool> mine(n, false);
  for (std::uint32_t k = 0; k < n; ++k)
    if (part.owner[k] == share) {
      mine[k] = true;
      part.subdomains.push_back(k);
    }
  std::vector<detail::SubdomainMesh> pieces;
  const std::vector<std::vector<Region>>& regions = view.regions;
  // Each subdomain is checked whole, against its own boundary, by the thread
  // that meshed it as soon as it has (the union of the shares is checked by
  // whoever joins them: tests/mpi).
  const detail::SubdomainCheck check = [&](std::uint32_t k, const detail::LocalDomain&,
                                           const detail::SubdomainMesh& piece) {
    detail::verify_subdomain(d, k, regions[k], piece, options.size.min_triangle_angle_deg, field);
  };
  detail::refine_in_rounds(d, options, field, report.expected_triangles, guard, mine, exchange.union_of, report, pieces,
                           regions, options.verify ? check : detail::SubdomainCheck{});
  report.phases.push_back({"refine", clock.lap()});

  // Steiner points and triangles of every subdomain, from every share: the
  // offsets mesh()'s merge numbers them with.
  std::vector<std::uint64_t> counts(2 * std::size_t{n}, 0);
  for (const std::uint32_t k : part.subdomains) {
    // The subdomain's own decomposition points (rings, interior pieces'
    // ends, isolated vertices) come first in its mesh; the rest are Steiner points.
    counts[k] = pieces[k].points.size() - detail::local_domain(d, k).to_global.size();
    counts[n + k] = pieces[k].triangles.size();
  }
  counts = exchange.sum_of(counts);
  std::uint64_t steiner_total = 0;
  const std::vector<std::uint64_t> first_steiner = exclusive_sums(counts, 0, n, steiner_total);
  const std::vector<std::uint64_t> first_triangle = exclusive_sums(counts, n, n, part.total_triangles);
  part.total_points = d.points.size() + steiner_total;

  take_merged(detail::merge(d, pieces, options.size.min_triangle_angle_deg, &mine, options.decomposition.threads),
              part);
  const std::size_t p = d.points.size();
  std::vector<std::uint64_t> ids(part.mesh.points.size());
  std::iota(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(p), std::uint64_t{0});
  std::size_t at = p;
  for (const std::uint32_t k : part.subdomains)
    for (std::uint64_t j = 0; j < counts[k]; ++j) ids[at++] = p + first_steiner[k] + j;
  const std::vector<std::uint32_t> point_owner = decomposition_point_owner(d, part.owner);
  std::vector<std::uint32_t> owners(part.mesh.points.size(), share);
  for (std::size_t v = 0; v < p; ++v) owners[v] = point_owner[v];
  // keep_used_points moves ids along; the owners follow the same ids.
  keep_used_points(part, ids);
  part.point_ids = std::move(ids);
  part.point_owner.resize(part.point_ids.size());
  for (std::size_t v = 0; v < part.point_ids.size(); ++v)
    part.point_owner[v] = part.point_ids[v] < p ? owners[part.point_ids[v]] : share;
  part.triangle_ids.reserve(part.mesh.triangles.size());
  for (const std::uint32_t k : part.subdomains)
    for (std::uint32_t t = part.mesh.subdomain_first_triangle[k]; t < part.mesh.subdomain_first_triangle[k + 1]; ++t)
      part.triangle_ids.push_back(first_triangle[k] + (t - part.mesh.subdomain_first_triangle[k]));
  report.phases.push_back({"merge", clock.lap()});
  return run;
}

}  // namespace madd
