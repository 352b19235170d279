// Interior constraints in the .poly outputs (docs/formats.md, "Interior
// segments in the outputs"): the faces the region points go to, output 1 and
// every output 2 file read back, and what Triangle's regional rule (here
// madd::triangulate with region attributes, the same rule) then gives every
// triangle: the subdomain number, or the input's own attribute and area bound.
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/output.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "interior_fixtures.hpp"
#include "kernel/rings.hpp"
#include "metrics_fixtures.hpp"
#include "output/faces.hpp"
#include "scratch_files.hpp"

namespace {

using namespace madd;
using madd::test::interior_square;

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// True when p is strictly inside subdomain k (inside its outer ring, outside its holes).
bool strictly_inside(const Decomposition& d, std::uint32_t k, Point p) {
  using detail::RingLocation, detail::RingView;
  const Subdomain& s = d.subdomains[k];
  if (detail::locate_in_ring(RingView(d.points, s.rings[0]), p) != RingLocation::inside) return false;
  for (std::size_t r = 1; r < s.rings.size(); ++r)
    if (detail::locate_in_ring(RingView(d.points, s.rings[r]), p) != RingLocation::outside) return false;
  return true;
}

bool on_any_segment(const Decomposition& d, Point p) {
  for (const Segment& s : d.segments) {
    const Point a = d.points[s.a], b = d.points[s.b];
    if (orient2d(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
        p.y <= std::max(a.y, b.y))
      return true;
  }
  return false;
}

// The loop of the fixture, points 4-7 counter-clockwise.
bool inside_loop(const Decomposition& d, Point p) {
  const std::vector<std::uint32_t> loop{4, 5, 6, 7};
  return detail::locate_in_ring(detail::RingView(d.points, loop), p) == detail::RingLocation::inside;
}

Point centroid(const Triangulation& tri, std::uint32_t t) {
  const Point a = tri.points[tri.triangles[t][0]], b = tri.points[tri.triangles[t][1]],
              c = tri.points[tri.triangles[t][2]];
  return {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
}

// The regional attribute of the triangle of `tri` holding p. On an edge of
// `tri` either side will do: an edge between two regions is a segment, which
// the file has too, so a centroid of the file's triangles is never on one.
double attribute_at(const Triangulation& tri, Point p) {
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    const Point a = tri.points[tri.triangles[t][0]], b = tri.points[tri.triangles[t][1]],
                c = tri.points[tri.triangles[t][2]];
    if (orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0) return tri.attributes[t];
  }
  FAIL("no triangle holds (" << p.x << ", " << p.y << ")");
  return 0;
}

// The PSLG with each region's max area as its attribute, so that
// triangulate's regional attributes show the area bound of every triangle.
// A bound <= 0 is none for Triangle, as is no region at all (attribute 0).
Pslg areas_as_attributes(Pslg p) {
  for (Region& r : p.regions) r.attribute = r.max_area > 0 ? r.max_area : 0.0;
  return p;
}

Triangulation with_regions(const Pslg& p) {
  validate_pslg(p);
  TriangulateOptions options;
  options.region_attributes = true;
  return triangulate(p, options);
}

// Every triangle of `file` gets, by Triangle's regional rule, the attribute
// and the area bound the input gives at the same place.
void check_regions_as_input(const Pslg& file, const Pslg& input) {
  const Triangulation got = with_regions(file), want = with_regions(input);
  const Triangulation got_area = with_regions(areas_as_attributes(file)),
                      want_area = with_regions(areas_as_attributes(input));
  REQUIRE(got.triangle_count() > 0);
  for (std::uint32_t t = 0; t < got.triangle_count(); ++t) {
    const Point c = centroid(got, t);
    CHECK(got.attributes[t] == attribute_at(want, c));
  }
  for (std::uint32_t t = 0; t < got_area.triangle_count(); ++t) {
    const Point c = centroid(got_area, t);
    CHECK(got_area.attributes[t] == attribute_at(want_area, c));
  }
}

}  // namespace

TEST_SUITE("output") {

TEST_CASE("interior output: a face per part of a subdomain, each with the input region covering it") {
  const test::InteriorFixture f = interior_square();
  Decomposition d = f.decomposition;
  const std::vector<detail::DecompositionFace> faces = detail::decomposition_faces(d);
  REQUIRE(faces.size() == 3);  // the left half is cut in two by its loop
  CHECK(faces[0].subdomain == 0);
  CHECK(faces[1].subdomain == 0);
  CHECK(faces[2].subdomain == 1);
  int in_loop = 0;
  for (const detail::DecompositionFace& face : faces) {
    CHECK(strictly_inside(d, face.subdomain, face.point));
    CHECK(!on_any_segment(d, face.point));
    const bool loop = inside_loop(d, face.point);
    in_loop += loop;
    // Region A is inside the loop; B, in the right half, covers the rest of
    // the square: the separator does not stop it.
    CHECK(face.region == (loop ? 0U : 1U));
  }
  CHECK(in_loop == 1);
  // A region point strictly inside the face it covers is the face's point.
  CHECK(faces[0].point != f.domain.regions[1].at);  // B is not in the left half
  CHECK((faces[1].point == f.domain.regions[0].at || faces[0].point == f.domain.regions[0].at));
  CHECK(faces[2].point == f.domain.regions[1].at);

  SUBCASE("a region point on the separator covers both sides, whichever it is given to") {
    d.regions.push_back({{0.5, 0.3}, 9, -1});
    for (const detail::DecompositionFace& face : detail::decomposition_faces(d)) {
      CHECK(face.region == (inside_loop(d, face.point) ? 0U : 2U));
      CHECK(!on_any_segment(d, face.point));  // not the region's own point: it is on the separator
    }
    // Earlier in the file than B, it loses to B (Triangle: the later region wins).
    d.regions = {{{0.5, 0.3}, 9, -1}, f.domain.regions[0], f.domain.regions[1]};
    for (const detail::DecompositionFace& face : detail::decomposition_faces(d))
      CHECK(face.region == (inside_loop(d, face.point) ? 1U : 2U));
  }
  SUBCASE("a region point outside the domain covers nothing") {
    d.regions = {{{2, 2}, 9, -1}, f.domain.regions[0]};
    for (const detail::DecompositionFace& face : detail::decomposition_faces(d))
      CHECK(face.region == (inside_loop(d, face.point) ? 1U : no_index));
  }
  SUBCASE("without regions, the faces are the same, covered by none") {
    d.regions.clear();
    const std::vector<detail::DecompositionFace> plain = detail::decomposition_faces(d);
    REQUIRE(plain.size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
      CHECK(plain[i].subdomain == faces[i].subdomain);
      CHECK(strictly_inside(d, plain[i].subdomain, plain[i].point));
      CHECK(!on_any_segment(d, plain[i].point));
      CHECK(inside_loop(d, plain[i].point) == inside_loop(d, faces[i].point));
      CHECK(plain[i].region == no_index);
    }
  }
}

TEST_CASE("interior output: without interior segments each subdomain is one face at its interior point") {
  for (const test::Fixture& fixture : test::all_fixtures()) {
    Decomposition d = fixture.decomposition;
    for (const bool regions : {false, true}) {
      if (regions) d.regions = {{d.subdomains[0].interior_point, 4, 0.5}};
      const std::vector<detail::DecompositionFace> faces = detail::decomposition_faces(d);
      REQUIRE(faces.size() == d.subdomains.size());
      for (std::uint32_t k = 0; k < faces.size(); ++k) {
        CHECK(faces[k].subdomain == k);
        CHECK(faces[k].point == d.subdomains[k].interior_point);
        // The domain is one region of the input: the one region point covers all of it.
        CHECK(faces[k].region == (regions ? 0U : no_index));
      }
    }
  }
}

TEST_CASE("interior output 1: interior pieces with their markers, every face labelled with its subdomain") {
  Decomposition d = interior_square().decomposition;
  d.regions.clear();
  const PolyFile back = parse_poly(format_decomposition_poly(d));
  CHECK(back.pslg.points == d.points);
  CHECK(back.pslg.segments == d.segments);  // separators 0, the loop 7, the dangling piece 1
  validate_pslg(back.pslg);
  REQUIRE(back.pslg.regions.size() == 3);
  for (const Region& r : back.pslg.regions) CHECK(r.max_area == -1);
  // triangle -pA: every triangle, inside the loop too, gets its subdomain's number.
  const Triangulation tri = with_regions(back.pslg);
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    const Point c = centroid(tri, t);
    CHECK(strictly_inside(d, static_cast<std::uint32_t>(tri.attributes[t]), c));
  }
}

TEST_CASE("interior output 1: with input regions, every triangle gets the input's attribute and area bound") {
  const test::InteriorFixture f = interior_square();
  const std::string text = format_decomposition_poly(f.decomposition);
  const PolyFile back = parse_poly(text);
  CHECK(back.pslg.points == f.decomposition.points);
  CHECK(back.pslg.segments == f.decomposition.segments);
  REQUIRE(back.pslg.regions.size() == 3);  // one per face, not per input region
  check_regions_as_input(back.pslg, f.domain);
  // Each region line names its subdomain in a comment.
  CHECK(count_of(text, "# subdomain 0") == 2);
  CHECK(count_of(text, "# subdomain 1") == 1);
}

TEST_CASE("interior output 2: each file has its interior segments, isolated points and regions") {
  const test::InteriorFixture f = interior_square();
  const Decomposition& d = f.decomposition;
  test::TempDir tmp("output");
  write_split(d, (tmp.path / "parts").string(), "sq");
  for (std::uint32_t k = 0; k < 2; ++k) {
    const std::string text = format_subdomain_poly(d, k);
    CHECK(test::read_text(tmp.path / "parts" / split_file_name("sq", k, 2)) ==
          text);  // faces computed once or per file
    const PolyFile back = parse_poly(text);
    validate_pslg(back.pslg);
    const Subdomain& sub = d.subdomains[k];
    // Segments: the ring, then the interior pieces, by coordinates (either
    // direction: rings are written as they walk) with their markers.
    using Key = std::tuple<double, double, double, double>;
    const auto key = [](Point a, Point b) {
      if (std::tie(b.x, b.y) < std::tie(a.x, a.y)) std::swap(a, b);
      return Key{a.x, a.y, b.x, b.y};
    };
    std::map<Key, int> want, got;
    std::set<std::uint32_t> used;
    for (const auto& ring : sub.ring_segments)
      for (const std::uint32_t j : ring) used.insert(j);
    used.insert(sub.interior_segments.begin(), sub.interior_segments.end());
    for (const std::uint32_t j : used)
      want[key(d.points[d.segments[j].a], d.points[d.segments[j].b])] = d.segments[j].marker;
    for (const Segment& s : back.pslg.segments) got[key(back.pslg.points[s.a], back.pslg.points[s.b])] = s.marker;
    CHECK(got == want);
    CHECK(back.pslg.segments.size() == used.size());
    // Points: those of the segments, and the isolated ones.
    std::set<std::pair<double, double>> points;
    for (const Point& p : back.pslg.points) points.insert({p.x, p.y});
    CHECK(points.size() == back.pslg.points.size());
    for (const std::uint32_t p : sub.interior_points) CHECK(points.count({d.points[p].x, d.points[p].y}) == 1);
    CHECK(back.pslg.points.size() == (k == 0 ? 4 + 4 : 4 + 2 + 1));
    // Regions: one per face of this subdomain, each the input's there.
    CHECK(back.pslg.regions.size() == (k == 0 ? 2U : 1U));
    check_regions_as_input(back.pslg, f.domain);
  }
  SUBCASE("without input regions a file has no regions") {
    Decomposition plain = d;
    plain.regions.clear();
    for (std::uint32_t k = 0; k < 2; ++k) CHECK(parse_poly(format_subdomain_poly(plain, k)).pslg.regions.empty());
  }
}

TEST_CASE("interior output 4: SVG draws interior segments dashed and isolated points as dots") {
  const Decomposition d = interior_square().decomposition;
  const std::string svg = format_svg(d);
  CHECK(count_of(svg, "<path ") == d.subdomains.size() + 3);
  CHECK(count_of(svg, "stroke-dasharray") == 1);
  CHECK(count_of(svg, "<circle ") == 1);
  CHECK(count_of(svg, "<g ") == count_of(svg, "</g>"));
  // The loop's four pieces chain into one polyline: one move, then five points.
  const std::size_t dash = svg.find("stroke-dasharray");
  const std::size_t data = svg.find(" d=\"", dash) + 4;
  const std::string path = svg.substr(data, svg.find('"', data) - data);
  CHECK(count_of(path, "M") == 2);  // the loop, then the dangling segment
}

}  // TEST_SUITE("output")

// ---- round trips: decompose, write, read back with the library's reader ----
namespace {

// Triangle's face.poly kind of domain: a rectangle holding a closed interior
// loop, an open polyline with a branch off its middle vertex (a Y), a segment
// from the boundary into the interior, an isolated vertex and two regions
// (inside the loop, and the rest).
const char* const face_poly = R"(# a face.poly kind of domain
15 2 0 0
1 0 0
2 4 0
3 4 1
4 4 2
5 0 2
6 0.5 0.5
7 1.5 0.5
8 1.5 1.5
9 0.5 1.5
10 2.2 0.3
11 2.6 0.8
12 3.0 0.6
13 3.4 1.0
14 2.6 1.4
15 3.5 1.6
13 1
1 1 2 1
2 2 3 2
3 3 4 2
4 4 5 3
5 5 1 4
6 6 7 5
7 7 8 5
8 8 9 5
9 9 6 5
10 10 11 6
11 11 12 6
12 3 13 0
13 11 14 6
0
2
1 1.0 1.0 1 0.05
2 3.0 1.2 2 0.2
)";

// Every triangle of the re-read output 1 without input regions gets its
// subdomain's number (triangle -pA).
void check_labelled_by_subdomain(const Pslg& file, const Decomposition& d) {
  const Triangulation tri = with_regions(file);
  REQUIRE(tri.triangle_count() > 0);
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    const double k = tri.attributes[t];
    REQUIRE(k >= 0);
    REQUIRE(k < static_cast<double>(d.subdomains.size()));
    CHECK(strictly_inside(d, static_cast<std::uint32_t>(k), centroid(tri, t)));
  }
}

// decompose -> output 1 -> parse_poly -> validate -> the same points and
// segments (markers too), the regions as designed -> decompose again; and
// every output 2 file a valid domain with the regions as designed.
void check_round_trip(const Pslg& domain, std::uint32_t n) {
  const Decomposition d = decompose(domain, [&] {
    DecomposeOptions o;
    o.subdomains = n;
    return o;
  }());
  REQUIRE(verify_decomposition(d, domain, n).ok());
  const PolyFile back = parse_poly(format_decomposition_poly(d, "round trip"));
  CHECK_NOTHROW(validate(back.pslg, back.source));
  CHECK(back.pslg.points == d.points);
  CHECK(back.pslg.segments == d.segments);  // separators (0), boundary and interior pieces, in order
  CHECK(back.pslg.holes == d.holes);
  CHECK(back.pslg.regions.size() >= d.subdomains.size());  // one per face
  if (domain.regions.empty()) {
    check_labelled_by_subdomain(back.pslg, d);
  } else {
    check_regions_as_input(back.pslg, domain);
  }
  // Decomposed again: its separators are now interior segments.
  DecomposeOptions again;
  again.subdomains = n;
  const Decomposition d2 = decompose(back.pslg, again);
  const Verification v = verify_decomposition(d2, back.pslg, n);
  CHECK_MESSAGE(v.ok(), (v.problems.empty() ? std::string() : v.problems.front()));
  for (std::uint32_t k = 0; k < n; ++k) {
    const PolyFile part = parse_poly(format_subdomain_poly(d, k));
    CHECK_NOTHROW(validate(part.pslg, part.source));
    if (!domain.regions.empty()) check_regions_as_input(part.pslg, domain);
    else CHECK(part.pslg.regions.empty());
  }
}

}  // namespace

TEST_SUITE("output") {

TEST_CASE("interior output round trip: a domain without interior constraints") {
  check_round_trip(read_domain(std::string(MADD_DATA_DIR) + "/key.poly"), 8);
  // One region, its point the centroid of a triangle of the domain (so inside it).
  Pslg with_region = read_domain(std::string(MADD_DATA_DIR) + "/key.poly");
  with_region.regions = {{centroid(triangulate(with_region), 0), 5, 0.5}};
  check_round_trip(with_region, 5);
}

TEST_CASE("interior output round trip: a face.poly kind of domain") {
  const PolyFile face = parse_poly(face_poly, "face.poly");
  validate(face.pslg, face.source);
  check_round_trip(face.pslg, 4);
  Pslg no_regions = face.pslg;
  no_regions.regions.clear();
  check_round_trip(no_regions, 4);
}

TEST_CASE("interior output round trip: data/estuary.poly (every kind of interior constraint, a region in a loop)") {
  check_round_trip(read_domain(std::string(MADD_DATA_DIR) + "/estuary.poly"), 6);
}

}  // TEST_SUITE("output")

#ifdef MADD_CLI_PATH
namespace {

// What a run of the CLI gave: its exit code and its output (a struct, not a
// pair to unpack: clang 14 cannot capture a structured binding in the
// lambdas the _MESSAGE checks expand to).
struct Run {
  int code;
  std::string text;
};

// Runs the CLI in `dir`; its exit code and standard output.
Run run_madd(const std::filesystem::path& dir, const std::string& args) {
  const std::string command =
      "cd '" + dir.string() + "' && '" MADD_CLI_PATH "' " + args + " > stdout.txt 2> stderr.txt";
  const int status = std::system(command.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return {code, test::read_text(dir / "stdout.txt") + test::read_text(dir / "stderr.txt")};
}

}  // namespace

TEST_SUITE("output") {

TEST_CASE(
    "interior output through the CLI: every output of a face.poly kind of domain, and madd check on the .poly files") {
  test::TempDir tmp("output-interior-cli");
  {
    std::ofstream out(tmp.path / "face.poly");
    out << face_poly;
  }
  const Run run = run_madd(tmp.path, "decompose face.poly -n 4 -o all.poly --split parts --subdomains-file face.sub "
                                     "--svg face.svg --geo face.geo --vtk face.vtk --geojson face.json -q");
  REQUIRE_MESSAGE(run.code == 0, run.text);
  for (const char* file :
       {"all.poly", "parts/face-0.poly", "parts/face-1.poly", "parts/face-2.poly", "parts/face-3.poly"}) {
    const Run check = run_madd(tmp.path, std::string("check ") + file);
    CHECK_MESSAGE(check.code == 0, check.text);
    CHECK_MESSAGE(check.text.find(std::string(file) + ": valid domain") != std::string::npos, check.text);
  }
  const Run again = run_madd(tmp.path, "decompose all.poly -n 4 -o again.poly -q");
  CHECK_MESSAGE(again.code == 0, again.text);
}

}  // TEST_SUITE("output")
#endif
