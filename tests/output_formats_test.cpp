// The gmsh, VTK and GeoJSON views read back: .geo structure (every segment
// one Line, loops closed and shared), VTK section counts and areas, GeoJSON
// through a strict little JSON parser, and, when gmsh is installed, a real
// `gmsh -2` run whose mesh must be conforming across every separator.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>

#include "madd/decomposition.hpp"
#include "madd/output_formats.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "interior_fixtures.hpp"
#include "output_formats_test_support.hpp"

namespace {

using namespace madd;
using namespace madd::test;
namespace fs = std::filesystem;

const Decomposition& key7() {
  static const Decomposition d = [] {
    DecomposeOptions o;
    o.subdomains = 7;
    return decompose(read_domain(MADD_DATA_DIR "/key.poly"), o);
  }();
  return d;
}

// madd::test::marked_square_domain in 4 subdomains.
const Decomposition& marked_square() {
  static const Decomposition d = [] {
    const Pslg p = marked_square_domain();
    DecomposeOptions o;
    o.subdomains = 4;
    return decompose(p, o);
  }();
  return d;
}

std::size_t ring_count(const Decomposition& d) {
  std::size_t n = 0;
  for (const Subdomain& s : d.subdomains) n += s.rings.size();
  return n;
}

void check_geo(const Decomposition& d) {
  const GeoModel g = parse_geo(format_geo(d));
  REQUIRE(g.points.size() == d.points.size());
  REQUIRE(g.lines.size() == d.segments.size());
  CHECK(g.loops.size() == ring_count(d));
  REQUIRE(g.surfaces.size() == d.subdomains.size());
  for (std::size_t i = 0; i < d.points.size(); ++i) CHECK(g.points[i] == d.points[i]);  // %.17g round-trips
  // Every segment is exactly one Line, and every Line is a segment.
  std::set<std::pair<std::uint32_t, std::uint32_t>> lines;
  for (const auto& [a, b] : g.lines) lines.insert({std::min(a, b), std::max(a, b)});
  CHECK(lines.size() == d.segments.size());
  for (std::size_t j = 0; j < d.segments.size(); ++j) CHECK(g.lines[j] == std::pair{d.segments[j].a, d.segments[j].b});
  // Loops are closed chains; separators are used by two loops, boundary pieces by one.
  std::vector<int> uses(d.segments.size(), 0);
  for (const auto& loop : g.loops) {
    REQUIRE(!loop.empty());
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const auto end_of = [&](std::int64_t l) { return l > 0 ? g.lines[l - 1].second : g.lines[-l - 1].first; };
      const auto start_of = [&](std::int64_t l) { return l > 0 ? g.lines[l - 1].first : g.lines[-l - 1].second; };
      CHECK(end_of(loop[k]) == start_of(loop[(k + 1) % loop.size()]));
      ++uses[static_cast<std::size_t>(std::abs(loop[k]) - 1)];
    }
  }
  const std::vector<std::uint32_t> owner = interior_segment_owners(d);
  for (std::uint32_t j = 0; j < d.segments.size(); ++j)
    CHECK(uses[j] == (d.is_separator(j) ? 2 : owner[j] != no_index ? 0 : 1));  // interior pieces are in no loop
  // Surface k+1 holds subdomain k's rings in order, and is its physical group.
  std::size_t next_loop = 1;
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    REQUIRE(g.surfaces[k].size() == d.subdomains[k].rings.size());
    for (const std::int64_t l : g.surfaces[k]) CHECK(l == static_cast<std::int64_t>(next_loop++));
    CHECK(g.physical_surfaces.at(static_cast<std::int64_t>(k) + 1) == "subdomain_" + std::to_string(k));
  }
  // Physical Curves: one per marker, holding exactly its pieces, boundary and interior alike.
  std::map<std::string, std::multiset<std::int64_t>> expected;
  for (std::uint32_t j = 0; j < d.segments.size(); ++j)
    if (!d.is_separator(j)) expected["boundary_" + std::to_string(d.segments[j].marker)].insert(j + 1);
  CHECK(g.physical_curves == expected);
  // Interior segments and isolated points are embedded in their subdomain's surface, and only there.
  std::map<std::int64_t, std::vector<std::int64_t>> lines_in, points_in;
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    const auto tag = static_cast<std::int64_t>(k) + 1;
    for (const std::uint32_t j : d.subdomains[k].interior_segments) lines_in[tag].push_back(std::int64_t{j} + 1);
    for (const std::uint32_t p : d.subdomains[k].interior_points) points_in[tag].push_back(std::int64_t{p} + 1);
  }
  CHECK(g.embedded_lines == lines_in);
  CHECK(g.embedded_points == points_in);
}

TEST_SUITE("output_formats") {

TEST_CASE("geo: every point, every segment once, one loop per ring, shared lines") {
  check_geo(key7());
  check_geo(marked_square());
  const std::string text = format_geo(marked_square());
  CHECK(text.find("Physical Curve(\"boundary_2\", 2)") != std::string::npos);
  CHECK(text.find("Physical Curve(\"boundary_-7\") =") != std::string::npos);  // gmsh picks the tag
}

TEST_CASE("geo: a fixed mesh size is written at every point") {
  GeoOptions o;
  o.mesh_size = 0.125;
  const std::string text = format_geo(marked_square(), o);
  CHECK(count_of(text, ", 0, 0.125};") == marked_square().points.size());
}

TEST_CASE("geojson: valid JSON, closed rings in the right orientation, exact coordinates") {
  for (const Decomposition* d : {&key7(), &marked_square()}) {
    const Json root = parse_json(format_geojson(*d));
    CHECK(root.at("type").text == "FeatureCollection");
    const auto& features = root.at("features").items;
    REQUIRE(features.size() == d->subdomains.size());
    for (std::size_t k = 0; k < features.size(); ++k) {
      const Subdomain& s = d->subdomains[k];
      CHECK(features[k].at("type").text == "Feature");
      CHECK(features[k].at("properties").at("id").number == static_cast<double>(k));
      CHECK(features[k].at("properties").at("area").number == s.area);
      CHECK(features[k].at("properties").at("weight").number == s.weight);
      CHECK(features[k].at("geometry").at("type").text == "Polygon");
      const auto& rings = features[k].at("geometry").at("coordinates").items;
      REQUIRE(rings.size() == s.rings.size());
      for (std::size_t r = 0; r < rings.size(); ++r) {
        const auto& positions = rings[r].items;
        REQUIRE(positions.size() == s.rings[r].size() + 1);
        CHECK(positions.size() >= 4);  // RFC 7946: a linear ring has four or more positions
        std::vector<Point> ring;
        for (const Json& p : positions) {
          REQUIRE(p.items.size() == 2);
          ring.push_back({p.items[0].number, p.items[1].number});
        }
        CHECK(ring.front() == ring.back());
        for (std::size_t i = 0; i < s.rings[r].size(); ++i) CHECK(ring[i] == d->points[s.rings[r][i]]);
        CHECK((ring_area(ring) > 0) == (r == 0));  // outer CCW, holes CW
      }
    }
  }
}

TEST_CASE("json checker rejects what JSON does not allow") {
  CHECK_THROWS(parse_json("{\"a\":1,}"));
  CHECK_THROWS(parse_json("[01]"));
  CHECK_THROWS(parse_json("[1.]"));
  CHECK_THROWS(parse_json("{\"a\" 1}"));
  CHECK_THROWS(parse_json("[nan]"));
  CHECK_THROWS(parse_json("[1] x"));
  CHECK(parse_json(" {\"a\":[-0.5e+3,true,null,\"x\\\"y\"]} ").at("a").items[0].number == -500.0);
}

TEST_CASE("vtk: consistent sections, triangles cover each subdomain exactly") {
  for (const Decomposition* d : {&key7(), &marked_square()}) {
    const VtkPolyData v = parse_vtk(format_vtk(*d));
    REQUIRE(v.points.size() == d->points.size());
    for (std::size_t i = 0; i < v.points.size(); ++i) CHECK(v.points[i] == d->points[i]);
    CHECK(v.vertices.empty());  // no isolated points here
    // Every segment is one line cell, in order, with its kind, marker and subdomain.
    REQUIRE(v.lines.size() == d->segments.size());
    const std::size_t first_triangle = v.lines.size();
    REQUIRE(v.subdomain.size() == first_triangle + v.cells.size());
    REQUIRE(v.area.size() == v.subdomain.size());
    REQUIRE(v.weight.size() == v.subdomain.size());
    std::vector<long> ring_owner(d->segments.size(), -1);
    for (std::size_t k = 0; k < d->subdomains.size(); ++k)
      for (const auto& ring : d->subdomains[k].ring_segments)
        for (const std::uint32_t j : ring)
          if (!d->is_separator(j)) ring_owner[j] = static_cast<long>(k);
    for (std::uint32_t j = 0; j < d->segments.size(); ++j) {
      CHECK(v.lines[j] == std::pair{d->segments[j].a, d->segments[j].b});
      CHECK(v.kind[j] == (d->is_separator(j) ? 2 : 1));
      CHECK(v.marker[j] == d->segments[j].marker);
      CHECK(v.subdomain[j] == ring_owner[j]);
    }
    std::vector<double> covered(d->subdomains.size(), 0.0);
    for (std::size_t c = 0; c < v.cells.size(); ++c) {
      const std::size_t cell = first_triangle + c;
      REQUIRE(v.cells[c].size() == 3);
      CHECK(v.kind[cell] == 0);
      CHECK(v.marker[cell] == 0);
      const auto k = static_cast<std::size_t>(v.subdomain[cell]);
      REQUIRE(k < d->subdomains.size());
      CHECK(v.area[cell] == d->subdomains[k].area);
      CHECK(v.weight[cell] == d->subdomains[k].weight);
      const double a = signed_area(v.points[v.cells[c][0]], v.points[v.cells[c][1]], v.points[v.cells[c][2]]);
      CHECK(a > 0);
      covered[k] += a;
    }
    for (std::size_t k = 0; k < covered.size(); ++k)
      CHECK(covered[k] == doctest::Approx(d->subdomains[k].area).epsilon(1e-9));
  }
}

TEST_CASE("interior output: geo embeds interior segments and isolated points, in their marker's curve") {
  const Decomposition d = interior_square().decomposition;
  check_geo(d);
  const GeoModel g = parse_geo(format_geo(d));
  CHECK(g.embedded_lines.at(1) == std::vector<std::int64_t>{8, 9, 10, 11});  // the loop, in subdomain 0
  CHECK(g.embedded_lines.at(2) == std::vector<std::int64_t>{12});            // the dangling segment
  CHECK(g.embedded_points.at(2) == std::vector<std::int64_t>{11});           // the isolated point
  CHECK(g.physical_curves.at("boundary_7").size() == 4);                     // the loop's marker
  CHECK(g.physical_curves.at("boundary_1").size() == 1);                     // the dangling piece: input marker 0, so 1
  CHECK(format_geo(d).find("Physical Curve(\"boundary_7\", 7)") != std::string::npos);
  // The isolated point's size is its subdomain's shortest segment (the dangling one, 0.3).
  CHECK(g.points.size() == d.points.size());
  const std::string text = format_geo(d);
  char expected[96];
  std::snprintf(expected, sizeof expected, "Point(11) = {0.75, 0.25, 0, %.17g};", distance(d.points[8], d.points[9]));
  CHECK(text.find(expected) != std::string::npos);
}

TEST_CASE("interior output: vtk has the isolated point as a vertex cell, interior pieces as lines") {
  const Decomposition d = interior_square().decomposition;
  const VtkPolyData v = parse_vtk(format_vtk(d));
  REQUIRE(v.vertices == std::vector<std::uint32_t>{10});
  REQUIRE(v.lines.size() == d.segments.size());
  const std::size_t lines = 1, triangles = 1 + d.segments.size();
  CHECK(v.kind[0] == 4);
  CHECK(v.subdomain[0] == 1);
  const std::vector<std::uint32_t> owner = interior_segment_owners(d);
  for (std::uint32_t j = 0; j < d.segments.size(); ++j) {
    const long expected_kind = d.is_separator(j) ? 2 : owner[j] != no_index ? 3 : 1;
    CHECK(v.kind[lines + j] == expected_kind);
    CHECK(v.marker[lines + j] == d.segments[j].marker);
    if (owner[j] != no_index) CHECK(v.subdomain[lines + j] == static_cast<long>(owner[j]));
  }
  // The triangles of a subdomain cover it and have its interior pieces as edges
  // and its isolated point as a vertex.
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  std::set<std::uint32_t> corners;
  std::vector<double> covered(2, 0.0);
  for (std::size_t c = 0; c < v.cells.size(); ++c) {
    const auto k = static_cast<std::size_t>(v.subdomain[triangles + c]);
    covered.at(k) += signed_area(v.points[v.cells[c][0]], v.points[v.cells[c][1]], v.points[v.cells[c][2]]);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = v.cells[c][i], b = v.cells[c][(i + 1) % 3];
      edges.insert({std::min(a, b), std::max(a, b)});
      corners.insert(a);
    }
  }
  for (const double a : covered) CHECK(a == doctest::Approx(0.5));
  for (std::uint32_t j = 7; j < d.segments.size(); ++j)
    CHECK(edges.count(std::minmax(d.segments[j].a, d.segments[j].b)) == 1);
  CHECK(corners.count(10) == 1);
}

TEST_CASE("interior output: vtk gives each triangle the input's regional attribute and area bound") {
  const InteriorFixture f = interior_square();
  const VtkPolyData v = parse_vtk(format_vtk(f.decomposition));
  REQUIRE(v.region_attribute.size() == v.subdomain.size());
  REQUIRE(v.region_max_area.size() == v.subdomain.size());
  // What Triangle's regional rule gives the input at a point (madd::triangulate, the same rule).
  TriangulateOptions options;
  options.region_attributes = true;
  Pslg areas = f.domain;
  for (Region& r : areas.regions) r.attribute = r.max_area;
  const Triangulation attribute = triangulate(f.domain, options), area = triangulate(areas, options);
  const auto at = [](const Triangulation& tri, Point p) {
    for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
      const auto& c = tri.triangles[t];
      if (orient2d(tri.points[c[0]], tri.points[c[1]], p) > 0 && orient2d(tri.points[c[1]], tri.points[c[2]], p) > 0 &&
          orient2d(tri.points[c[2]], tri.points[c[0]], p) > 0)
        return tri.attributes[t];
    }
    return -99.0;
  };
  const std::size_t first = v.vertices.size() + v.lines.size();
  for (std::size_t c = 0; c < first; ++c) {
    CHECK(v.region_attribute[c] == 0);
    CHECK(v.region_max_area[c] == -1);
  }
  std::set<double> seen;
  for (std::size_t c = 0; c < v.cells.size(); ++c) {
    const auto& t = v.cells[c];
    const Point m{(v.points[t[0]].x + v.points[t[1]].x + v.points[t[2]].x) / 3,
                  (v.points[t[0]].y + v.points[t[1]].y + v.points[t[2]].y) / 3};
    CHECK(v.region_attribute[first + c] == at(attribute, m));
    CHECK(v.region_max_area[first + c] == at(area, m));
    seen.insert(v.region_attribute[first + c]);
  }
  CHECK(seen == std::set<double>{2, 3});  // both regions show
  // Without the input's regions there are no region arrays.
  Decomposition plain = f.decomposition;
  plain.regions.clear();
  CHECK(parse_vtk(format_vtk(plain)).region_attribute.empty());
}

TEST_CASE("interior output: geojson has a LineString per interior piece and a Point per isolated point") {
  const Decomposition d = interior_square().decomposition;
  const Json root = parse_json(format_geojson(d));
  const auto& features = root.at("features").items;
  REQUIRE(features.size() == 2 + 5 + 1);
  for (std::size_t k = 0; k < 2; ++k) CHECK(features[k].at("geometry").at("type").text == "Polygon");
  std::size_t lines = 0;
  for (std::size_t i = 2; i < features.size(); ++i) {
    const Json& f = features[i];
    const auto k = static_cast<std::size_t>(f.at("properties").at("subdomain").number);
    REQUIRE(k < d.subdomains.size());
    const Json& geometry = f.at("geometry");
    if (geometry.at("type").text == "LineString") {
      ++lines;
      const auto j = static_cast<std::uint32_t>(f.at("properties").at("segment").number) - 1;
      const auto& sub = d.subdomains[k].interior_segments;
      CHECK(std::find(sub.begin(), sub.end(), j) != sub.end());
      CHECK(f.at("properties").at("marker").number == d.segments[j].marker);
      const auto& at = geometry.at("coordinates").items;
      REQUIRE(at.size() == 2);
      CHECK(Point{at[0].items[0].number, at[0].items[1].number} == d.points[d.segments[j].a]);
      CHECK(Point{at[1].items[0].number, at[1].items[1].number} == d.points[d.segments[j].b]);
    } else {
      REQUIRE(geometry.at("type").text == "Point");
      CHECK(k == 1);
      CHECK(f.at("properties").at("point").number == 11);
      const auto& at = geometry.at("coordinates").items;
      CHECK(Point{at[0].number, at[1].number} == d.points[10]);
    }
  }
  CHECK(lines == 5);
}

TEST_CASE("gmsh meshes the .geo conformingly (skipped without gmsh)") {
  if (std::system("command -v gmsh >/dev/null 2>&1") != 0) {
    MESSAGE("skipped: gmsh is not installed (apt-get install gmsh to run this check)");
    return;
  }
  const fs::path dir = fs::temp_directory_path() / ("madd-geo-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const Decomposition interior = interior_square().decomposition;
  for (const Decomposition* d : {&key7(), &marked_square(), &interior}) {
    const fs::path geo = dir / "d.geo";
    const fs::path msh = dir / "d.msh";
    // A size well below the separators' lengths, so separators get nodes inside them too.
    double area = 0;
    for (const Subdomain& s : d->subdomains) area += s.area;
    GeoOptions options;
    options.mesh_size = std::sqrt(area / static_cast<double>(d->subdomains.size())) / 6;
    std::ofstream(geo) << format_geo(*d, options);
    const std::string command = "gmsh -2 -format msh22 '" + geo.string() + "' -o '" + msh.string() + "' > '" +
                                (dir / "gmsh.log").string() + "' 2>&1";
    REQUIRE_MESSAGE(std::system(command.c_str()) == 0, "gmsh failed, see " << (dir / "gmsh.log").string());
    std::ifstream in(msh);
    std::stringstream text;
    text << in.rdbuf();
    check_gmsh_mesh(*d, parse_msh22(text.str()));
    check_gmsh_embedded(*d, parse_msh22(text.str()));
  }
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}

}  // TEST_SUITE("output_formats")

}  // namespace
