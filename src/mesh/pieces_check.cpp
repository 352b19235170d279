// verify_mesh for a mesh kept in pieces (mesh/pieces_check.hpp).
#include "mesh/pieces_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <string>
#include <unordered_map>
#include <utility>

#include "kernel/exact_sum.hpp"
#include "kernel/threads.hpp"
#include "mesh/subdomain_check.hpp"
#include "kernel/number_format.hpp"
#include "mesh/pieces_view.hpp"
#include "quality/mesh_regions.hpp"
#include "quality/parallel_log.hpp"
#include "quality/verify_mesh_detail.hpp"
#include "kernel/edge_key.hpp"

namespace madd::detail {

namespace {

std::string piece_triangle_text(std::uint32_t k, std::uint32_t t) {
  return "triangle " + std::to_string(t) + " of subdomain " + std::to_string(k);
}

// Sizes and offsets: a piece per subdomain, each numbered by the prefix sums
// of the pieces before it. Everything after relies on these.
bool check_placement(const MeshPiecesData& m, ProblemLog& log, unsigned threads) {
  const Decomposition& d = m.decomposition;
  const std::size_t n = d.subdomains.size();
  if (m.pieces.size() != n || m.local.size() != n || m.across.size() != n || m.first_point.size() != n + 1 ||
      m.first_triangle.size() != n + 1 || m.point_markers.size() != d.points.size()) {
    log.add("the pieces do not match the decomposition's " + std::to_string(n) + " subdomains and " +
            std::to_string(d.points.size()) + " points");
    return false;
  }
  const std::size_t before = log.count();
  std::uint64_t points = d.points.size(), triangles = 0;
  for (std::uint32_t k = 0; k < n; ++k) {
    const SubdomainMesh& p = m.pieces[k];
    const std::size_t own = m.local[k].to_global.size();
    if (m.first_point[k] != points || m.first_triangle[k] != triangles)
      log.add("subdomain " + std::to_string(k) + " is placed at point " + std::to_string(m.first_point[k]) +
              " and triangle " + std::to_string(m.first_triangle[k]) + ", expected " + std::to_string(points) +
              " and " + std::to_string(triangles));
    if (p.points.size() < own || p.point_segment.size() != p.points.size() ||
        p.neighbours.size() != p.triangles.size()) {
      log.add("subdomain " + std::to_string(k) + "'s piece has " + std::to_string(p.points.size()) +
              " points for its " + std::to_string(own) + " decomposition points, or arrays of unequal sizes");
      continue;
    }
    for (const std::uint32_t g : m.local[k].to_global)
      if (g >= d.points.size())
        log.add("subdomain " + std::to_string(k) + " names decomposition point " + std::to_string(g) +
                ", which does not exist");
    points += p.points.size() - own;
    triangles += p.triangles.size();
  }
  MeshShortfall sum;
  for (const SubdomainMesh& p : m.pieces) {
    sum.input_angle += p.shortfall.input_angle;
    sum.separator += p.shortfall.separator;
    sum.precision += p.shortfall.precision;
    sum.limit += p.shortfall.limit;
  }
  if (sum != m.shortfall)
    log.add("the mesh counts " + std::to_string(m.shortfall.total()) + " triangles below the angle bound, its pieces " +
            std::to_string(sum.total()));
  // Each piece's own points are the decomposition's points its local view
  // names (what the files number them by), as local_domain lists them.
  std::vector<std::uint8_t> renamed(n, 0);
  for_each_on_threads(n, threads, [&](std::size_t k) {
    renamed[k] = local_domain(d, static_cast<std::uint32_t>(k)).to_global != m.local[k].to_global ? 1 : 0;
  });
  for (std::uint32_t k = 0; k < n; ++k)
    if (renamed[k] != 0)
      log.add("subdomain " + std::to_string(k) +
              "'s piece names other decomposition points than the subdomain's rings and constraints");
  if (m.first_point[n] != points || m.first_triangle[n] != triangles)
    log.add("the pieces are numbered to " + std::to_string(m.first_point[n]) + " points and " +
            std::to_string(m.first_triangle[n]) + " triangles, but hold " + std::to_string(points) + " and " +
            std::to_string(triangles));
  return log.count() == before;
}

// Each link across a separator: from a free edge of one piece lying on a
// separator to a triangle of another piece with the same edge reversed that
// links back; every separator matched by exactly two such sides.
void check_separator_links(const MeshPiecesData& m, ProblemLog& log) {
  const Decomposition& d = m.decomposition;
  std::unordered_map<std::uint64_t, std::uint32_t> separator_of;
  for (std::uint32_t j = 0; j < d.segments.size(); ++j)
    if (d.is_separator(j)) separator_of.emplace(edge_key(d.segments[j].a, d.segments[j].b), j);
  std::vector<std::uint32_t> sides(d.segments.size(), 0);
  const auto edge_of = [&](std::uint32_t k, std::uint32_t t, std::uint32_t i) {
    const auto& c = m.pieces[k].triangles[t];
    return std::pair{m.global_point(k, c[(i + 1) % 3]), m.global_point(k, c[(i + 2) % 3])};
  };
  for (std::uint32_t k = 0; k < m.pieces.size(); ++k)
    for (const auto& [code, u] : m.across[k]) {
      const std::uint32_t t = code / 3, i = code % 3;
      if (t >= m.pieces[k].triangles.size()) {
        log.add("subdomain " + std::to_string(k) + " links its triangle " + std::to_string(t) +
                " across a separator, but has " + std::to_string(m.pieces[k].triangles.size()) + " triangles");
        continue;
      }
      const auto [a, b] = edge_of(k, t, i);
      const std::string edge =
          "edge " + std::to_string(a) + "-" + std::to_string(b) + " of " + piece_triangle_text(k, t);
      if (m.pieces[k].neighbours[t][i] != no_index) log.add(edge + " is linked within its subdomain and across");
      const auto on = separator_of.find(edge_key(a, b));
      if (on == separator_of.end()) {
        log.add(edge + " is linked to another subdomain but lies on no separator");
        continue;
      }
      ++sides[on->second];
      if (u >= m.triangle_count()) {
        log.add(edge + " is linked to triangle " + std::to_string(u) + ", which does not exist");
        continue;
      }
      const std::uint32_t h = m.subdomain_of_triangle(u), tu = u - m.first_triangle[h];
      bool back = false;
      for (std::uint32_t j = 0; j < 3 && h != k; ++j) {
        const auto& list = m.across[h];
        const auto it = std::lower_bound(list.begin(), list.end(), std::pair{3 * tu + j, std::uint32_t{0}});
        if (it != list.end() && it->first == 3 * tu + j && it->second == m.first_triangle[k] + t &&
            edge_of(h, tu, j) == std::pair{b, a})
          back = true;
      }
      if (!back)
        log.add(edge + " is linked to " + piece_triangle_text(h, tu) +
                ", which does not have the edge reversed linked back to it");
    }
  for (std::uint32_t j = 0; j < d.segments.size(); ++j)
    if (d.is_separator(j) && sides[j] != 2)
      log.add("separator " + std::to_string(j) + " is matched by " + std::to_string(sides[j]) +
              " triangle sides, expected one in each of its two subdomains");
}

// The mesh's segments as a Mesh of no triangles: the decomposition's points,
// then the Steiner points on segments, so that check_mesh_segments walks the
// chains the files' numbering gives (with ids of its own, in the same order).
Mesh segment_mesh(const MeshPiecesData& m) {
  Mesh b;
  b.decomposition = m.decomposition;
  b.points = m.decomposition.points;
  b.point_markers = m.point_markers;
  std::unordered_map<std::uint32_t, std::uint32_t> compact;  // global Steiner point -> its id here
  for (std::uint32_t k = 0; k < m.pieces.size(); ++k) {
    const SubdomainMesh& p = m.pieces[k];
    for (auto v = static_cast<std::uint32_t>(m.local[k].to_global.size()); v < p.points.size(); ++v)
      if (p.point_segment[v] != no_index) {
        compact.emplace(m.global_point(k, v), static_cast<std::uint32_t>(b.points.size()));
        b.points.push_back(p.points[v]);
        b.point_markers.push_back(m.steiner_marker(k, v));
      }
  }
  const auto id = [&](std::uint32_t g) { return g < m.decomposition.points.size() ? g : compact.at(g); };
  b.segments = m.segments;
  for (MeshSegment& s : b.segments) {
    s.a = id(s.a);
    s.b = id(s.b);
  }
  return b;
}

// Twice the area of all the pieces, exactly: the sum of x_a y_b - x_b y_a
// over the free edges a -> b not on a separator (a separator's two sides
// cancel, and within a piece its own links do).
ExactSum twice_area(const MeshPiecesData& m, unsigned threads) {
  std::vector<ExactSum> of(m.pieces.size());
  for_each_on_threads(m.pieces.size(), threads, [&](std::size_t i) {
    const auto k = static_cast<std::uint32_t>(i);
    const SubdomainMesh& p = m.pieces[k];
    const LocalDomain& local = m.local[k];
    const auto at = [&](std::uint32_t v) {
      return v < local.to_global.size() ? m.decomposition.points[local.to_global[v]] : p.points[v];
    };
    for (std::uint32_t t = 0; t < p.triangles.size(); ++t)
      for (std::uint32_t e = 0; e < 3; ++e)
        if (p.neighbours[t][e] == no_index && m.global_neighbour(k, t, e) == no_index)
          of[k].add_cross(at(p.triangles[t][(e + 1) % 3]), at(p.triangles[t][(e + 2) % 3]));
  });
  ExactSum sum;
  for (const ExactSum& s : of) sum.add(s);
  return sum;
}

// "triangle t (subdomain k) (x, y) (x, y) (x, y)" in the merged mesh's
// numbering, as verify_mesh names a triangle.
std::string merged_triangle_text(const PiecesView& view, std::uint32_t t) {
  std::string text =
      "triangle " + std::to_string(t) + " (subdomain " + std::to_string(view.triangle_subdomain[t]) + ")";
  for (const std::uint32_t v : view.triangles[t]) text.append(" ").append(point_text(view.points[v]));
  return text;
}

// The regions flooded over the whole mesh, across the separators (each
// subdomain's check floods only its own triangles, from the regions the
// decomposition gives it): every triangle's attribute, and its region's
// area bound (Region::max_area > 0), as verify_mesh checks them.
void check_regions(const MeshPiecesData& m, ProblemLog& log, unsigned threads) {
  if (!m.has_regions()) return;
  const PiecesView view(m);
  const std::vector<std::uint32_t> label = mesh_regions_of(view, threads);
  const auto text = [&view](std::uint32_t t) { return merged_triangle_text(view, t); };
  check_region_attributes_of(view, label, log, threads, text);
  const std::vector<Region>& regions = m.decomposition.regions;
  constexpr double u = 0x1p-53;
  const std::size_t n = view.triangle_count();
  log_in_parts(n, 4 * std::size_t{thread_count(threads, n)}, threads, log,
               [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& mine) {
                 for (auto t = static_cast<std::uint32_t>(begin); t < end; ++t) {
                   if (label[t] == 0 || !(regions[label[t] - 1].max_area > 0)) continue;
                   const double bound = regions[label[t] - 1].max_area;
                   const std::array<std::uint32_t, 3> c = view.triangles[t];
                   const Point a = view.points[c[0]], ab = view.points[c[1]] - a, ac = view.points[c[2]] - a;
                   const Point bc = ac - ab;
                   const double twice = std::abs(cross(ab, ac));
                   const double longest2 = std::max({dot(ab, ab), dot(ac, ac), dot(bc, bc)});
                   if (twice > 2.0 * bound * (1.0 + 1e-12) + 32.0 * u * longest2)
                     mine.add(text(t) + " has area " + number_text(0.5 * twice) + ", above the area bound " +
                              number_text(bound) + " of region " + std::to_string(label[t] - 1));
                 }
               });
}

}  // namespace

Verification verify_pieces(const MeshPiecesData& m, const Pslg& domain, const AreaBound& field, bool pieces_checked,
                           unsigned threads) {
  Verification result;
  ProblemLog log(result);
  try {
    if (check_placement(m, log, threads)) {
      if (!pieces_checked) {
        std::vector<Verification> found(m.pieces.size());
        for_each_on_threads(m.pieces.size(), threads, [&](std::size_t k) {
          found[k] = check_subdomain(m.decomposition, static_cast<std::uint32_t>(k), {}, m.pieces[k],
                                     m.min_triangle_angle_deg, field);
        });
        for (Verification& v : found) log.absorb(std::move(v.problems), v.problems.size());
      }
      check_separator_links(m, log);
      const double sliver = check_mesh_segments(segment_mesh(m), domain, log, threads);
      check_cover(twice_area(m, threads), domain, sliver, log);
      check_regions(m, log, threads);
    }
  } catch (const std::exception& e) {
    log.add(std::string("the check stopped: ") + e.what());
  }
  log.finish();
  return result;
}

}  // namespace madd::detail
