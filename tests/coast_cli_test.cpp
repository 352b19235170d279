// The coastal path from the outside (docs/coastal.md): GeoJSON and
// shapefiles where a .poly goes, the box, the cleaning report, the model
// files and `madd check FILE.14`. Runs the madd binary (skipped when the CLI
// is not built).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_sandbox.hpp"
#include "madd/coast.hpp"
#include "madd/model_output.hpp"
#include "madd/poly_io.hpp"

#ifdef MADD_CLI_PATH

namespace {

using madd_test::CliRun;
using madd_test::CliSandbox;

const std::string coast_dir = std::string(MADD_DATA_DIR) + "/coast/";
const std::string bay_box = " --clip -70.0,43.5,-69.5,43.9";

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("coast cli") {

TEST_CASE("madd check: the bay's GeoJSON and its shapefile make the same domain, written with --write-poly") {
  const CliSandbox box("madd-coast-cli");
  const CliRun g = box.run("check " + coast_dir + "bay.geojson" + bay_box + " --write-poly g.poly");
  const CliRun s = box.run("check " + coast_dir + "bay.shp" + bay_box + " --write-poly s.poly");
  REQUIRE_MESSAGE(g.status == 0, g.output);
  REQUIRE_MESSAGE(s.status == 0, s.output);
  CHECK(contains(g.output, "302 rings read; kept 1 of 2 water bodies"));
  CHECK(contains(g.output, "valid domain"));
  // The comment names the file read; every line after it is the same.
  const std::string a = slurp(box.path("g.poly")), b = slurp(box.path("s.poly"));
  CHECK(a.substr(a.find('\n')) == b.substr(b.find('\n')));
  // The written domain reads back as a valid domain whose area is the report's.
  const madd::Pslg domain = madd::read_domain(box.path("g.poly").string());
  madd::CoastOptions options;
  options.clip = madd::ClipBox{-70.0, 43.5, -69.5, 43.9};
  const madd::CoastDomain direct = madd::read_coast(coast_dir + "bay.geojson", options);
  CHECK(domain == direct.domain);
  CHECK(madd::domain_area(domain) == doctest::Approx(direct.report.area_m2));
}

TEST_CASE("madd mesh: from the bay's GeoJSON and depth grid to fort.14, hgrid.gr3/.ll and .2dm that check") {
  const CliSandbox box("madd-coast-cli");
  const CliRun run = box.run("mesh " + coast_dir + "bay.geojson" + bay_box +
                             " --hmin 200 --hmax 4000 --distance-rate 0.2 --cells-across 2 --gradation 0.25"
                             " --depth " +
                             coast_dir +
                             "depth.asc --wavelength-cells 50 -n 8 -j 2 -o bay"
                             " --fort14 bay.14 --gr3 hgrid.gr3 --2dm bay.2dm");
  REQUIRE_MESSAGE(run.status == 0, run.output);
  for (const char* file : {"bay.node", "bay.ele", "bay.14", "hgrid.gr3", "hgrid.ll", "bay.2dm"})
    CHECK(std::filesystem::exists(box.path(file)));
  const CliRun check = box.run("check bay.14");
  CHECK_MESSAGE(check.status == 0, check.output);
  CHECK(contains(check.output, "valid fort.14"));
  // Read back: lon/lat inside the box, depths from the grid (positive in the water), counts as the .ele says.
  const madd::Fort14 grid = madd::read_fort14_file(box.path("bay.14").string());
  CHECK(madd::check_fort14(grid).ok());
  for (const madd::Point p : grid.points) {
    REQUIRE(p.x >= -70.0 - 1e-9);
    REQUIRE(p.x <= -69.5 + 1e-9);
    REQUIRE(p.y >= 43.5 - 1e-9);
    REQUIRE(p.y <= 43.9 + 1e-9);
  }
  std::size_t deep = 0;
  for (const double d : grid.depths) deep += d > 1.0 ? 1 : 0;
  CHECK(deep > grid.depths.size() / 2);
  std::istringstream ele(slurp(box.path("bay.ele")));
  std::size_t triangles = 0;
  ele >> triangles;
  CHECK(grid.elements.size() == triangles);
  CHECK(!grid.open_boundaries.empty());
  CHECK(!grid.land_boundaries.empty());
}

TEST_CASE("madd mesh: the model files and --lonlat's mesh files, all written from the pieces, agree point for point") {
  // madd mesh never merges the mesh (docs/mesh.md, "Meshes in pieces"):
  // fort.14, hgrid.ll, .2dm and the --lonlat .node/.ele are each written
  // from the subdomains' meshes (tests/mesh_pieces_test.cpp compares each
  // with the merged mesh's file). Here they must describe one mesh.
  const CliSandbox box("madd-coast-cli");
  const std::string common = "mesh " + coast_dir + "bay.geojson" + bay_box +
                             " --hmin 200 --hmax 4000 --distance-rate 0.2 --cells-across 2 --gradation 0.25 -n 8 -j 2";
  const CliRun metres = box.run(common + " -o m");
  const CliRun lonlat = box.run(common + " -o ll --lonlat --fort14 ll.14 --gr3 ll.gr3 --2dm ll.2dm");
  REQUIRE_MESSAGE(metres.status == 0, metres.output);
  REQUIRE_MESSAGE(lonlat.status == 0, lonlat.output);
  CHECK(slurp(box.path("m.ele")) == slurp(box.path("ll.ele")));  // the same triangles, whatever the units
  // The .node's points (lon/lat) are fort.14's and hgrid.ll's, exactly.
  std::istringstream node(slurp(box.path("ll.node")));
  std::size_t count = 0, dimension = 0, attributes = 0, markers = 0;
  node >> count >> dimension >> attributes >> markers;
  std::vector<madd::Point> points(count);
  for (madd::Point& p : points) {
    std::size_t id = 0;
    int marker = 0;
    node >> id >> p.x >> p.y >> marker;
  }
  REQUIRE(node);
  const madd::Fort14 grid = madd::read_fort14_file(box.path("ll.14").string());
  CHECK(grid.points == points);
  // hgrid.gr3 (metres) and hgrid.ll (lon/lat): fort.14's node and element
  // lines, then SCHISM's boundary part.
  const auto gr3_grid = [](const std::string& text, std::vector<madd::Point>& xy,
                           std::vector<std::array<std::uint32_t, 3>>& elements) {
    std::istringstream in(text);
    std::string title;
    std::getline(in, title);
    std::size_t ne = 0, np = 0;
    in >> ne >> np;
    in.ignore(1 << 20, '\n');
    xy.resize(np);
    for (madd::Point& p : xy) {
      double id = 0, depth = 0;
      in >> id >> p.x >> p.y >> depth;
    }
    elements.resize(ne);
    for (auto& e : elements) {
      std::size_t id = 0, kind = 0, a = 0, b = 0, c = 0;
      in >> id >> kind >> a >> b >> c;
      e = {static_cast<std::uint32_t>(a - 1), static_cast<std::uint32_t>(b - 1), static_cast<std::uint32_t>(c - 1)};
    }
    return static_cast<bool>(in);
  };
  std::vector<madd::Point> ll_points, gr3_points;
  std::vector<std::array<std::uint32_t, 3>> ll_elements, gr3_elements;
  REQUIRE(gr3_grid(slurp(box.path("ll.ll")), ll_points, ll_elements));
  REQUIRE(gr3_grid(slurp(box.path("ll.gr3")), gr3_points, gr3_elements));
  CHECK(ll_points == points);
  CHECK(ll_elements == grid.elements);
  CHECK(gr3_elements == grid.elements);
  CHECK(gr3_points.size() == points.size());
  CHECK(gr3_points != points);  // metres
  std::istringstream ele(slurp(box.path("ll.ele")));
  std::size_t triangles = 0;
  ele >> triangles >> dimension >> attributes;
  REQUIRE(grid.elements.size() == triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    std::size_t id = 0, a = 0, b = 0, c = 0;
    double subdomain = 0;
    ele >> id >> a >> b >> c >> subdomain;
    REQUIRE(grid.elements[t] == std::array<std::uint32_t, 3>{static_cast<std::uint32_t>(a - 1),
                                                             static_cast<std::uint32_t>(b - 1),
                                                             static_cast<std::uint32_t>(c - 1)});
  }
  // The .2dm: one ND card per point, in lon/lat with --lonlat.
  const std::string sms = slurp(box.path("ll.2dm"));
  std::size_t nd = 0;
  for (std::size_t at = sms.find("\nND "); at != std::string::npos; at = sms.find("\nND ", at + 1)) ++nd;
  CHECK(nd == points.size());
  CHECK(!grid.open_boundaries.empty());
  CHECK(!grid.land_boundaries.empty());
}

TEST_CASE("a malformed GeoJSON is one located line and exit 3, nothing written; a box on a .poly is a usage error") {
  const CliSandbox box("madd-coast-cli");
  std::ofstream(box.path("bad.geojson"))
      << R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 91], [0, 0]]]})";
  const CliRun run = box.run("mesh bad.geojson -n 2 -o m --fort14 m.14");
  CHECK(run.status == 3);
  CHECK_MESSAGE(contains(run.output, "bad.geojson: ring 0, vertex 2: latitude 91 is outside [-90, 90]"), run.output);
  CHECK_FALSE(std::filesystem::exists(box.path("m.node")));
  CHECK_FALSE(std::filesystem::exists(box.path("m.14")));
  const CliRun poly = box.run("mesh " + std::string(MADD_DATA_DIR) + "/key.poly --clip 0,0,1,1 -n 2 -o k");
  CHECK(poly.status == 2);
  CHECK_MESSAGE(contains(poly.output, "--clip applies to GeoJSON and shapefile inputs"), poly.output);
  const CliRun empty = box.run("check " + coast_dir + "bay.geojson --clip 10,10,11,11");
  CHECK(empty.status == 3);
  CHECK_MESSAGE(contains(empty.output, "no water inside the clip box"), empty.output);
}

TEST_CASE("madd mesh --lonlat writes PREFIX.node in longitude/latitude, else in the projection's metres") {
  const CliSandbox box("madd-coast-cli");
  const madd::Projection projection = madd::read_coast(coast_dir + "lagoon.geojson").projection;
  REQUIRE(projection.geographic);
  for (const bool lonlat : {false, true}) {
    CAPTURE(lonlat);
    REQUIRE(
        box.run("mesh " + coast_dir + "lagoon.geojson -n 2 -a 5e7 -o l --quiet" + (lonlat ? " --lonlat" : "")).status ==
        0);
    std::istringstream node(slurp(box.path("l.node")));
    std::size_t n = 0, dim = 0, attributes = 0, markers = 0;
    node >> n >> dim >> attributes >> markers;
    REQUIRE(n > 0);
    double widest = 0;
    for (std::size_t k = 0; k < n; ++k) {
      double id = 0, x = 0, y = 0;
      int marker = 0;
      node >> id >> x >> y >> marker;
      // The lagoon lies in [-70.5, -70] x [43, 43.5]; in metres, once taken back.
      const madd::Point p = lonlat ? madd::Point{x, y} : projection.to_lonlat({x, y});
      REQUIRE(p.x >= -70.5 - 1e-9);
      REQUIRE(p.x <= -70.0 + 1e-9);
      REQUIRE(p.y >= 43.0 - 1e-9);
      REQUIRE(p.y <= 43.5 + 1e-9);
      widest = std::max(widest, std::abs(x));
    }
    CHECK((widest > 1000) == !lonlat);  // metres from the centre (lon -70), or degrees
  }
}

TEST_CASE("madd check FILE.14 refuses a fort.14 whose island is not closed, naming the problem") {
  const CliSandbox box("madd-coast-cli");
  REQUIRE(box.run("mesh " + coast_dir + "lagoon.geojson -n 2 -a 2e6 -o l --fort14 l.14 --quiet").status == 0);
  std::string text = slurp(box.path("l.14"));
  // Drop the repeated closing node of the last island: its list no longer closes.
  const std::size_t last = text.rfind("21 ! NVELL");
  REQUIRE(last != std::string::npos);
  const std::size_t end = text.find_last_not_of('\n');
  const std::size_t cut = text.rfind('\n', end);
  const std::size_t count_at = text.rfind('\n', last) + 1;
  const std::size_t count = std::stoul(text.substr(count_at));
  text = text.substr(0, count_at) + std::to_string(count - 1) +
         text.substr(text.find(' ', count_at), cut - text.find(' ', count_at)) + "\n";
  // NVEL counts one node less too.
  const std::size_t nvel = text.find("! NVEL");
  const std::size_t nvel_at = text.rfind('\n', nvel) + 1;
  text = text.substr(0, nvel_at) + std::to_string(std::stoul(text.substr(nvel_at)) - 1) +
         text.substr(text.find(' ', nvel_at));
  std::ofstream(box.path("open.14")) << text;
  const CliRun run = box.run("check open.14");
  CHECK(run.status == 3);
  CHECK_MESSAGE(contains(run.output, "not a valid fort.14"), run.output);
  CHECK_MESSAGE(contains(run.output, "closed"), run.output);
}

}  // TEST_SUITE

#endif
