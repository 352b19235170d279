// madd_bench illustrate FILE.poly OUT.svg [--phi DEG] [--per-side K]
// Draws one MADD split step by step for docs/algorithm.md: the refined
// boundary, its constrained Delaunay triangulation (grey), the junction
// triangles' circumcentres (dots), the acceptable partial separators of G'_D
// (blue) and the separator the bisector chose (red). Uses only the public API.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "bench.hpp"
#include "madd/bisect.hpp"
#include "madd/medial.hpp"
#include "madd/poly_io.hpp"
#include "madd/triangulation.hpp"

namespace {

// Splits every segment into pieces of at most `spacing` (uniform refinement).
madd::Pslg refine_uniformly(const madd::Pslg& in, double spacing) {
  madd::Pslg out;
  out.points = in.points;
  out.holes = in.holes;
  out.first_index = 0;
  for (const madd::Segment& s : in.segments) {
    const madd::Point a = in.points[s.a], b = in.points[s.b];
    const auto pieces = static_cast<std::uint32_t>(std::max(1.0, std::ceil(madd::distance(a, b) / spacing)));
    std::uint32_t prev = s.a;
    for (std::uint32_t j = 1; j <= pieces; ++j) {
      std::uint32_t next = s.b;
      if (j < pieces) {
        next = static_cast<std::uint32_t>(out.points.size());
        out.points.push_back(madd::lerp(a, b, static_cast<double>(j) / pieces));
      }
      out.segments.push_back({prev, next, 1});
      prev = next;
    }
  }
  return out;
}

struct SvgCanvas {
  double xmin, ymax, scale;
  std::string body;
  double x(madd::Point p) const { return (p.x - xmin) * scale + 10; }
  double y(madd::Point p) const { return (ymax - p.y) * scale + 10; }
  void line(madd::Point a, madd::Point b, const char* colour, double width) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='%s' stroke-width='%.2f'/>\n",
                  x(a), y(a), x(b), y(b), colour, width);
    body += buf;
  }
  void dot(madd::Point p, const char* colour, double r) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "<circle cx='%.1f' cy='%.1f' r='%.1f' fill='%s'/>\n", x(p), y(p), r, colour);
    body += buf;
  }
};

int run_illustrate(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: madd_bench illustrate FILE.poly OUT.svg [--phi DEG] [--per-side K]\n");
    return 2;
  }
  double phi = 60.0, per_side = 12.0;
  for (int i = 3; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--phi") == 0) phi = std::atof(argv[i + 1]);
    if (std::strcmp(argv[i], "--per-side") == 0) per_side = std::atof(argv[i + 1]);
  }
  const madd::Pslg domain = madd::read_domain(argv[1]);
  const double spacing = std::sqrt(madd::domain_area(domain)) / per_side;
  const madd::Triangulation tri = madd::triangulate(refine_uniformly(domain, spacing));
  const madd::MedialGraph g = madd::build_medial_graph(tri, {phi, false});
  const madd::Bisection cut = madd::bisect(g.contracted, {});

  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const madd::Point& p : tri.points) {
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  }
  SvgCanvas c{xmin, ymax, 800.0 / std::max(xmax - xmin, ymax - ymin), {}};
  for (const auto& t : tri.triangles) {
    for (int i = 0; i < 3; ++i) c.line(tri.points[t[i]], tri.points[t[(i + 1) % 3]], "#bbbbbb", 0.6);
  }
  for (const madd::MedialEdge& e : g.edges) {
    if (e.acceptable) c.line(g.points[e.from], g.points[e.to], "#3366cc", 1.2);
  }
  for (const madd::MedialEdge& e : g.edges) {
    if (cut.side[g.coarse[e.left]] != cut.side[g.coarse[e.right]])
      c.line(g.points[e.from], g.points[e.to], "#dd2222", 3.0);
  }
  for (std::uint32_t t = 0; t < tri.triangles.size(); ++t) {
    if (g.centre[t] != madd::no_index) c.dot(g.points[g.centre[t]], "#228833", 2.5);
  }
  for (std::uint32_t t = 0; t < tri.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      if (tri.is_constrained(t, i)) {
        c.line(tri.points[tri.triangles[t][(i + 1) % 3]], tri.points[tri.triangles[t][(i + 2) % 3]], "#000000", 2.0);
      }
    }
  }
  const double w = (xmax - xmin) * c.scale + 20, h = (ymax - ymin) * c.scale + 20;
  std::ofstream out(argv[2]);
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << w << "' height='" << h << "' viewBox='0 0 " << w << ' '
      << h << "'>\n<rect width='100%' height='100%' fill='white'/>\n"
      << c.body << "</svg>\n";
  std::printf("%zu boundary points, %zu triangles, G_D %zu vertices, G'_D %zu vertices / %zu edges, cut %.4g\n",
              tri.points.size(), tri.triangles.size(), g.gd.vertex_count(), g.contracted.vertex_count(),
              g.contracted.edge_count(), cut.cut);
  return 0;
}

const madd::bench::Registration registration("illustrate", run_illustrate);

}  // namespace
