// Junction triangles (Sec. 3), G_D (Algorithm 1) and its contraction into
// G'_D (Algorithm 2).
#include "madd/medial.hpp"
#include "medial/medial_detail.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "kernel/angles.hpp"
#include "kernel/segment_distance.hpp"
#include "kernel/union_find.hpp"
#include "madd/predicates.hpp"

namespace madd {

double boundary_angle(Point at, Point prev, Point next, Point towards) {
  const double wedge = detail::ccw_angle_deg(at, next, prev);
  const double a1 = detail::ccw_angle_deg(at, next, towards);
  const double a2 = detail::ccw_angle_deg(at, towards, prev);
  if (wedge <= 0.0 || a1 <= 0.0 || a2 <= 0.0) return -1.0;
  if (std::abs(a1 + a2 - wedge) > 1e-6) return -1.0;  // outside the wedge
  return std::min(a1, a2);
}

std::array<Point, 3> vertex_triangle_corners(const MedialGraph& graph, const Triangulation& tri, std::uint32_t v) {
  const std::uint32_t t = graph.vertex_triangle[v];
  const auto& tv = tri.triangles[t];
  const int sub = graph.vertex_sub[v];
  if (sub == 3) return {tri.points[tv[0]], tri.points[tv[1]], tri.points[tv[2]]};
  return {graph.points[graph.centre[t]], tri.points[tv[(sub + 1) % 3]], tri.points[tv[(sub + 2) % 3]]};
}

namespace detail {

namespace {

// Angles are accepted with a tiny margin so that an independent check of the
// committed geometry never disagrees at the last bit.
constexpr double angle_margin_deg = 1e-9;

// Sec. 5.1: f0 = 1 / (phi - Phi0 + 1) with angles in radians, phi capped at pi/2.
double angle_coefficient(double angle_deg, double separator_angle_deg) {
  const double phi = radians(std::min(angle_deg, 90.0));
  return 1.0 / (phi - radians(separator_angle_deg) + 1.0);
}

double end_angle(const Triangulation& tri, std::span<const BoundaryLinks> links, std::uint32_t at, Point towards) {
  return link_angle(tri.points, links, at, towards);
}

}  // namespace

double link_angle(std::span<const Point> points, std::span<const BoundaryLinks> links, std::uint32_t at,
                  Point towards) {
  const BoundaryLinks& l = links[at];
  if (l.no_end) return 180.0;
  if (l.prev == no_index || l.next == no_index) return -1.0;
  if (l.tip) {
    const double a = detail::ccw_angle_deg(points[at], points[l.prev], towards);
    return a <= 0.0 || a >= 360.0 ? -1.0 : std::min(a, 360.0 - a);
  }
  const double left = boundary_angle(points[at], points[l.prev], points[l.next], towards);
  if (left >= 0.0 || !l.two_sided) return left;
  return boundary_angle(points[at], points[l.next], points[l.prev], towards);
}

int link_side(std::span<const Point> points, std::span<const BoundaryLinks> links, std::uint32_t at, Point towards) {
  const BoundaryLinks& l = links[at];
  if (!l.two_sided || l.tip || l.prev == no_index || l.next == no_index) return 0;
  return boundary_angle(points[at], points[l.prev], points[l.next], towards) >= 0.0 ? 0 : 1;
}

JunctionTest test_junction(const Triangulation& tri, std::uint32_t t, std::span<const BoundaryLinks> links,
                           double separator_angle_deg) {
  JunctionTest out;
  const auto& v = tri.triangles[t];
  const Point p[3] = {tri.points[v[0]], tri.points[v[1]], tri.points[v[2]]};
  out.centre = circumcentre(p[0], p[1], p[2]);
  const Point c = out.centre;
  // Property 1: the circumcentre lies strictly inside (decided exactly on the computed point).
  for (int i = 0; i < 3; ++i) {
    if (!(orient2d(p[i], p[(i + 1) % 3], c) > 0.0)) return out;
  }
  // Property 2: at least two edges are interior.
  int interior = 0;
  for (int i = 0; i < 3; ++i) {
    interior += (tri.neighbours[t][i] != no_index && tri.segment_of[t][i] == no_index) ? 1 : 0;
  }
  if (interior < 2) return out;
  // Property 3: at least two spokes good with the boundary and with each other.
  const double bound = separator_angle_deg + angle_margin_deg;
  double b[3], central[3][3];
  for (int i = 0; i < 3; ++i) b[i] = end_angle(tri, links, v[i], c);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) central[i][j] = i == j ? 360.0 : degrees(angle_at(c, p[i], p[j]));
  }
  const bool all = b[0] >= bound && b[1] >= bound && b[2] >= bound && central[0][1] >= bound &&
                   central[1][2] >= bound && central[0][2] >= bound;
  if (all) {
    out.spoke_ok = {true, true, true};
  } else {
    double best = -1.0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const double q = std::min({b[i], b[j], central[i][j]});
      if (q >= bound && q > best) {
        best = q;
        out.spoke_ok = {false, false, false};
        out.spoke_ok[i] = out.spoke_ok[j] = true;
      }
    }
    if (best < 0.0) return out;
  }
  out.junction = true;
  for (int i = 0; i < 3; ++i) {
    double a = b[i];
    for (int j = 0; j < 3; ++j) {
      if (j != i && out.spoke_ok[j]) a = std::min(a, central[i][j]);
    }
    out.spoke_angle[i] = a;
  }
  return out;
}

namespace {

void add_vertices(MedialGraph& g, const Triangulation& tri, std::span<const BoundaryLinks> links,
                  double separator_angle_deg, std::vector<double>& weights, std::vector<JunctionTest>& tests) {
  const auto count = static_cast<std::uint32_t>(tri.triangle_count());
  g.centre.assign(count, no_index);
  g.first_vertex.assign(count, 0);
  tests.resize(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    tests[t] = test_junction(tri, t, links, separator_angle_deg);
    g.first_vertex[t] = static_cast<std::uint32_t>(weights.size());
    const auto& v = tri.triangles[t];
    if (!tests[t].junction) {
      weights.push_back(triangle_area(tri.points[v[0]], tri.points[v[1]], tri.points[v[2]]));
      g.vertex_triangle.push_back(t);
      g.vertex_sub.push_back(3);
      continue;
    }
    g.centre[t] = static_cast<std::uint32_t>(g.points.size());
    g.points.push_back(tests[t].centre);
    for (int i = 0; i < 3; ++i) {
      weights.push_back(triangle_area(tests[t].centre, tri.points[v[(i + 1) % 3]], tri.points[v[(i + 2) % 3]]));
      g.vertex_triangle.push_back(t);
      g.vertex_sub.push_back(static_cast<std::uint8_t>(i));
    }
  }
}

// Whether edge i of triangle t (a chord between boundary points) runs a hair
// from the boundary along its middle: from the triangle's third corner, or
// from one of its other sides that is a boundary edge (an edge no refinement
// point divides, which a third corner alone would not show).
bool hugs_boundary(const Triangulation& tri, std::uint32_t t, int i) {
  const auto& v = tri.triangles[t];
  const Point a = tri.points[v[(i + 1) % 3]], b = tri.points[v[(i + 2) % 3]], c = tri.points[v[i]];
  if (hugs_separator(a, b, c, c)) return true;
  for (const int k : {(i + 1) % 3, (i + 2) % 3}) {
    if (tri.neighbours[t][k] != no_index) continue;  // inside: not the boundary
    const Point p = tri.points[v[(k + 1) % 3]], q = tri.points[v[(k + 2) % 3]];
    if (hugs_separator(a, b, p, q)) return true;
  }
  return false;
}

// Algorithm 1, lines 9-10, plus the spokes inside junction triangles.
std::vector<double> add_edges(MedialGraph& g, const Triangulation& tri, std::span<const BoundaryLinks> links,
                              const MedialOptions& options, const std::vector<JunctionTest>& tests) {
  std::vector<double> lengths;
  const double bound = options.separator_angle_deg + angle_margin_deg;
  auto gd_vertex = [&](std::uint32_t t, int edge) {
    return g.first_vertex[t] + (g.centre[t] != no_index ? static_cast<std::uint32_t>(edge) : 0u);
  };
  const auto count = static_cast<std::uint32_t>(tri.triangle_count());
  for (std::uint32_t t = 0; t < count; ++t) {
    const auto& v = tri.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t n = tri.neighbours[t][i];
      if (n == no_index || n < t) continue;
      int j = 0;
      while (j < 3 && tri.neighbours[n][j] != t) ++j;
      if (j == 3) continue;
      MedialEdge e;
      e.from = v[(i + 1) % 3];
      e.to = v[(i + 2) % 3];
      e.left = gd_vertex(t, i);
      e.right = gd_vertex(n, j);
      const double a = end_angle(tri, links, e.from, tri.points[e.to]);
      const double b = end_angle(tri, links, e.to, tri.points[e.from]);
      e.smallest_angle_deg = std::min(a, b);
      // The two triangles on it hold the boundary nearest it on either side:
      // their third corners, and their sides that are boundary edges.
      const bool clear = !hugs_boundary(tri, t, i) && !hugs_boundary(tri, n, j);
      e.acceptable = tri.segment_of[t][i] == no_index && e.smallest_angle_deg >= bound && clear;
      g.edges.push_back(e);
      double w = distance(tri.points[e.from], tri.points[e.to]);
      if (options.smooth) w *= static_cast<double>(links[e.from].bonus) * static_cast<double>(links[e.to].bonus);
      lengths.push_back(w);
    }
    if (g.centre[t] == no_index) continue;
    for (int k = 0; k < 3; ++k) {
      MedialEdge e;
      e.from = g.centre[t];
      e.to = v[k];
      e.left = g.first_vertex[t] + static_cast<std::uint32_t>((k + 2) % 3);
      e.right = g.first_vertex[t] + static_cast<std::uint32_t>((k + 1) % 3);
      e.smallest_angle_deg = tests[t].spoke_angle[k];
      // A flat junction triangle's centre lies near its long side, and the
      // spokes to that side's ends run along it, a hair from the third corner.
      const Point centre = g.points[e.from], end = tri.points[e.to];
      const Point p1 = tri.points[v[(k + 1) % 3]], p2 = tri.points[v[(k + 2) % 3]];
      e.acceptable =
          tests[t].spoke_ok[k] && !hugs_separator(centre, end, p1, p1) && !hugs_separator(centre, end, p2, p2);
      g.edges.push_back(e);
      double w = distance(g.points[e.from], tri.points[e.to]);
      if (options.smooth) w *= static_cast<double>(links[e.to].bonus);
      lengths.push_back(w);
    }
  }
  if (options.smooth) {
    for (std::size_t k = 0; k < g.edges.size(); ++k) {
      if (g.edges[k].acceptable)
        lengths[k] *= angle_coefficient(g.edges[k].smallest_angle_deg, options.separator_angle_deg);
    }
  }
  return lengths;
}

// Algorithm 2: merge across every unacceptable edge (union-find), then build
// the quotient graph whose edges remember the partial separators they stand for.
void contract(MedialGraph& g, const std::vector<double>& weights, const std::vector<double>& lengths) {
  const auto n = static_cast<std::uint32_t>(weights.size());
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const MedialEdge& e : g.edges) {
    if (e.acceptable) continue;
    const std::uint32_t a = detail::find_root(parent, e.left);
    const std::uint32_t b = detail::find_root(parent, e.right);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  g.coarse.assign(n, no_index);
  std::vector<double> coarse_weights;
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t r = detail::find_root(parent, v);
    if (g.coarse[r] == no_index) {
      g.coarse[r] = static_cast<std::uint32_t>(coarse_weights.size());
      coarse_weights.push_back(0.0);
    }
    g.coarse[v] = g.coarse[r];
    coarse_weights[g.coarse[v]] += weights[v];
  }
  std::vector<std::array<std::uint32_t, 3>> keyed;  // (u, v, G_D edge)
  for (std::uint32_t k = 0; k < g.edges.size(); ++k) {
    const MedialEdge& e = g.edges[k];
    const std::uint32_t a = g.coarse[e.left];
    const std::uint32_t b = g.coarse[e.right];
    if (!e.acceptable || a == b) continue;
    keyed.push_back({std::min(a, b), std::max(a, b), k});
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<WeightedEdge> coarse_edges;
  g.separator_offsets.push_back(0);
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    const bool fresh = i == 0 || keyed[i][0] != keyed[i - 1][0] || keyed[i][1] != keyed[i - 1][1];
    if (fresh) {
      if (i != 0) g.separator_offsets.push_back(static_cast<std::uint32_t>(i));
      g.contracted_ends.push_back({keyed[i][0], keyed[i][1]});
      coarse_edges.push_back({keyed[i][0], keyed[i][1], 0.0});
    }
    coarse_edges.back().weight += lengths[keyed[i][2]];
    g.separators.push_back(keyed[i][2]);
  }
  if (!keyed.empty()) g.separator_offsets.push_back(static_cast<std::uint32_t>(keyed.size()));
  g.contracted = make_graph(std::move(coarse_weights), coarse_edges);
}

}  // namespace

MedialGraph build_medial_graph(const Triangulation& tri, std::span<const BoundaryLinks> links,
                               const MedialOptions& options) {
  MedialGraph g;
  g.points = tri.points;
  std::vector<double> weights;
  std::vector<JunctionTest> tests;
  add_vertices(g, tri, links, options.separator_angle_deg, weights, tests);
  const std::vector<double> lengths = add_edges(g, tri, links, options, tests);
  std::vector<WeightedEdge> gd_edges;
  gd_edges.reserve(g.edges.size());
  for (std::size_t k = 0; k < g.edges.size(); ++k) gd_edges.push_back({g.edges[k].left, g.edges[k].right, lengths[k]});
  g.gd = make_graph(weights, gd_edges);
  contract(g, weights, lengths);
  return g;
}

void set_vertex_weights(MedialGraph& graph, std::vector<double> weights) {
  std::vector<double>& coarse = graph.contracted.vertex_weights;
  std::fill(coarse.begin(), coarse.end(), 0.0);
  for (std::size_t v = 0; v < weights.size(); ++v) coarse[graph.coarse[v]] += weights[v];
  graph.gd.vertex_weights = std::move(weights);
}

bool hugs_separator(Point a, Point b, Point p, Point q) {
  // Near its ends a separator meets the boundary it ends on: only its middle counts.
  constexpr double clearance_end = 0.1;
  const double limit = separator_clearance * distance(a, b);
  const Point m0 = lerp(a, b, clearance_end), m1 = lerp(a, b, 1.0 - clearance_end);
  // Two segments that do not cross are nearest at an end of one of them.
  if (orient2d(m0, m1, p) * orient2d(m0, m1, q) < 0.0 && orient2d(p, q, m0) * orient2d(p, q, m1) < 0.0) return true;
  return std::min({segment_distance(p, m0, m1), segment_distance(q, m0, m1), segment_distance(m0, p, q),
                   segment_distance(m1, p, q)}) < limit;
}

std::vector<BoundaryLinks> boundary_links(const Triangulation& tri) {
  std::vector<BoundaryLinks> links(tri.points.size());
  std::vector<std::uint8_t> passes(tri.points.size(), 0);
  for (std::uint32_t t = 0; t < tri.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      if (tri.neighbours[t][i] != no_index) continue;
      // Edge i of a counter-clockwise triangle, a -> b, has the triangle on its left.
      const std::uint32_t a = tri.triangles[t][(i + 1) % 3], b = tri.triangles[t][(i + 2) % 3];
      links[a].next = b;
      links[b].prev = a;
      ++passes[a];
    }
  for (std::size_t v = 0; v < links.size(); ++v)
    if (passes[v] > 1) links[v].prev = no_index;  // the boundary passes it twice: no separator ends there
  return links;
}

}  // namespace detail

MedialGraph build_medial_graph(const Triangulation& tri, const MedialOptions& options) {
  const std::vector<detail::BoundaryLinks> links = detail::boundary_links(tri);
  return detail::build_medial_graph(tri, links, options);
}

}  // namespace madd
