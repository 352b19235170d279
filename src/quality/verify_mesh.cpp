// verify_mesh(): recomputes every invariant of a mesh (include/madd/mesh.hpp,
// docs/quality.md "verify_mesh") from the mesh, its decomposition and the
// input domain, sharing no code with the mesher. The shape of the arrays is
// checked here first, then each concern in its own file:
// verify_mesh_edges.cpp (adjacency, conformity, Delaunay, the exact area),
// verify_mesh_segments.cpp (chains along the decomposition and the input),
// verify_mesh_hanging.cpp, verify_mesh_regions.cpp (isolated vertices, region
// attributes), verify_mesh_quality.cpp (size and angles).
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <string>

#include "kernel/number_format.hpp"
#include "madd/mesh.hpp"
#include "kernel/threads.hpp"
#include "madd/predicates.hpp"
#include "quality/area_bound.hpp"
#include "quality/parallel_log.hpp"
#include "quality/verify_mesh_bounded.hpp"
#include "quality/verify_mesh_detail.hpp"
#include "triangulation/exact_area.hpp"

namespace madd {

namespace detail {

std::string mesh_triangle_text(const Mesh& mesh, std::uint32_t t) {
  std::string text = "triangle " + std::to_string(t);
  if (t < mesh.triangle_subdomain.size()) text += " (subdomain " + std::to_string(mesh.triangle_subdomain[t]) + ")";
  if (t < mesh.triangles.size())
    for (const std::uint32_t v : mesh.triangles[t]) {
      text += ' ';
      if (v < mesh.points.size()) {
        text += point_text(mesh.points[v]);
      } else {
        text += "(vertex ";
        text += std::to_string(v);
        text += ')';
      }
    }
  return text;
}

// Full cover: twice the triangles' area against twice the domain's, both
// exact. A correct mesh can differ only by the area between its boundary
// chains and the input segments (the rounding of its boundary vertices),
// which check_mesh_segments bounds from their exact distances (`sliver`, 0
// when every boundary vertex lies exactly on its segment). With the
// orientation, adjacency and boundary checks this rules out any gap or
// overlap: the triangles, all counter-clockwise and glued edge to edge, cover
// each point as many times as their free edges (exactly the boundary chains)
// wind around it, and a boundary ring walked the wrong way changes the area
// by twice its own.
void check_cover(const ExactSum& triangles, const Pslg& domain, double sliver, ProblemLog& log) {
  const ExactSum whole = domain_twice_area_exact(domain);
  ExactSum difference = triangles;
  difference.subtract(whole);
  if (difference.magnitude_at_most(sliver)) return;
  log.add("the triangles' areas add up to " + number_text(0.5 * triangles.approximate()) + " but the domain's is " +
          number_text(0.5 * whole.approximate()) + ": a gap or an overlap (they differ by " +
          number_text(0.5 * difference.approximate()) + ", more than the " + number_text(0.5 * sliver) +
          " the rounding of boundary vertices can account for)");
}

}  // namespace detail

namespace {

using detail::ProblemLog;

// Sizes, offsets and index ranges: everything after relies on these, so a
// failure here ends the check.
bool check_mesh_shape(const Mesh& m, const Pslg& domain, ProblemLog& log, unsigned threads) {
  const std::size_t before = log.count();
  const Decomposition& d = m.decomposition;
  const std::size_t np = m.points.size(), nt = m.triangles.size();
  if (m.point_markers.size() != np)
    log.add("point_markers has " + std::to_string(m.point_markers.size()) + " entries for " + std::to_string(np) +
            " points");
  const std::size_t parts = 4 * std::size_t{detail::thread_count(threads, nt)};
  detail::log_in_parts(np, parts, threads, log, [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& mine) {
    for (std::size_t p = begin; p < end; ++p)
      if (!std::isfinite(m.points[p].x) || !std::isfinite(m.points[p].y))
        mine.add("point " + std::to_string(p) + " " + detail::point_text(m.points[p]) + " is not finite");
  });
  // Indices are 32 bits, no_index reserved.
  if (nt >= no_index) log.add(std::to_string(nt) + " triangles: more than 32-bit indices can number");
  if (m.neighbours.size() != nt || m.triangle_subdomain.size() != nt)
    log.add("triangles, neighbours and triangle_subdomain differ in size (" + std::to_string(nt) + ", " +
            std::to_string(m.neighbours.size()) + ", " + std::to_string(m.triangle_subdomain.size()) + ")");
  detail::log_in_parts(nt, parts, threads, log, [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& mine) {
    for (auto t = static_cast<std::uint32_t>(begin); t < end; ++t)
      for (int i = 0; i < 3; ++i) {
        if (m.triangles[t][i] >= np)
          mine.add("triangle " + std::to_string(t) + " has vertex " + std::to_string(m.triangles[t][i]) +
                   ", out of range");
        if (t < m.neighbours.size() && m.neighbours[t][i] != no_index && m.neighbours[t][i] >= nt)
          mine.add("triangle " + std::to_string(t) + " has neighbour " + std::to_string(m.neighbours[t][i]) +
                   ", out of range");
      }
  });
  // Subdomain ranges: N + 1 non-decreasing offsets from 0 to the triangle
  // count, N the decomposition's subdomain count, matching triangle_subdomain.
  const std::size_t n = d.subdomains.size();
  const auto& first = m.subdomain_first_triangle;
  if (first.size() != n + 1) {
    log.add("subdomain_first_triangle has " + std::to_string(first.size()) + " offsets for " + std::to_string(n) +
            " subdomains (expected N + 1)");
  } else if (first.front() != 0 || first.back() != nt) {
    log.add("subdomain_first_triangle runs from " + std::to_string(first.front()) + " to " +
            std::to_string(first.back()) + " instead of 0 to the triangle count " + std::to_string(nt));
  } else {
    for (std::uint32_t k = 0; k < n; ++k) {
      if (first[k] > first[k + 1]) {
        log.add("subdomain_first_triangle decreases at subdomain " + std::to_string(k));
        continue;
      }
      for (std::uint32_t t = first[k]; t < first[k + 1] && t < m.triangle_subdomain.size(); ++t)
        if (m.triangle_subdomain[t] != k)
          log.add("triangle " + std::to_string(t) + " is in the range of subdomain " + std::to_string(k) +
                  " but triangle_subdomain says " + std::to_string(m.triangle_subdomain[t]));
    }
  }
  // The decomposition and the input: their points are the mesh's first ones.
  if (d.points.size() > np || !std::equal(d.points.begin(), d.points.end(), m.points.begin()))
    log.add("the decomposition's points are not the mesh's first points, with the same indices");
  if (domain.points.size() > d.points.size() ||
      !std::equal(domain.points.begin(), domain.points.end(), d.points.begin()))
    log.add("the input points are not the decomposition's first points, with the same indices");
  for (std::size_t s = 0; s < domain.segments.size(); ++s)
    if (domain.segments[s].a >= domain.points.size() || domain.segments[s].b >= domain.points.size())
      log.add("input segment " + std::to_string(s) + " has an endpoint out of range");
  if (d.segment_origin.size() != d.segments.size())
    log.add("the decomposition's segment_origin and segments differ in size");
  for (std::size_t j = 0; j < d.segments.size(); ++j) {
    const Segment& g = d.segments[j];
    if (g.a >= d.points.size() || g.b >= d.points.size() || g.a == g.b)
      log.add("decomposition segment " + std::to_string(j) + " has bad endpoints");
    if (j < d.segment_origin.size() && d.segment_origin[j] != no_index && d.segment_origin[j] >= domain.segments.size())
      log.add("decomposition segment " + std::to_string(j) + " comes from a nonexistent input segment");
  }
  for (std::uint32_t k = 0; k < n; ++k) {
    for (const std::uint32_t j : d.subdomains[k].interior_segments)
      if (j >= d.segments.size() || j >= d.segment_origin.size() || d.segment_origin[j] == no_index)
        log.add("subdomain " + std::to_string(k) + " names interior segment " + std::to_string(j) +
                ", which is no piece of an input segment");
    for (const std::uint32_t v : d.subdomains[k].interior_points)
      if (v >= d.points.size())
        log.add("subdomain " + std::to_string(k) + " names isolated vertex " + std::to_string(v) + ", out of range");
  }
  for (std::size_t s = 0; s < m.segments.size(); ++s) {
    const MeshSegment& g = m.segments[s];
    if (g.a >= np || g.b >= np || g.a == g.b)
      log.add("mesh segment " + std::to_string(s) + " has bad endpoints " + std::to_string(g.a) + "-" +
              std::to_string(g.b));
    if (g.piece >= d.segments.size())
      log.add("mesh segment " + std::to_string(s) + " lies on decomposition segment " + std::to_string(g.piece) +
              ", which does not exist");
  }
  return log.count() == before;
}

// One region attribute per triangle with regions, none without; no other
// check indexes them, so a wrong count only skips the attribute check.
bool attributes_sized(const Mesh& m, ProblemLog& log) {
  const std::size_t nt = m.triangles.size(), na = m.triangle_attribute.size();
  const bool regions = !m.decomposition.regions.empty();
  if (regions ? na == nt : na == 0) return true;
  log.add("triangle_attribute has " + std::to_string(na) + " entries for " + std::to_string(nt) +
          " triangles (expected " + (regions ? "one each" : "none: the input has no regions") + ")");
  return false;
}

// Strictly counter-clockwise, decided exactly; a repeated or collinear
// vertex fails too. Returns the flags the in-circle test needs.
std::vector<std::uint8_t> check_orientation(const Mesh& m, ProblemLog& log, unsigned threads) {
  std::vector<std::uint8_t> ccw(m.triangles.size(), 0);
  const std::size_t parts = 4 * std::size_t{detail::thread_count(threads, m.triangles.size())};
  detail::log_in_parts(m.triangles.size(), parts, threads, log,
                       [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& part_log) {
                         for (auto t = static_cast<std::uint32_t>(begin); t < end; ++t) {
                           const auto& c = m.triangles[t];
                           const double o = orient2d(m.points[c[0]], m.points[c[1]], m.points[c[2]]);
                           ccw[t] = o > 0.0 ? 1 : 0;
                           if (ccw[t] == 0)
                             part_log.add(
                                 detail::mesh_triangle_text(m, t) +
                                 (o < 0.0 ? " is clockwise" : " is degenerate (collinear or repeated vertices)"));
                         }
                       });
  return ccw;
}

}  // namespace

Verification verify_mesh(const Mesh& mesh, const Pslg& domain, const MeshSizeOptions& size) {
  // Building the size field may refuse its options (coast markers the
  // domain lacks...): a problem to report, like any other.
  std::optional<detail::AreaBound> bound;
  try {
    bound.emplace(size, &domain);
  } catch (const std::exception& e) {
    Verification result;
    ProblemLog log(result);
    log.add(std::string("the size bound could not be built: ") + e.what());
    log.finish();
    return result;
  }
  return detail::verify_mesh(mesh, domain, *bound);
}

Verification detail::verify_mesh(const Mesh& mesh, const Pslg& domain, const AreaBound& bound, unsigned threads) {
  Verification result;
  ProblemLog log(result);
  // Nothing here may escape: the contract is a report, never an exception
  // (the only one possible is std::bad_alloc, or one thrown by the user's
  // area function; both become a problem).
  try {
    if (check_mesh_shape(mesh, domain, log, threads)) {
      const std::vector<std::uint8_t> ccw = check_orientation(mesh, log, threads);
      const detail::MeshEdges edges = detail::check_mesh_edges(mesh, ccw, log, threads);
      const double sliver = detail::check_mesh_segments(mesh, domain, log, threads);
      detail::check_hanging_vertices(mesh, edges.boundary, log, threads);
      detail::check_cover(edges.twice_area, domain, sliver, log);
      detail::check_interior_points(mesh, log, threads);
      const std::vector<std::uint32_t> region = detail::mesh_regions(mesh, threads);
      if (attributes_sized(mesh, log)) detail::check_region_attributes(mesh, region, log, threads);
      detail::check_mesh_size(mesh, bound, region, log, threads);
      detail::check_mesh_angles(mesh, log, threads);
    }
  } catch (const std::exception& e) {
    log.add(std::string("the check stopped: ") + e.what());
  }
  log.finish();
  return result;
}

}  // namespace madd
