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

#include "kernel/fresh_memory.hpp"
#include "kernel/resource_limits.hpp"
#include "kernel/stopwatch.hpp"
#include "kernel/threads.hpp"
#include "madd/mesh_share.hpp"
#include "mesh/discretise.hpp"
#include "quality/verify_mesh_bounded.hpp"
#include "mesh/merge.hpp"
#include "mesh/mesh_pieces.hpp"
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

// The part's local numbering of the share's pieces (assemble()'s numbering
// of the share's subdomains: all of the decomposition's points, then the
// share's Steiner points): the decomposition points the share's triangles
// and mesh segments use, in increasing global id, then each subdomain's used
// Steiner points in order (all of them, as refinement leaves no vertex
// outside a triangle; counted all the same).
struct PartNumbering {
  std::vector<std::uint32_t> decomposition_local;  // per decomposition point: its local id, or no_index
  std::vector<std::uint32_t> used_decomposition;   // the used decomposition points, increasing
  // Per subdomain, per Steiner point: its local id, or no_index (unused).
  std::vector<std::vector<std::uint32_t>> steiner_local;
  std::uint32_t count = 0;

  std::uint32_t local_of(const detail::MeshPiecesData& m, std::uint32_t k, std::uint32_t v) const {
    const std::size_t own = m.local[k].to_global.size();
    return v < own ? decomposition_local[m.local[k].to_global[v]] : steiner_local[k][v - own];
  }
  // A point in assemble()'s numbering (as detail::MeshPiecesData::segments hold them).
  std::uint32_t local_of_global(const detail::MeshPiecesData& m, std::uint32_t g) const {
    if (g < decomposition_local.size()) return decomposition_local[g];
    const std::uint32_t k = m.subdomain_of_point(g);
    return steiner_local[k][g - m.first_point[k]];
  }
};

PartNumbering number_part(const detail::MeshPiecesData& m, const std::vector<std::uint32_t>& subdomains,
                          unsigned threads) {
  PartNumbering out;
  const std::size_t p = m.decomposition.points.size();
  // Per subdomain, which of its points its triangles use (on the threads),
  // then the decomposition's points gathered in subdomain order.
  std::vector<std::vector<std::uint8_t>> used(m.pieces.size());
  detail::for_each_on_threads(subdomains.size(), threads, [&](std::size_t i) {
    const std::uint32_t k = subdomains[i];
    used[k].assign(m.pieces[k].points.size(), 0);
    for (const auto& tri : m.pieces[k].triangles)
      for (const std::uint32_t v : tri) used[k][v] = 1;
  });
  std::vector<std::uint8_t> used_decomposition(p, 0);
  for (const std::uint32_t k : subdomains)
    for (std::size_t v = 0; v < m.local[k].to_global.size(); ++v)
      if (used[k][v] != 0) used_decomposition[m.local[k].to_global[v]] = 1;
  out.steiner_local.resize(m.pieces.size());
  for (const MeshSegment& g : m.segments)
    for (const std::uint32_t v : {g.a, g.b}) {
      if (v < p) {
        used_decomposition[v] = 1;
      } else {
        const std::uint32_t k = m.subdomain_of_point(v);
        used[k][v - m.first_point[k] + m.local[k].to_global.size()] = 1;
      }
    }
  out.decomposition_local.assign(p, no_index);
  for (std::uint32_t g = 0; g < p; ++g)
    if (used_decomposition[g] != 0) {
      out.decomposition_local[g] = out.count++;
      out.used_decomposition.push_back(g);
    }
  for (const std::uint32_t k : subdomains) {
    const std::size_t own = m.local[k].to_global.size();
    std::vector<std::uint32_t>& local = out.steiner_local[k];
    local.assign(m.pieces[k].points.size() - own, no_index);
    for (std::size_t v = own; v < m.pieces[k].points.size(); ++v)
      if (used[k][v] != 0) local[v - own] = out.count++;
  }
  return out;
}

// The share's part of the mesh made from its pieces, each copied on the
// threads into its ranges of the part's arrays and released: no merged copy
// of the share's mesh is made first. `first_steiner`, `first_triangle`: per
// subdomain, its first Steiner point (less the decomposition's points) and
// its first triangle in mesh()'s numbering (over every share's subdomains).
void fill_part(detail::MeshPiecesData&& m, const PartNumbering& numbering,
               const std::vector<std::uint64_t>& first_steiner, const std::vector<std::uint64_t>& first_triangle,
               const std::vector<std::uint32_t>& point_owner, unsigned threads, MeshPart& part) {
  LocalMesh& out = part.mesh;
  const std::size_t p = m.decomposition.points.size(), points = numbering.count;
  const std::uint32_t triangles = m.triangle_count();
  detail::resize_on_threads(out.points, points, threads);
  detail::resize_on_threads(out.point_markers, points, threads);
  for (const std::uint32_t g : numbering.used_decomposition) {
    const std::uint32_t v = numbering.decomposition_local[g];
    out.points[v] = m.decomposition.points[g];
    out.point_markers[v] = m.point_markers[g];
  }
  detail::resize_on_threads(out.triangles, triangles, threads);
  detail::resize_on_threads(out.neighbours, triangles, threads);
  detail::resize_on_threads(out.triangle_subdomain, triangles, threads);
  if (m.has_regions()) detail::assign_on_threads(out.triangle_attribute, triangles, 0.0, threads);  // 0: in no region
  detail::for_each_on_threads(part.subdomains.size(), threads, [&](std::size_t i) {
    const std::uint32_t k = part.subdomains[i];
    const detail::SubdomainMesh& piece = m.pieces[k];
    const std::size_t own = m.local[k].to_global.size();
    for (std::size_t v = own; v < piece.points.size(); ++v) {
      const std::uint32_t local = numbering.steiner_local[k][v - own];
      if (local == no_index) continue;
      out.points[local] = piece.points[v];
      out.point_markers[local] = m.steiner_marker(k, static_cast<std::uint32_t>(v));
    }
    const std::uint32_t base = m.first_triangle[k];
    for (std::uint32_t t = 0; t < piece.triangles.size(); ++t) {
      const auto& tri = piece.triangles[t];
      out.triangles[base + t] = {numbering.local_of(m, k, tri[0]), numbering.local_of(m, k, tri[1]),
                                 numbering.local_of(m, k, tri[2])};
      for (std::uint32_t e = 0; e < 3; ++e)
        out.neighbours[base + t][e] =
            piece.neighbours[t][e] == no_index ? m.global_neighbour(k, t, e) : base + piece.neighbours[t][e];
      out.triangle_subdomain[base + t] = k;
    }
    if (m.has_regions() && piece.triangle_attribute.size() == piece.triangles.size())
      std::copy(piece.triangle_attribute.begin(), piece.triangle_attribute.end(),
                out.triangle_attribute.begin() + base);
    m.pieces[k] = detail::SubdomainMesh{};  // released as it goes
  });
  // The pieces' memory back to the system before the ids take fresh pages:
  // the heap could not reuse it for them (scattered), and the peak would
  // be the pieces', the part's and the ids' (docs/mpi.md).
  detail::release_free_memory();
  // The global ids once the pieces are gone (the peak is then the pieces'
  // and the part's arrays, as a merge's).
  detail::resize_on_threads(part.point_ids, points, threads);
  detail::assign_on_threads(part.point_owner, points, part.share, threads);
  for (const std::uint32_t g : numbering.used_decomposition) {
    part.point_ids[numbering.decomposition_local[g]] = g;
    part.point_owner[numbering.decomposition_local[g]] = point_owner[g];
  }
  detail::resize_on_threads(part.triangle_ids, triangles, threads);
  detail::for_each_on_threads(part.subdomains.size(), threads, [&](std::size_t i) {
    const std::uint32_t k = part.subdomains[i];
    const std::vector<std::uint32_t>& steiner = numbering.steiner_local[k];
    for (std::size_t j = 0; j < steiner.size(); ++j)
      if (steiner[j] != no_index) part.point_ids[steiner[j]] = p + first_steiner[k] + j;
    for (std::uint32_t t = m.first_triangle[k]; t < m.first_triangle[k + 1]; ++t)
      part.triangle_ids[t] = first_triangle[k] + (t - m.first_triangle[k]);
  });
  out.segments = std::move(m.segments);
  for (MeshSegment& g : out.segments) {
    g.a = numbering.local_of_global(m, g.a);
    g.b = numbering.local_of_global(m, g.b);
  }
  out.subdomain_first_triangle = std::move(m.first_triangle);
  out.shortfall = m.shortfall;
  out.min_triangle_angle_deg = m.min_triangle_angle_deg;
  part.decomposition = std::move(m.decomposition);
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

  // The share's pieces numbered (assemble: each subdomain's own
  // decomposition points, its local domain, found once), then copied into
  // the part's arrays in its own numbering, each piece released once copied.
  const std::vector<std::uint32_t> point_owner = decomposition_point_owner(d, part.owner);
  detail::MeshPiecesData m = detail::assemble(std::move(d), std::move(pieces), options.size.min_triangle_angle_deg,
                                              &mine, options.decomposition.threads);
  // Steiner points and triangles of every subdomain, from every share: the
  // offsets mesh()'s numbering uses.
  std::vector<std::uint64_t> counts(2 * std::size_t{n}, 0);
  for (const std::uint32_t k : part.subdomains) {
    // The subdomain's own decomposition points (rings, interior pieces'
    // ends, isolated vertices) come first in its mesh; the rest are Steiner points.
    counts[k] = m.pieces[k].points.size() - m.local[k].to_global.size();
    counts[n + k] = m.pieces[k].triangles.size();
  }
  counts = exchange.sum_of(counts);
  std::uint64_t steiner_total = 0;
  const std::vector<std::uint64_t> first_steiner = exclusive_sums(counts, 0, n, steiner_total);
  const std::vector<std::uint64_t> first_triangle = exclusive_sums(counts, n, n, part.total_triangles);
  part.total_points = m.decomposition.points.size() + steiner_total;
  const PartNumbering numbering = number_part(m, part.subdomains, options.decomposition.threads);
  fill_part(std::move(m), numbering, first_steiner, first_triangle, point_owner, options.decomposition.threads, part);
  report.phases.push_back({"assemble", clock.lap()});
  return run;
}

}  // namespace madd
