// libFuzzer target: .poly text -> parse -> validate -> mesh (decompose,
// discretise, refine, merge, and mesh()'s own verify_mesh self-check), then
// properties checked here independently of verify_mesh: every triangle
// strictly counter-clockwise, the shortfall equal to the number of triangles
// below the angle bound (the one measure, src/quality/mesh_angle.hpp), the
// mesh the same on 2 threads as on 1, and the same kept in pieces and
// checked there (madd mesh's path, include/madd/mesh_pieces.hpp), joined.
//
// Options come from the last five bytes, which stay part of the text (a
// newline, a digit, or the end of a trailing '#' comment), so plain .poly
// seeds work unchanged. All combinations occur among printable characters:
//   last byte % 50:        N = {5, 1, 2, 3, 8}[v % 5], -q = {0, 20, 30, 25, 33}[v / 5 % 5],
//                          threads = 1 + v / 25 % 2
//   last but one % 48:     max area = domain area x {0 (none), 1/50, 1/500, 1/3000}[v % 4],
//                          Phi0 = {45, 70, 60}[v / 4 % 3], off-centres off if v / 12 % 2,
//                          balance by work off if v / 24 % 2
// (a file ending in "\n\n": N = 5, -q 30, 1 thread, area / 500, Phi0 60, both on).
// The three bytes before them draw the size field (docs/mesh.md), in edge
// lengths relative to the domain's extent E (the larger side of its bounding
// box), bounded so that a run stays fast:
//   5th from last % 3:     0: no size field (the run is as it was before the field)
//   3rd from last % 48:    distance rate = {0, 0.1, 0.3, 1}[v % 4], cells across = {0, 1, 3, 8}[v / 4 % 4],
//                          hmin = E x {1/200, 1/40, 1/10}[v / 16 % 3] when either is on (else 0)
//   4th from last % 48:    gradation = {0, 0.1, 0.3, 1}[v % 4], hmax = E x {0, 1/10, 1/3, 1}[v / 4 % 4]
//                          (at least hmin), coast = {every segment, the smallest marker, the
//                          largest}[v / 16 % 3] of the segments' markers
// A gradation with nothing to grade is refused (OptionError), an expected outcome.
//
// Each run stays small: at most 300 vertices, and the triangle count a
// domain asks for at most ~20k, estimated as the larger of area / max area
// and (4 x the boundary pieces the decoupling will cut, each segment split
// to half its local feature size or 1.18 sqrt(max area), src/mesh/discretise.cpp,
// here from 17 samples per segment; plus 20 / alpha for every two segments
// meeting at an angle alpha < 60 degrees, in radians: the refined layers
// along a sharp wedge, whose width there sets the triangle size). Both terms
// come from the first campaign's slow inputs (docs/hostile.md, Issue 14): a
// sliver 1e-7 wide and 0.05 long in a unit domain needs ~1e6 pieces however
// round the domain is, and a 0.02 degree spike 5 long on a unit square gets
// 30k to 140k triangles with or without an area bound. With a size field the
// estimate takes the larger of that and twice the field's own count (twice:
// refined triangles are smaller than their bound): A / (sqrt(3)/4 hmax^2); a
// coastal band of h = hmin + G d, integrated out from the segments' total
// length P, P / (sqrt(3)/4 G hmin) for the distance rate and for the gradation
// (which grows the field from its smallest value, hmin, no faster); about
// R^2 / 1.7 triangles per boundary piece for R cells across (a channel of
// half-width w has pieces of about w, and triangles of side 2w / R); none
// finer than hmin everywhere, A / (sqrt(3)/4 hmin^2). The decomposition
// has a 2 s time limit; the mesher has no time limit of its own. Only
// madd::Error other than InternalError may escape: OptionError, DecompositionError and LimitError
// are expected outcomes for hostile inputs; an InternalError (the self-check
// failed), a failed property here, a crash or a hang is a finding and aborts.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string_view>
#include <vector>

#include "madd/error.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_pieces.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "mesh/feature_distance.hpp"
#include "quality/mesh_angle.hpp"

namespace {

// About how many pieces discretise() cuts the input boundary into: the
// integral of 1 / h along every segment, h = min(0.5 lfs, 1.18 sqrt(max_area)).
double boundary_pieces(const madd::Pslg& p, double max_area) {
  const madd::detail::FeatureDistance features(p.points, p.segments);
  double pieces = 0.0;
  for (std::uint32_t j = 0; j < p.segments.size(); ++j) {
    const madd::Point a = p.points[p.segments[j].a], b = p.points[p.segments[j].b];
    double sum = 0.0;
    for (int i = 0; i <= 16; ++i) {
      double h = 0.5 * features.to_nonincident(madd::lerp(a, b, i / 16.0), p.segments[j].a, p.segments[j].b);
      if (max_area > 0) h = std::min(h, 1.18 * std::sqrt(max_area));
      sum += h > 0 ? 1.0 / h : 0.0;
    }
    pieces += madd::distance(a, b) * sum / 17.0;
  }
  return pieces;
}

// About how many triangles the sharp corners add: 20 / alpha for every two
// segments meeting at an angle alpha below 60 degrees (either side of them
// may be the domain's; a sharp notch is counted too).
double sharp_corner_triangles(const madd::Pslg& p) {
  std::vector<std::vector<std::uint32_t>> around(p.points.size());
  for (const madd::Segment& s : p.segments) {
    around[s.a].push_back(s.b);
    around[s.b].push_back(s.a);
  }
  double triangles = 0.0;
  for (std::size_t v = 0; v < around.size(); ++v)
    for (std::size_t i = 0; i < around[v].size(); ++i)
      for (std::size_t j = i + 1; j < around[v].size(); ++j) {
        const double alpha = madd::angle_at(p.points[v], p.points[around[v][i]], p.points[around[v][j]]);
        if (alpha < std::numbers::pi / 3) triangles += 20.0 / std::max(alpha, 1e-300);
      }
  return triangles;
}

// The size field drawn from the three bytes before the last two (see the top);
// nothing when they say none.
void draw_size_field(const madd::Pslg& p, unsigned k3, unsigned k4, unsigned k5, madd::MeshSizeOptions& size) {
  if (k5 % 3 == 0 || p.points.empty()) return;
  double low_x = p.points[0].x, high_x = low_x, low_y = p.points[0].y, high_y = low_y;
  for (const madd::Point& q : p.points) {
    low_x = std::min(low_x, q.x), high_x = std::max(high_x, q.x);
    low_y = std::min(low_y, q.y), high_y = std::max(high_y, q.y);
  }
  const double extent = std::max(high_x - low_x, high_y - low_y);
  constexpr double rates[] = {0.0, 0.1, 0.3, 1.0};
  constexpr double cells[] = {0.0, 1.0, 3.0, 8.0};
  constexpr double hmin_fractions[] = {1.0 / 200, 1.0 / 40, 1.0 / 10};
  constexpr double hmax_fractions[] = {0.0, 1.0 / 10, 1.0 / 3, 1.0};
  size.distance_rate = rates[k3 % 4];
  size.cells_across = cells[k3 / 4 % 4];
  if (size.distance_rate > 0 || size.cells_across > 0) size.min_edge_length = extent * hmin_fractions[k3 / 16 % 3];
  size.size_gradation = rates[k4 % 4];
  size.max_edge_length = extent * hmax_fractions[k4 / 4 % 4];
  if (size.max_edge_length > 0) size.max_edge_length = std::max(size.max_edge_length, size.min_edge_length);
  int smallest = 0, largest = 0;
  for (std::size_t j = 0; j < p.segments.size(); ++j) {
    const int m = p.segments[j].marker;
    smallest = j == 0 ? m : std::min(smallest, m);
    largest = j == 0 ? m : std::max(largest, m);
  }
  if (k4 / 16 % 3 == 1) size.coast_markers = {smallest};
  if (k4 / 16 % 3 == 2) size.coast_markers = {largest};
}

// About how many triangles the size field asks for (see the top); 0 without one.
double field_triangles(const madd::Pslg& p, const madd::MeshSizeOptions& size, double area) {
  const auto triangles_of_edge = [area](double h) { return area / (0.4330127018922193 * h * h); };
  double length = 0.0;
  for (const madd::Segment& s : p.segments) length += madd::distance(p.points[s.a], p.points[s.b]);
  const double hmin = size.min_edge_length;
  double t = size.max_edge_length > 0 ? triangles_of_edge(size.max_edge_length) : 0.0;
  for (const double growth : {size.distance_rate, size.size_gradation})
    if (growth > 0 && hmin > 0) t = std::max(t, length / (0.4330127018922193 * growth * hmin));
  if (size.cells_across > 0) t = std::max(t, boundary_pieces(p, 0.0) * size.cells_across * size.cells_across / 1.7);
  if (hmin > 0) t = std::min(t, triangles_of_edge(hmin));
  return 2.0 * t;
}

[[noreturn]] void fail(const madd::MeshOptions& o, const char* what) {
  const madd::MeshSizeOptions& s = o.size;
  std::fprintf(stderr,
               "fuzz_mesh (N=%u, q=%g, max_area=%g, Phi0=%g, threads=%u, off_centres=%d, balance_by_work=%d, "
               "hmin=%g, hmax=%g, distance_rate=%g, cells_across=%g, gradation=%g, coast markers %zu: %d): %s\n",
               o.decomposition.subdomains, s.min_triangle_angle_deg, s.max_triangle_area,
               o.decomposition.separator_angle_deg, o.decomposition.threads, o.off_centres ? 1 : 0,
               o.balance_by_work ? 1 : 0, s.min_edge_length, s.max_edge_length, s.distance_rate, s.cells_across,
               s.size_gradation, s.coast_markers.size(), s.coast_markers.empty() ? 0 : s.coast_markers[0], what);
  std::abort();
}

void check_properties(const madd::Mesh& m, const madd::MeshOptions& o) {
  std::size_t below = 0;
  for (const auto& t : m.triangles) {
    const madd::Point a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
    if (!(madd::orient2d(a, b, c) > 0)) fail(o, "a triangle is not strictly counter-clockwise");
    if (madd::detail::smallest_angle_deg(a, b, c) < o.size.min_triangle_angle_deg - madd::detail::mesh_angle_slack_deg)
      ++below;
  }
  if (below != m.shortfall.total()) {
    std::fprintf(stderr, "%zu triangles below the bound, shortfall total %zu\n", below, m.shortfall.total());
    fail(o, "the shortfall does not count the triangles below the angle bound");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const unsigned k1 = data[size - 1] % 50u;
  const unsigned k2 = (size >= 2 ? data[size - 2] : '\n') % 48u;
  const unsigned k3 = (size >= 3 ? data[size - 3] : '\n') % 48u;
  const unsigned k4 = (size >= 4 ? data[size - 4] : '\n') % 48u;
  const unsigned k5 = (size >= 5 ? data[size - 5] : '\n') % 3u;
  constexpr std::uint32_t subdomains[] = {5, 1, 2, 3, 8};
  constexpr double min_angles[] = {0.0, 20.0, 30.0, 25.0, 33.0};
  constexpr double area_fractions[] = {0.0, 1.0 / 50, 1.0 / 500, 1.0 / 3000};
  constexpr double phi0[] = {45.0, 70.0, 60.0};
  madd::MeshOptions options;
  options.decomposition.subdomains = subdomains[k1 % 5];
  options.size.min_triangle_angle_deg = min_angles[k1 / 5 % 5];
  options.decomposition.threads = 1 + k1 / 25 % 2;
  options.decomposition.separator_angle_deg = phi0[k2 / 4 % 3];
  options.off_centres = k2 / 12 % 2 == 0;
  options.balance_by_work = k2 / 24 % 2 == 0;
  options.decomposition.time_limit_seconds = 2.0;
  try {
    const madd::PolyFile file = madd::parse_poly(text, "fuzz.poly");
    if (file.pslg.points.size() > 300) return 0;
    madd::validate(file.pslg, file.source);
    const double area = madd::domain_area(file.pslg);
    options.size.max_triangle_area = area * area_fractions[k2 % 4];
    if (!std::isfinite(options.size.max_triangle_area)) return 0;
    draw_size_field(file.pslg, k3, k4, k5, options.size);
    const double wanted =
        std::max({options.size.max_triangle_area > 0 ? area / options.size.max_triangle_area : 0.0,
                  4.0 * boundary_pieces(file.pslg, options.size.max_triangle_area) + sharp_corner_triangles(file.pslg),
                  field_triangles(file.pslg, options.size, area)});
    if (!(wanted <= 2e4)) return 0;
    const madd::Mesh m = madd::mesh(file.pslg, options);
    check_properties(m, options);
    // madd mesh's own path: the mesh kept in pieces, each checked on its
    // worker and what crosses them after (InternalError on a failed check),
    // joined, must be mesh()'s.
    if (madd::join(madd::mesh_pieces_with_report(file.pslg, options).mesh) != m)
      fail(options, "the mesh kept in pieces differs from mesh()'s");
    if (options.decomposition.threads == 2) {
      madd::MeshOptions one = options;
      one.decomposition.threads = 1;
      if (madd::mesh(file.pslg, one) != m) fail(options, "the mesh on 1 thread differs from the mesh on 2");
    }
  } catch (const madd::InternalError& e) {
    fail(options, e.what());
  } catch (const madd::Error&) {}
  return 0;
}
