// libFuzzer target: .poly text -> parse -> validate -> mesh (decompose,
// discretise, refine, merge, and mesh()'s own verify_mesh self-check), then
// properties checked here independently of verify_mesh: every triangle
// strictly counter-clockwise, the shortfall equal to the number of triangles
// below the angle bound (the one measure, src/quality/mesh_angle.hpp), and
// the mesh the same on 2 threads as on 1.
//
// Options come from the last two bytes, which stay part of the text (a
// newline, a digit, or the end of a trailing '#' comment), so plain .poly
// seeds work unchanged. All combinations occur among printable characters:
//   last byte % 50:        N = {5, 1, 2, 3, 8}[v % 5], -q = {0, 20, 30, 25, 33}[v / 5 % 5],
//                          threads = 1 + v / 25 % 2
//   last but one % 48:     max area = domain area x {0 (none), 1/50, 1/500, 1/3000}[v % 4],
//                          Phi0 = {45, 70, 60}[v / 4 % 3], off-centres off if v / 12 % 2,
//                          balance by work off if v / 24 % 2
// (a file ending in "\n\n": N = 5, -q 30, 1 thread, area / 500, Phi0 60, both on).
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
// 30k to 140k triangles with or without an area bound. The decomposition
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

[[noreturn]] void fail(const madd::MeshOptions& o, const char* what) {
  std::fprintf(stderr,
               "fuzz_mesh (N=%u, q=%g, max_area=%g, Phi0=%g, threads=%u, off_centres=%d, balance_by_work=%d): %s\n",
               o.decomposition.subdomains, o.size.min_triangle_angle_deg, o.size.max_triangle_area,
               o.decomposition.separator_angle_deg, o.decomposition.threads, o.off_centres ? 1 : 0,
               o.balance_by_work ? 1 : 0, what);
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
    const double wanted =
        std::max(options.size.max_triangle_area > 0 ? area / options.size.max_triangle_area : 0.0,
                 4.0 * boundary_pieces(file.pslg, options.size.max_triangle_area) + sharp_corner_triangles(file.pslg));
    if (!(wanted <= 2e4)) return 0;
    const madd::Mesh m = madd::mesh(file.pslg, options);
    check_properties(m, options);
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
