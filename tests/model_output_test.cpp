// Tests of the coastal model formats (include/madd/model_output.hpp): the
// boundary lists against a brute-force boundary of the mesh, fort.14,
// hgrid.gr3 and .2dm read back line by line by the test's own reader of the
// documented layouts, fort.14's round trip, and check_fort14 and
// parse_fort14 on broken files.
#include <doctest/doctest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "madd/error.hpp"
#include "madd/mesh.hpp"
#include "madd/model_output.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "scratch_files.hpp"

namespace {

using madd::BoundaryKind;
using madd::Mesh;
using madd::ModelBoundary;
using madd::ModelGrid;
using madd::Point;

// Adds the closed ring `points` to `p`, segment k (from point k) marked marks[k].
void add_ring(madd::Pslg& p, const std::vector<Point>& points, const std::vector<int>& marks) {
  const auto first = static_cast<std::uint32_t>(p.points.size());
  const auto n = static_cast<std::uint32_t>(points.size());
  p.points.insert(p.points.end(), points.begin(), points.end());
  for (std::uint32_t k = 0; k < n; ++k) p.segments.push_back({first + k, first + (k + 1) % n, marks[k]});
}

// The coast: a 12 x 8 box whose top right is open sea (two segments marked
// 2 through (10, 8.5)), the rest mainland (1); island A a square, island B a
// triangle touching A at its corner (5, 4).
madd::Pslg coast() {
  madd::Pslg p;
  p.has_segment_markers = true;
  add_ring(p, {{0, 0}, {12, 0}, {12, 8}, {10, 8.5}, {8, 8}, {0, 8}}, {1, 1, 2, 2, 1, 1});
  add_ring(p, {{3, 2}, {5, 2}, {5, 4}, {3, 4}}, {1, 1, 1, 1});
  const auto corner = static_cast<std::uint32_t>(p.points.size() - 2);  // (5, 4)
  const auto b = static_cast<std::uint32_t>(p.points.size());
  p.points.insert(p.points.end(), {{7, 4}, {6, 6}});
  p.segments.insert(p.segments.end(), {{corner, b, 1}, {b, b + 1, 1}, {b + 1, corner, 1}});
  p.holes = {{4, 3}, {6, 4.6}};
  return p;
}

Mesh mesh_of(const madd::Pslg& domain, std::uint32_t n = 3, double area = 0.6) {
  madd::MeshOptions o;
  o.decomposition.subdomains = n;
  o.decomposition.threads = 1;
  o.size.max_triangle_area = area;
  return madd::mesh(domain, o);
}

const Mesh& coast_mesh() {
  static const Mesh m = mesh_of(coast());
  return m;
}

// Synthetic lon/lat and depths whose decimals are not exact in binary, and
// a depth of -0.0 (a dry point at the datum) to keep the sign.
ModelGrid lonlat_grid(const Mesh& m) {
  ModelGrid g;
  g.title = "coast test grid";
  for (std::size_t v = 0; v < m.points.size(); ++v) {
    g.coordinates.push_back({-70.1 + m.points[v].x / 111.3, 42.7 + m.points[v].y / 97.1});
    g.depth.push_back(v == 1 ? -0.0 : 3.3 + 0.1 * m.points[v].x - 0.07 * m.points[v].y);
  }
  return g;
}

// Brute force: every triangle edge (a, b) whose reverse is in no triangle:
// the boundary with the domain on the left.
std::set<std::pair<std::uint32_t, std::uint32_t>> boundary_by_brute_force(const Mesh& m) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges, boundary;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) edges.insert({t[static_cast<std::size_t>(i)], t[(i + 1) % 3]});
  for (const auto& [a, b] : edges)
    if (!edges.count({b, a})) boundary.insert({a, b});
  return boundary;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, int> marker_of_edge(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> markers;
  for (const madd::MeshSegment& s : m.segments) markers[{std::min(s.a, s.b), std::max(s.a, s.b)}] = s.marker;
  return markers;
}

double signed_area(const Mesh& m, const std::vector<std::uint32_t>& closed) {
  double area = 0;
  for (std::size_t j = 0; j + 1 < closed.size(); ++j) {
    const Point p = m.points[closed[j]], q = m.points[closed[j + 1]];
    area += 0.5 * (p.x * q.y - p.y * q.x);
  }
  return area;
}

// Every list pair is a boundary edge, domain on its left, of the list's
// kind; every boundary edge is in exactly one list.
void check_cover(const Mesh& m, const std::vector<ModelBoundary>& lists, int open_marker = 2) {
  const auto boundary = boundary_by_brute_force(m);
  const auto markers = marker_of_edge(m);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const ModelBoundary& list : lists) {
    REQUIRE(list.nodes.size() >= 2);
    CHECK(list.closed == (list.nodes.front() == list.nodes.back()));
    for (std::size_t j = 0; j + 1 < list.nodes.size(); ++j) {
      const std::pair<std::uint32_t, std::uint32_t> e{list.nodes[j], list.nodes[j + 1]};
      REQUIRE(boundary.count(e) == 1);
      ++uses[e];
      const int marker = markers.at({std::min(e.first, e.second), std::max(e.first, e.second)});
      CHECK((list.kind == BoundaryKind::open) == (marker == open_marker));
    }
  }
  CHECK(uses.size() == boundary.size());
  for (const auto& [e, n] : uses) CHECK(n == 1);
}

// The runs of one loop chain: each unclosed list's last node is the first
// node of exactly one unclosed list.
void check_runs_chain(const std::vector<ModelBoundary>& lists) {
  std::multiset<std::uint32_t> starts, ends;
  for (const ModelBoundary& list : lists)
    if (!list.closed) starts.insert(list.nodes.front()), ends.insert(list.nodes.back());
  CHECK(starts == ends);
}

// ---- a reader of the documented layouts, for the line-by-line checks ----

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The whitespace-separated words of a line.
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::int64_t integer(const std::string& word) {
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
  REQUIRE_MESSAGE((ec == std::errc() && ptr == word.data() + word.size()), "not an integer: " << word);
  return v;
}

double real(const std::string& word) {
  double v = 0;
  const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
  REQUIRE_MESSAGE((ec == std::errc() && ptr == word.data() + word.size()), "not a real: " << word);
  return v;
}

bool same_bits(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }

// Lines [at, at + NP) are "JN X Y DP", then NE lines "JE 3 N1 N2 N3" of the
// mesh's triangles, counter-clockwise in the written coordinates.
std::size_t check_grid_lines(const std::vector<std::string>& lines, std::size_t at, const Mesh& m, const ModelGrid& g) {
  const auto& xy = g.coordinates.empty() ? m.points : g.coordinates;
  for (std::size_t v = 0; v < m.points.size(); ++v, ++at) {
    const auto w = words(lines.at(at));
    REQUIRE(w.size() == 4);
    CHECK(integer(w[0]) == static_cast<std::int64_t>(v + 1));
    CHECK(same_bits(real(w[1]), xy[v].x));
    CHECK(same_bits(real(w[2]), xy[v].y));
    CHECK(same_bits(real(w[3]), g.depth.empty() ? 0.0 : g.depth[v]));
  }
  for (std::size_t t = 0; t < m.triangles.size(); ++t, ++at) {
    const auto w = words(lines.at(at));
    REQUIRE(w.size() == 5);
    CHECK(integer(w[0]) == static_cast<std::int64_t>(t + 1));
    CHECK(integer(w[1]) == 3);
    std::array<std::uint32_t, 3> c{};
    for (std::size_t i = 0; i < 3; ++i) c[i] = static_cast<std::uint32_t>(integer(w[2 + i]) - 1);
    CHECK(c == m.triangles[t]);
    CHECK(madd::orient2d(xy[c[0]], xy[c[1]], xy[c[2]]) > 0);
  }
  return at;
}

// A count line "<values...> <comment>": the values, checked to be
// followed by a comment starting with `comment`.
std::vector<std::int64_t> count_line(const std::string& line, std::size_t values, const std::string& comment) {
  const auto w = words(line);
  REQUIRE(w.size() > values);
  std::vector<std::int64_t> out;
  for (std::size_t k = 0; k < values; ++k) out.push_back(integer(w[k]));
  CHECK(line.find(comment) != std::string::npos);
  return out;
}

// `count` node lines from `at`: one 1-based id each.
std::vector<std::uint32_t> node_lines(const std::vector<std::string>& lines, std::size_t& at, std::int64_t count) {
  std::vector<std::uint32_t> nodes;
  for (std::int64_t j = 0; j < count; ++j, ++at) {
    const auto w = words(lines.at(at));
    REQUIRE(w.size() == 1);
    nodes.push_back(static_cast<std::uint32_t>(integer(w[0]) - 1));
  }
  return nodes;
}

// hgrid.gr3's boundary part from line `at`: (flag, nodes) per list, flag
// -1 for open lists, checking the documented count lines on the way.
std::vector<std::pair<int, std::vector<std::uint32_t>>> gr3_lists(const std::vector<std::string>& lines,
                                                                  std::size_t at) {
  std::vector<std::pair<int, std::vector<std::uint32_t>>> out;
  const auto open = count_line(lines.at(at++), 1, "= Number of open boundaries")[0];
  std::int64_t open_nodes = count_line(lines.at(at++), 1, "= Total number of open boundary nodes")[0];
  for (std::int64_t k = 0; k < open; ++k) {
    const auto w = words(lines.at(at));
    CHECK(w.at(1) == "=");  // "n = Number of nodes for open boundary k": no type
    const auto n = count_line(lines.at(at++), 1, "= Number of nodes for open boundary " + std::to_string(k + 1))[0];
    out.push_back({-1, node_lines(lines, at, n)});
    open_nodes -= n;
  }
  CHECK(open_nodes == 0);
  const auto land = count_line(lines.at(at++), 1, "= Number of land boundaries")[0];
  std::int64_t land_nodes = count_line(lines.at(at++), 1, "= Total number of land boundary nodes")[0];
  for (std::int64_t k = 0; k < land; ++k) {
    const auto head = count_line(lines.at(at++), 2, "= Number of nodes for ");
    CHECK((head[1] == 0 || head[1] == 1));
    CHECK(lines.at(at - 1).find(head[1] == 0 ? "land boundary" : "island boundary") != std::string::npos);
    out.push_back({static_cast<int>(head[1]), node_lines(lines, at, head[0])});
    land_nodes -= head[0];
  }
  CHECK(land_nodes == 0);
  CHECK(at == lines.size());
  return out;
}

// The .2dm's nodestrings: NS cards of at most 10 ids, each nodestring ended
// by its one negative id.
std::vector<std::vector<std::uint32_t>> nodestrings(const std::vector<std::string>& lines, std::size_t at) {
  std::vector<std::vector<std::uint32_t>> out;
  bool open = false;
  for (; at < lines.size(); ++at) {
    const auto w = words(lines[at]);
    REQUIRE(w.at(0) == "NS");
    CHECK(w.size() >= 2);
    CHECK(w.size() <= 11);
    if (!open) out.emplace_back();
    for (std::size_t k = 1; k < w.size(); ++k) {
      const std::int64_t id = integer(w[k]);
      CHECK(id != 0);
      out.back().push_back(static_cast<std::uint32_t>(std::abs(id) - 1));
      open = id > 0;
      if (id < 0) CHECK(k + 1 == w.size());  // a negative id ends the card too
    }
  }
  CHECK(!open);
  return out;
}

// A unit square of two elements: open boundary 1-2, land 2-3-4-1.
const char* const square14 = "square\n"
                             "2 4 ! NE NP\n"
                             "1 0.0 0.0 5.0\n"
                             "2 1.0 0.0 5.0\n"
                             "3 1.0 1.0 5.0\n"
                             "4 0.0 1.0 5.0\n"
                             "1 3 1 2 3\n"
                             "2 3 1 3 4\n"
                             "1 = Number of open boundaries\n"
                             "2 = Total number of open boundary nodes\n"
                             "2 0 = Number of nodes for open boundary 1\n"
                             "1\n"
                             "2\n"
                             "1 = Number of land boundaries\n"
                             "4 = Total number of land boundary nodes\n"
                             "4 20 = Number of nodes for land boundary 1\n"
                             "2\n"
                             "3\n"
                             "4\n"
                             "1\n";

// Whether some problem of `v` holds `text`.
bool says(const madd::Verification& v, const std::string& text) {
  return std::any_of(v.problems.begin(), v.problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

madd::Fort14 coast14() { return madd::parse_fort14(madd::format_fort14(coast_mesh(), lonlat_grid(coast_mesh()))); }

madd::Fort14Boundary& island_of(madd::Fort14& f) {
  REQUIRE(f.land_boundaries.back().type == 21);
  return f.land_boundaries.back();
}

madd::ParseError parse_error(const std::string& text) {
  try {
    madd::parse_fort14(text, "t.14");
  } catch (const madd::ParseError& e) {
    return e;
  }
  FAIL("expected a ParseError for:\n" << text);
  return madd::ParseError("", 0, 0, "");
}

// square14 with line `line` (1-based) replaced by `with`.
std::string square_with(std::size_t line, const std::string& with) {
  auto lines = lines_of(square14);
  lines.at(line - 1) = with;
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

}  // namespace

TEST_SUITE("model_output") {

TEST_CASE("model_boundaries: the coast's lists cover its boundary once, open and land runs and a touching island") {
  const Mesh& m = coast_mesh();
  const auto lists = madd::model_boundaries(m);
  check_cover(m, lists);
  check_runs_chain(lists);
  // One open run, one mainland run, and A and B as one island loop (they
  // touch at (5, 4), which it passes twice).
  REQUIRE(lists.size() == 3);
  CHECK(lists[0].kind == BoundaryKind::open);
  CHECK(lists[1].kind == BoundaryKind::mainland);
  CHECK(lists[2].kind == BoundaryKind::island);
  CHECK(!lists[0].closed);
  CHECK(!lists[1].closed);
  CHECK(lists[2].closed);
  CHECK(m.points[lists[0].nodes.front()] == Point{12, 8});  // the open run from the sea's first corner
  CHECK(m.points[lists[0].nodes.back()] == Point{8, 8});
  CHECK(lists[0].nodes.front() == lists[1].nodes.back());
  CHECK(lists[0].nodes.back() == lists[1].nodes.front());
  std::vector<std::uint32_t> outer = lists[0].nodes;
  outer.insert(outer.end(), lists[1].nodes.begin() + 1, lists[1].nodes.end());
  CHECK(signed_area(m, outer) == doctest::Approx(12 * 8 + 2 * 0.5));   // counter-clockwise: the box and the cap
  CHECK(signed_area(m, lists[2].nodes) == doctest::Approx(-(4 + 2)));  // clockwise round A and B
  const auto corner =
      static_cast<std::size_t>(std::count_if(lists[2].nodes.begin(), lists[2].nodes.end() - 1, [&](std::uint32_t v) {
        return m.points[v] == Point{5, 4};
      }));
  CHECK(corner == 2);
  // Each loop starts at its smallest directed edge: the island at its lowest node.
  CHECK(lists[2].nodes.front() == *std::min_element(lists[2].nodes.begin(), lists[2].nodes.end()));
  CHECK(madd::model_boundaries(m) == lists);
  CHECK(madd::model_boundaries(mesh_of(coast(), 4, 0.3)).size() == 3);
}

TEST_CASE("model_boundaries: an island touching the coast joins the mainland loop; all land is one closed list") {
  madd::Pslg p = coast();
  // Island C: a triangle with a corner on the coast's corner (0, 8).
  const auto c = static_cast<std::uint32_t>(p.points.size());
  p.points.insert(p.points.end(), {{1, 6}, {2, 7}});
  p.segments.insert(p.segments.end(), {{5, c, 1}, {c, c + 1, 1}, {c + 1, 5, 1}});
  p.holes.push_back({1, 7});
  madd::validate(p);
  const Mesh m = mesh_of(p, 1);  // the touch inside one subdomain (the mesher refused it once)
  const auto lists = madd::model_boundaries(m);
  check_cover(m, lists);
  check_runs_chain(lists);
  REQUIRE(lists.size() == 3);
  CHECK(lists[1].kind == BoundaryKind::mainland);
  CHECK(std::count_if(lists[1].nodes.begin(), lists[1].nodes.end(), [&](std::uint32_t v) {
          return m.points[v] == Point{0, 8};
        }) == 2);
  // All land: one closed mainland list from the smallest directed edge.
  madd::Pslg land = coast();
  for (madd::Segment& s : land.segments) s.marker = 1;
  const Mesh l = mesh_of(land);
  const auto land_lists = madd::model_boundaries(l);
  check_cover(l, land_lists);
  REQUIRE(land_lists.size() == 2);
  CHECK(land_lists[0].kind == BoundaryKind::mainland);
  CHECK(land_lists[0].closed);
  CHECK(land_lists[0].nodes.front() == 0);  // point 0 is on the outer loop, the lowest id of all
  CHECK(land_lists[1].kind == BoundaryKind::island);
}

TEST_CASE("model_boundaries: a hole with an open part is split like the outer loop; open_marker chooses the kind") {
  madd::Pslg p = coast();
  p.segments[6].marker = 2;  // island A's bottom side (3, 2)-(5, 2) is open
  const Mesh m = mesh_of(p);
  const auto lists = madd::model_boundaries(m);
  check_cover(m, lists);
  check_runs_chain(lists);
  REQUIRE(lists.size() == 4);
  CHECK(lists[0].kind == BoundaryKind::open);
  CHECK(lists[1].kind == BoundaryKind::open);
  CHECK(m.points[lists[1].nodes.front()] == Point{5, 2});  // clockwise round the hole: from (5, 2) to (3, 2)
  CHECK(m.points[lists[1].nodes.back()] == Point{3, 2});
  CHECK(lists[2].kind == BoundaryKind::mainland);
  CHECK(lists[3].kind == BoundaryKind::mainland);
  CHECK(lists[3].nodes.front() == lists[1].nodes.back());
  // Marker 1 as the open one: everything but the sea is open.
  const auto swapped = madd::model_boundaries(m, 1);
  check_cover(m, swapped, 1);
  for (const ModelBoundary& list : swapped) CHECK(list.kind != BoundaryKind::island);
}

TEST_CASE("model_boundaries: a malformed mesh is bad input, not a crash") {
  Mesh m = coast_mesh();
  m.neighbours.pop_back();
  CHECK_THROWS_AS(madd::model_boundaries(m), madd::InvalidInputError);
  // A neighbour across an edge at a boundary vertex that lacks the vertex.
  Mesh n = coast_mesh();
  bool broken = false;
  for (std::uint32_t t = 0; t < n.triangles.size() && !broken; ++t)
    for (std::uint32_t i = 0; i < 3 && !broken; ++i) {
      const std::uint32_t q = (i + 1) % 3, b = n.triangles[t][(i + 2) % 3];
      if (n.neighbours[t][i] != madd::no_index || n.neighbours[t][q] == madd::no_index) continue;
      for (std::uint32_t far = 0; far < n.triangles.size() && !broken; ++far)
        if (std::find(n.triangles[far].begin(), n.triangles[far].end(), b) == n.triangles[far].end())
          n.neighbours[t][q] = far, broken = true;
    }
  REQUIRE(broken);
  CHECK_THROWS_AS(madd::model_boundaries(n), madd::InvalidInputError);
  Mesh o = coast_mesh();
  o.triangles[0][0] = static_cast<std::uint32_t>(o.points.size());
  CHECK_THROWS_AS(madd::model_boundaries(o), madd::InvalidInputError);
  CHECK(madd::model_boundaries(Mesh{}).empty());
}

TEST_CASE("fort.14: every section line by line as the ADCIRC page lays it out") {
  const Mesh& m = coast_mesh();
  const ModelGrid g = lonlat_grid(m);
  const auto lines = lines_of(madd::format_fort14(m, g));
  const auto lists = madd::model_boundaries(m);
  CHECK(lines.at(0) == g.title);
  CHECK(count_line(lines.at(1), 2, "! NE NP") ==
        std::vector<std::int64_t>{static_cast<std::int64_t>(m.triangles.size()),
                                  static_cast<std::int64_t>(m.points.size())});
  std::size_t at = check_grid_lines(lines, 2, m, g);
  std::vector<ModelBoundary> open, land;
  for (const ModelBoundary& list : lists) (list.kind == BoundaryKind::open ? open : land).push_back(list);
  const auto total = [](const std::vector<ModelBoundary>& v) {
    std::int64_t n = 0;
    for (const auto& list : v) n += static_cast<std::int64_t>(list.nodes.size());
    return n;
  };
  CHECK(count_line(lines.at(at++), 1, "! NOPE")[0] == static_cast<std::int64_t>(open.size()));
  CHECK(count_line(lines.at(at++), 1, "! NETA")[0] == total(open));
  for (const ModelBoundary& list : open) {
    const auto head = count_line(lines.at(at++), 2, "! NVDLL IBTYPEE");
    CHECK(head[1] == 0);  // IBTYPEE 0: elevation specified
    CHECK(node_lines(lines, at, head[0]) == list.nodes);
  }
  CHECK(count_line(lines.at(at++), 1, "! NBOU")[0] == static_cast<std::int64_t>(land.size()));
  CHECK(count_line(lines.at(at++), 1, "! NVEL")[0] == total(land));  // the islands' repeated nodes counted
  bool island_seen = false;
  for (const ModelBoundary& list : land) {
    const auto head = count_line(lines.at(at++), 2, "! NVELL IBTYPE");
    const auto nodes = node_lines(lines, at, head[0]);
    CHECK(nodes == list.nodes);
    CHECK(head[1] == (list.kind == BoundaryKind::island ? 21 : 20));
    if (head[1] == 21) CHECK(nodes.front() == nodes.back());  // islands closed
    if (head[1] == 20) CHECK(!island_seen);                   // external before internal
    island_seen = island_seen || head[1] == 21;
  }
  CHECK(island_seen);
  CHECK(at == lines.size());
}

TEST_CASE("fort.14 reads back exactly and passes check_fort14") {
  const Mesh& m = coast_mesh();
  for (const ModelGrid& g : {ModelGrid{}, lonlat_grid(m)}) {
    const madd::Fort14 f = madd::parse_fort14(madd::format_fort14(m, g), "coast.14");
    CHECK(f.title == g.title);
    const auto& xy = g.coordinates.empty() ? m.points : g.coordinates;
    REQUIRE(f.points.size() == xy.size());
    for (std::size_t v = 0; v < xy.size(); ++v) {
      CHECK(same_bits(f.points[v].x, xy[v].x));
      CHECK(same_bits(f.points[v].y, xy[v].y));
      CHECK(same_bits(f.depths[v], g.depth.empty() ? 0.0 : g.depth[v]));
    }
    CHECK(f.elements == m.triangles);
    const auto lists = madd::model_boundaries(m);
    REQUIRE(f.open_boundaries.size() + f.land_boundaries.size() == lists.size());
    for (std::size_t k = 0; k < lists.size(); ++k) {
      const bool open = k < f.open_boundaries.size();
      const madd::Fort14Boundary& b = open ? f.open_boundaries[k] : f.land_boundaries[k - f.open_boundaries.size()];
      CHECK(b.nodes == lists[k].nodes);
      CHECK(b.type == (open ? 0 : lists[k].kind == BoundaryKind::island ? 21 : 20));
      CHECK(b.paired.empty());
    }
    const madd::Verification v = madd::check_fort14(f);
    CHECK_MESSAGE(v.ok(), (v.problems.empty() ? "" : v.problems[0]));
  }
}

TEST_CASE("hgrid.gr3: SCHISM's layout, islands not closed, flags 0 and 1") {
  const Mesh& m = coast_mesh();
  const ModelGrid g = lonlat_grid(m);
  const auto lines = lines_of(madd::format_gr3(m, g));
  CHECK(lines.at(0) == g.title);
  CHECK(count_line(lines.at(1), 2, "NE NP")[1] == static_cast<std::int64_t>(m.points.size()));
  const auto lists = gr3_lists(lines, check_grid_lines(lines, 2, m, g));
  const auto model = madd::model_boundaries(m);
  REQUIRE(lists.size() == model.size());
  const auto boundary = boundary_by_brute_force(m);
  for (std::size_t k = 0; k < lists.size(); ++k) {
    const auto& [flag, nodes] = lists[k];
    CHECK(flag == (model[k].kind == BoundaryKind::open ? -1 : model[k].kind == BoundaryKind::island ? 1 : 0));
    if (flag != 1) {
      CHECK(nodes == model[k].nodes);
      continue;
    }
    CHECK(nodes.size() + 1 == model[k].nodes.size());  // the island without its repeated first node
    CHECK(std::equal(nodes.begin(), nodes.end(), model[k].nodes.begin()));
    CHECK(nodes.front() != nodes.back());
    CHECK(boundary.count({nodes.back(), nodes.front()}) == 1);  // the closing edge is implied
  }
  // hgrid.ll: the same file with lon/lat coordinates; hgrid.gr3 in metres.
  CHECK(lines_of(madd::format_gr3(m, ModelGrid{})).size() == lines.size());
}

TEST_CASE("hgrid.gr3: an outer boundary all land is two exterior lists linked at both ends") {
  madd::Pslg land = coast();
  for (madd::Segment& s : land.segments) s.marker = 1;
  const Mesh m = mesh_of(land);
  const auto model = madd::model_boundaries(m);
  REQUIRE(model.size() == 2);
  const auto lines = lines_of(madd::format_gr3(m));
  const auto lists = gr3_lists(lines, 2 + m.points.size() + m.triangles.size());
  REQUIRE(lists.size() == 3);
  CHECK(lists[0].first == 0);
  CHECK(lists[1].first == 0);
  CHECK(lists[2].first == 1);
  const auto& a = lists[0].second;
  const auto& b = lists[1].second;
  CHECK(a.front() == b.back());
  CHECK(a.back() == b.front());
  std::vector<std::uint32_t> joined = a;
  joined.insert(joined.end(), b.begin() + 1, b.end());
  CHECK(joined == model[0].nodes);
  CHECK(std::abs(static_cast<std::ptrdiff_t>(a.size()) - static_cast<std::ptrdiff_t>(b.size())) <= 1);
  // fort.14 closes the same loop instead: one IBTYPE 20 list, first node repeated.
  const madd::Fort14 f = madd::parse_fort14(madd::format_fort14(m));
  REQUIRE(f.land_boundaries.size() == 2);
  CHECK(f.land_boundaries[0].type == 20);
  CHECK(f.land_boundaries[0].nodes.front() == f.land_boundaries[0].nodes.back());
  CHECK(madd::check_fort14(f).ok());
}

TEST_CASE(".2dm: MESH2D, ND with z = -depth, E3T with material = subdomain + 1, NS nodestrings") {
  const Mesh& m = coast_mesh();
  const ModelGrid g = lonlat_grid(m);
  const auto lines = lines_of(madd::format_2dm(m, g));
  CHECK(lines.at(0) == "MESH2D");
  CHECK(lines.at(1) == "NUM_MATERIALS_PER_ELEM 1");
  CHECK(lines.at(2) == "MESHNAME \"coast test grid\"");
  std::size_t at = 3;
  for (std::size_t v = 0; v < m.points.size(); ++v, ++at) {
    const auto w = words(lines.at(at));
    REQUIRE(w.size() == 5);
    CHECK(w[0] == "ND");
    CHECK(integer(w[1]) == static_cast<std::int64_t>(v + 1));
    CHECK(same_bits(real(w[2]), g.coordinates[v].x));
    CHECK(same_bits(real(w[3]), g.coordinates[v].y));
    CHECK(same_bits(real(w[4]), 0.0 - g.depth[v]));  // elevation; the dry point at -0.0 depth is z = 0
  }
  std::set<std::int64_t> materials;
  for (std::size_t t = 0; t < m.triangles.size(); ++t, ++at) {
    const auto w = words(lines.at(at));
    REQUIRE(w.size() == 6);
    CHECK(w[0] == "E3T");
    CHECK(integer(w[1]) == static_cast<std::int64_t>(t + 1));
    for (std::size_t i = 0; i < 3; ++i) CHECK(integer(w[2 + i]) == std::int64_t{m.triangles[t][i]} + 1);
    CHECK(integer(w[5]) == std::int64_t{m.triangle_subdomain[t]} + 1);
    materials.insert(integer(w[5]));
  }
  CHECK(materials.size() == m.subdomain_count());
  const auto strings = nodestrings(lines, at);
  const auto model = madd::model_boundaries(m);
  REQUIRE(strings.size() == model.size());
  for (std::size_t k = 0; k < model.size(); ++k) CHECK(strings[k] == model[k].nodes);
  ModelGrid untitled;
  untitled.title.clear();
  CHECK(lines_of(madd::format_2dm(m, untitled)).at(2).rfind("ND 1 ", 0) == 0);  // no MESHNAME
}

TEST_CASE("add_fort14, add_gr3, add_2dm write what format_* returns, on any thread count") {
  const Mesh& m = coast_mesh();
  const ModelGrid g = lonlat_grid(m);
  madd::test::TempDir dir("model-output");
  for (const unsigned threads : {1u, 3u}) {
    madd::OutputSet outputs;
    const std::string stem = (dir.path / ("coast" + std::to_string(threads))).string();
    madd::add_fort14(outputs, stem + ".14", m, g, threads);
    madd::add_gr3(outputs, stem + ".gr3", m, ModelGrid{}, threads);
    madd::add_gr3(outputs, stem + ".ll", m, g, threads);
    madd::add_2dm(outputs, stem + ".2dm", m, g, threads);
    CHECK_THROWS_AS(madd::add_2dm(outputs, stem + ".2dm", m, g), madd::OutputError);
    outputs.write();
    CHECK(madd::test::read_text(stem + ".14") == madd::format_fort14(m, g));
    CHECK(madd::test::read_text(stem + ".gr3") == madd::format_gr3(m));
    CHECK(madd::test::read_text(stem + ".ll") == madd::format_gr3(m, g));
    CHECK(madd::test::read_text(stem + ".2dm") == madd::format_2dm(m, g));
    CHECK(madd::read_fort14_file(stem + ".14") == madd::parse_fort14(madd::format_fort14(m, g), stem + ".14"));
  }
  CHECK_THROWS_AS(madd::read_fort14_file((dir.path / "missing.14").string()), madd::InputFileError);
}

TEST_CASE("a grid that does not fit the mesh is an OptionError naming the field") {
  const Mesh& m = coast_mesh();
  const auto field_of = [&](const ModelGrid& g, auto format) {
    try {
      format(m, g);
    } catch (const madd::OptionError& e) {
      return e.option();
    }
    return std::string("none");
  };
  ModelGrid short_xy = lonlat_grid(m);
  short_xy.coordinates.pop_back();
  ModelGrid nan_depth = lonlat_grid(m);
  nan_depth.depth[3] = std::nan("");
  ModelGrid inf_xy = lonlat_grid(m);
  inf_xy.coordinates[2].y = HUGE_VAL;
  ModelGrid two_lines;
  two_lines.title = "a\nb";
  ModelGrid quoted;
  quoted.title = "the \"coast\"";
  for (const auto format : {madd::format_fort14, madd::format_gr3, madd::format_2dm}) {
    CHECK(field_of(short_xy, format) == "coordinates");
    CHECK(field_of(inf_xy, format) == "coordinates");
    CHECK(field_of(nan_depth, format) == "depth");
    CHECK(field_of(two_lines, format) == "title");
  }
  CHECK(field_of(quoted, madd::format_2dm) == "title");
  CHECK(field_of(quoted, madd::format_fort14) == "none");
  madd::OutputSet outputs;
  CHECK_THROWS_AS(madd::add_fort14(outputs, "x.14", m, short_xy), madd::OptionError);
  CHECK(outputs.empty());
}

TEST_CASE("check_fort14 passes the square and names each problem of broken files") {
  CHECK(madd::check_fort14(madd::parse_fort14(square14)).ok());
  madd::Fort14 f = coast14();
  REQUIRE(madd::check_fort14(f).ok());
  {
    madd::Fort14 g = f;  // a boundary edge missing from the lists
    g.land_boundaries[0].nodes.pop_back();
    g.declared_land_nodes -= 1;
    const auto v = madd::check_fort14(g);
    CHECK(v.problems.size() == 1);
    CHECK(says(v, "is in no boundary list"));
  }
  {
    madd::Fort14 g = f;  // an island not closed
    island_of(g).nodes.pop_back();
    g.declared_land_nodes -= 1;
    const auto v = madd::check_fort14(g);
    CHECK(says(v, "an island is not closed"));
    CHECK(says(v, "is in no boundary list"));
  }
  {
    madd::Fort14 g = f;  // a clockwise element
    std::swap(g.elements[0][1], g.elements[0][2]);
    CHECK(says(madd::check_fort14(g), "element 1 (nodes"));
    CHECK(says(madd::check_fort14(g), "is clockwise"));
  }
  {
    madd::Fort14 g = f;  // counts lying
    g.declared_open_nodes += 1;
    g.declared_land_nodes += 2;
    const auto v = madd::check_fort14(g);
    CHECK(says(v, "NETA is " + std::to_string(g.declared_open_nodes) + " but the open boundaries list " +
                      std::to_string(g.declared_open_nodes - 1) + " nodes"));
    CHECK(says(v, "NVEL is " + std::to_string(g.declared_land_nodes)));
    CHECK(v.problems.size() == 2);
  }
  {
    madd::Fort14 g = f;  // a list the wrong way round
    std::reverse(g.open_boundaries[0].nodes.begin(), g.open_boundaries[0].nodes.end());
    CHECK(says(madd::check_fort14(g), "run with the domain on their right"));
    CHECK(says(madd::check_fort14(g), "is in no boundary list"));
  }
  {
    madd::Fort14 g = f;  // the island listed before the mainland
    std::swap(g.land_boundaries.front(), g.land_boundaries.back());
    CHECK(says(madd::check_fort14(g), "is external but comes after an internal boundary"));
  }
  {
    madd::Fort14 g = f;  // a boundary edge listed twice, a pair that is no boundary edge, a repeat, a short list
    g.open_boundaries.push_back(g.open_boundaries[0]);
    g.open_boundaries.push_back({0, {g.elements[0][0], g.elements[0][1], g.elements[0][1]}, {}, {}, 99});
    g.open_boundaries.push_back({0, {g.elements[0][0]}, {}, {}, 100});
    const auto v = madd::check_fort14(g);
    CHECK(says(v, "is in 2 lists"));
    CHECK(says(v, "repeat a node"));
    CHECK(says(v, "open boundary 4 (IBTYPEE 0, line 100) has fewer than 2 nodes"));
  }
  {
    madd::Fort14 g = f;  // a node in no element, an element twice
    g.points.push_back({0, 0});
    g.depths.push_back(1);
    g.elements.push_back(g.elements[5]);
    const auto v = madd::check_fort14(g);
    CHECK(says(v, "node " + std::to_string(g.points.size()) + " is in no element"));
    CHECK(says(v, "in two elements the same way round"));
  }
}

TEST_CASE("check_fort14: degenerate elements, bad ids, barriers' paired nodes, and the cap on each kind") {
  madd::Fort14 line;
  line.points = {{0, 0}, {1, 0}, {2, 0}};
  line.depths = {1, 1, 1};
  line.elements = {{0, 1, 2}, {0, 0, 1}};
  const auto v = madd::check_fort14(line);
  CHECK(says(v, "element 1 (nodes 1 2 3) is degenerate"));
  CHECK(says(v, "element 2 (nodes 1 1 2) repeats a node"));
  madd::Fort14 bad = line;
  bad.elements[0][2] = 3;
  bad.depths.pop_back();
  const auto w = madd::check_fort14(bad);
  CHECK(says(w, "element 1 names no node"));
  CHECK(says(w, "depths for 3"));
  // An IBTYPE 24 barrier counts its IBCONN nodes in NVEL.
  madd::Fort14 sq = madd::parse_fort14(square14);
  sq.land_boundaries[0].type = 24;
  sq.land_boundaries[0].paired = sq.land_boundaries[0].nodes;
  CHECK(says(madd::check_fort14(sq), "NVEL is 4 but the flow boundaries list 8 nodes"));
  sq.land_boundaries[0].paired.pop_back();
  CHECK(says(madd::check_fort14(sq), "its IBCONN list does not match"));
  // Every element flipped: the first 10 said, the others counted.
  madd::Fort14 f = coast14();
  for (auto& e : f.elements) std::swap(e[1], e[2]);
  const auto all = madd::check_fort14(f);
  CHECK(says(all, "... and " + std::to_string(f.elements.size() - 10) + " more bad elements"));
}

TEST_CASE("parse_fort14 takes ADCIRC's and SCHISM's comments, CRLF, blank lines, D exponents and barrier records") {
  const madd::Fort14 square = madd::parse_fort14(square14, "square.14");
  CHECK(square.title == "square");
  CHECK(square.points == std::vector<Point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  CHECK(square.declared_open_nodes == 2);
  CHECK(square.open_boundaries.at(0).line == 11);
  CHECK(square.land_boundaries.at(0).nodes == std::vector<std::uint32_t>{1, 2, 3, 0});
  std::string crlf;
  for (const std::string& l : lines_of(square14)) crlf += l + " \r\n\r\n";
  CHECK(madd::parse_fort14(crlf).points == square.points);
  CHECK(madd::parse_fort14(square_with(3, "1 0.0D0 +0.0d+00 5.0 ! JN X Y DP")).points == square.points);
  CHECK(madd::parse_fort14(square_with(3, "+1 .0e0 0. 5")).depths == square.depths);
  // Barrier records: IBTYPE 3 (node, 2 reals), 24 (node, IBCONN, 3 reals), 5 (node, IBCONN, 6 reals).
  std::string barriers = std::string(square14).substr(0, std::string(square14).find("1 = Number of land"));
  barriers += "3 ! NBOU\n5 ! NVEL\n1 3\n2 1.5 1\n1 24\n3 4 2.0 1 1\n1 5\n4 1 2 1 1 0.5 0.6 0.7\n";
  const madd::Fort14 b = madd::parse_fort14(barriers);
  REQUIRE(b.land_boundaries.size() == 3);
  CHECK(b.land_boundaries[0].values == std::vector<double>{1.5, 1});
  CHECK(b.land_boundaries[1].paired == std::vector<std::uint32_t>{3});
  CHECK(b.land_boundaries[1].values == std::vector<double>{2, 1, 1});
  CHECK(b.land_boundaries[2].values.size() == 6);
  CHECK(!says(madd::check_fort14(b), "NVEL is"));  // 1, then 2 and 2: the barriers' IBCONN nodes count
}

TEST_CASE("parse_fort14: every malformed record is a ParseError at its line and column") {
  const auto at = [](const madd::ParseError& e) { return std::to_string(e.line()) + ":" + std::to_string(e.column()); };
  CHECK(at(parse_error("")) == "1:1");
  CHECK(at(parse_error(square_with(2, "2"))) == "2:2");  // missing NP
  CHECK(parse_error(square_with(2, "2 -4")).message().find("negative") != std::string::npos);
  CHECK(at(parse_error(square_with(2, "9000 4"))) == "2:1");  // cannot fit
  CHECK(parse_error(square_with(2, "9000 4")).message().find("cannot fit") != std::string::npos);
  CHECK(at(parse_error(square_with(4, "3 1.0 0.0 5.0"))) == "4:1");     // JN out of sequence
  CHECK(at(parse_error(square_with(4, "2 1.0 0.0 5.0 7"))) == "4:15");  // extra number
  CHECK(at(parse_error(square_with(4, "2 1.0 0.0 deep"))) == "4:11");
  CHECK(parse_error(square_with(4, "2 1.0 nan 5")).message() == "expected a number for Y, got 'nan'");
  CHECK(parse_error(square_with(4, "2 1.0 -inf 5")).message() == "Y is not finite: '-inf'");
  CHECK(parse_error(square_with(4, "2 1e999 0 5")).message().find("out of the range") != std::string::npos);
  CHECK(at(parse_error(square_with(7, "1 4 1 2 3"))) == "7:3");  // NHY
  CHECK(at(parse_error(square_with(7, "1 3 1 5 3"))) == "7:7");  // node 5 of 4
  CHECK(at(parse_error(square_with(7, "1 3 1 2.0 3"))) == "7:7");
  CHECK(at(parse_error(square_with(9, "99999999 = Number of open boundaries"))) == "9:1");
  CHECK(at(parse_error(square_with(11, "2000000 0"))) == "11:1");
  CHECK(at(parse_error(square_with(16, "4 7"))) == "16:3");  // IBTYPE 7 is not listed
  CHECK(parse_error(square_with(16, "4 7")).message().find("IBTYPE 7 is not a type") != std::string::npos);
  CHECK(at(parse_error(square_with(12, "0"))) == "12:1");
  CHECK(at(parse_error(std::string(square14) + "\n\n5\n")) == "23:1");           // text after the end
  CHECK(at(parse_error(square_with(8, "2 3 1 3 4 ! ok\n3 3 1 3 4"))) == "9:3");  // an element too many: NOPE 3 3
}

TEST_CASE("parse_fort14: text cut after any line, or at any byte, fails cleanly") {
  const std::string full = madd::format_fort14(coast_mesh(), lonlat_grid(coast_mesh()));
  const madd::Fort14 whole = madd::parse_fort14(full);
  std::size_t cuts = 0;
  for (std::size_t end = full.find('\n'); end + 1 < full.size(); end = full.find('\n', end + 1), ++cuts) {
    const std::string message = parse_error(full.substr(0, end + 1)).message();
    CHECK((message.rfind("unexpected end of file: expected ", 0) == 0 ||
           message.find("cannot fit") != std::string::npos));
  }
  CHECK(cuts + 1 == lines_of(full).size());
  const std::string small = square14;
  for (std::size_t n = 0; n < small.size(); ++n) {
    try {
      const madd::Fort14 f = madd::parse_fort14(small.substr(0, n));
      CHECK(n + 1 == small.size());  // only the final line break may go
      CHECK(f == madd::parse_fort14(small));
    } catch (const madd::ParseError&) {}
  }
  CHECK(whole.elements.size() == coast_mesh().triangles.size());
}

}  // TEST_SUITE
