#pragma once
// A gmsh MSH 2.2 ASCII reader and the conformity check of a mesh made by
// `gmsh -2` from format_geo's output (used by output_formats_test.cpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "madd/decomposition.hpp"

namespace madd::test {

struct MshElement {
  int type = 0;            // 1 line, 2 triangle, 15 point
  std::vector<long> tags;  // physical, elementary, ...
  std::vector<long> nodes;
};

struct Msh {
  std::map<long, Point> nodes;
  std::vector<MshElement> elements;
};

inline Msh parse_msh22(const std::string& text) {
  std::istringstream in(text);
  Msh m;
  std::string word, version;
  in >> word >> version;
  if (word != "$MeshFormat" || version != "2.2") throw std::runtime_error("msh: not format 2.2");
  while (in >> word) {
    if (word == "$Nodes") {
      std::size_t n = 0;
      in >> n;
      for (std::size_t i = 0; i < n; ++i) {
        long id = 0;
        double x = 0, y = 0, z = 0;
        if (!(in >> id >> x >> y >> z)) throw std::runtime_error("msh: bad node");
        m.nodes[id] = {x, y};
      }
    } else if (word == "$Elements") {
      std::size_t n = 0;
      in >> n;
      for (std::size_t i = 0; i < n; ++i) {
        long id = 0;
        int tags = 0;
        MshElement e;
        in >> id >> e.type >> tags;
        e.tags.resize(static_cast<std::size_t>(tags));
        for (long& t : e.tags) in >> t;
        const std::size_t count = e.type == 2 ? 3 : e.type == 1 ? 2 : e.type == 15 ? 1 : 0;
        if (count == 0) throw std::runtime_error("msh: unexpected element type " + std::to_string(e.type));
        e.nodes.resize(count);
        for (long& v : e.nodes) in >> v;
        if (!in) throw std::runtime_error("msh: bad element");
        m.elements.push_back(e);
      }
    }
  }
  return m;
}

// Whether p lies on segment ab, within tol of the line and between a and b.
inline bool on_segment(Point p, Point a, Point b, double tol) {
  const Point ab = b - a;
  const double len = length(ab);
  const double t = dot(p - a, ab) / (len * len);
  return std::abs(cross(ab, p - a)) / len <= tol && t >= -tol / len && t <= 1 + tol / len;
}

// The checks of a gmsh mesh of format_geo(d): every triangle in a subdomain's
// physical group, each subdomain covered (areas add up), and conformity: the
// nodes on a separator are nodes of triangles on both sides, and an edge used
// by only one triangle lies on the original boundary.
inline void check_gmsh_mesh(const Decomposition& d, const Msh& m) {
  const std::size_t n = d.subdomains.size();
  double span = 0;
  for (const Point& p : d.points) span = std::max({span, std::abs(p.x), std::abs(p.y)});
  const double tol = 1e-9 * span;
  std::vector<double> area(n, 0.0);
  std::map<long, std::set<long>> subdomains_at;  // node -> physical tags of its triangles
  std::map<std::pair<long, long>, int> edge_uses;
  std::size_t triangles = 0;
  for (const MshElement& e : m.elements) {
    if (e.type != 2) continue;
    ++triangles;
    REQUIRE(e.tags.size() >= 2);
    const long tag = e.tags[0];
    REQUIRE(tag >= 1);
    REQUIRE(tag <= static_cast<long>(n));
    CHECK(e.tags[1] == tag);  // elementary surface k+1 is physical k+1
    const Point a = m.nodes.at(e.nodes[0]), b = m.nodes.at(e.nodes[1]), c = m.nodes.at(e.nodes[2]);
    area[static_cast<std::size_t>(tag - 1)] += std::abs(signed_area(a, b, c));
    for (int i = 0; i < 3; ++i) {
      subdomains_at[e.nodes[i]].insert(tag);
      const long u = e.nodes[i], v = e.nodes[(i + 1) % 3];
      ++edge_uses[{std::min(u, v), std::max(u, v)}];
    }
  }
  MESSAGE("gmsh mesh: " << triangles << " triangles, " << m.nodes.size() << " nodes, " << n << " subdomains");
  for (std::size_t k = 0; k < n; ++k) CHECK(area[k] == doctest::Approx(d.subdomains[k].area).epsilon(1e-9));
  // The two subdomains of each separator, from the rings.
  std::vector<std::vector<long>> sides(d.segments.size());
  for (std::size_t k = 0; k < n; ++k)
    for (const auto& ring : d.subdomains[k].ring_segments)
      for (const std::uint32_t s : ring) sides[s].push_back(static_cast<long>(k) + 1);
  std::size_t inside_separators = 0;
  for (std::uint32_t s = 0; s < d.segments.size(); ++s) {
    if (!d.is_separator(s)) continue;
    REQUIRE(sides[s].size() == 2);
    const Point a = d.points[d.segments[s].a], b = d.points[d.segments[s].b];
    std::size_t on = 0;
    for (const auto& [id, p] : m.nodes) {
      if (!on_segment(p, a, b, tol) || !subdomains_at.count(id)) continue;
      ++on;
      CHECK(subdomains_at[id].count(sides[s][0]) == 1);
      CHECK(subdomains_at[id].count(sides[s][1]) == 1);
    }
    CHECK(on >= 2);  // at least its endpoints
    inside_separators += on - 2;
  }
  CHECK(inside_separators > 0);  // the check above saw more than the geometry's own points
  for (const auto& edge_use : edge_uses) {
    // Not a structured binding: clang 14 cannot capture one in CHECK_MESSAGE's lambda.
    const auto& edge = edge_use.first;
    const auto uses = edge_use.second;
    REQUIRE(uses <= 2);
    if (uses == 2) continue;
    const Point mid = midpoint(m.nodes.at(edge.first), m.nodes.at(edge.second));
    bool on_boundary = false;
    for (std::uint32_t s = 0; s < d.segments.size() && !on_boundary; ++s)
      on_boundary = !d.is_separator(s) && on_segment(mid, d.points[d.segments[s].a], d.points[d.segments[s].b], tol);
    CHECK_MESSAGE(on_boundary, "edge used by one triangle off the boundary: " << edge.first << "-" << edge.second);
  }
}

// gmsh honoured "Line{...} In Surface" and "Point{...} In Surface": the mesh
// nodes on each interior segment, in order along it, are joined by triangle
// edges, and each isolated point is a triangle's node.
inline void check_gmsh_embedded(const Decomposition& d, const Msh& m) {
  double span = 0;
  for (const Point& p : d.points) span = std::max({span, std::abs(p.x), std::abs(p.y)});
  const double tol = 1e-9 * span;
  std::set<std::pair<long, long>> edges;
  std::set<long> corners;
  for (const MshElement& e : m.elements) {
    if (e.type != 2) continue;
    for (int i = 0; i < 3; ++i) {
      const long u = e.nodes[i], v = e.nodes[(i + 1) % 3];
      edges.insert({std::min(u, v), std::max(u, v)});
      corners.insert(u);
    }
  }
  for (const Subdomain& sub : d.subdomains) {
    for (const std::uint32_t j : sub.interior_segments) {
      const Point a = d.points[d.segments[j].a], b = d.points[d.segments[j].b];
      std::vector<std::pair<double, long>> along;
      for (const auto& [id, p] : m.nodes)
        if (corners.count(id) && on_segment(p, a, b, tol)) along.push_back({dot(p - a, b - a), id});
      std::sort(along.begin(), along.end());
      REQUIRE(along.size() >= 2);
      for (std::size_t i = 0; i + 1 < along.size(); ++i)
        CHECK(edges.count({std::min(along[i].second, along[i + 1].second),
                           std::max(along[i].second, along[i + 1].second)}) == 1);
    }
    for (const std::uint32_t p : sub.interior_points) {
      bool found = false;
      for (const auto& [id, q] : m.nodes) found = found || (corners.count(id) && q == d.points[p]);
      CHECK(found);
    }
  }
}

}  // namespace madd::test
