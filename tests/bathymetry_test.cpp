// Tests of bathymetry (include/madd/bathymetry.hpp): the Esri ASCII grid and
// x y z readers, the depth between the samples and its gradient, and the two
// depth rules of a coastal mesh's edge length.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "madd/bathymetry.hpp"
#include "madd/error.hpp"

namespace fs = std::filesystem;

namespace {

std::string parse_error_of(std::string_view text, bool grid) {
  try {
    if (grid) {
      madd::parse_esri_ascii_grid(text, "t.asc");
    } else {
      madd::parse_xyz(text, "t.xyz");
    }
  } catch (const madd::ParseError& e) {
    return e.what();
  }
  FAIL("expected a ParseError for: " << text);
  return {};
}

std::string invalid_error_of(const madd::Bathymetry& b) {
  try {
    const madd::DepthField field(b);
  } catch (const madd::InvalidInputError& e) {
    CHECK(e.problem() == madd::InputProblem::other);
    return e.what();
  }
  FAIL("expected an InvalidInputError");
  return {};
}

madd::DepthField field_of(madd::DepthGrid grid) { return madd::DepthField(madd::Bathymetry{std::move(grid)}); }

// A temporary file removed at the end of the scope.
struct TempFile {
  fs::path path;
  TempFile(const std::string& name, const std::string& text)
      : path(fs::temp_directory_path() / ("madd_bathymetry_" + std::to_string(::getpid()) + "_" + name)) {
    std::ofstream(path, std::ios::binary) << text;
  }
  ~TempFile() { fs::remove(path); }
};

const char* const small_grid = "ncols 3\nnrows 2\nxllcorner 10\nyllcorner 20\ncellsize 2\nNODATA_value -9999\n"
                               "1 2 3\n4 -9999 6\n";

// The synthetic bay of data/coast/generate_depth.py, for comparison with the file it wrote.
double bay_depth(double lon, double lat, bool& has_depth) {
  const double pi = std::numbers::pi;
  const double coast =
      43.80 + 0.030 * std::sin(2 * pi * (lon + 70) / 0.21) + 0.012 * std::sin(2 * pi * (lon + 70) / 0.053 + 1.0);
  has_depth = true;
  if (lat >= coast) {
    has_depth = lat - coast <= 0.02;
    return -2.0;
  }
  const auto bump = [&](double x0, double y0, double r) {
    return std::exp(-((lon - x0) * (lon - x0) + (lat - y0) * (lat - y0)) / (2 * r * r));
  };
  const double ax = -70.15, ay = 43.35, ux = -69.35 - ax, uy = 43.50 - ay;
  const double t = ((lon - ax) * ux + (lat - ay) * uy) / (ux * ux + uy * uy);
  const double d = std::abs((lon - ax) * uy - (lat - ay) * ux) / std::hypot(ux, uy);
  const double trench = t < 0 || t > 1 ? 0.0 : 20.0 * std::sin(pi * t) * std::exp(-(d / 0.02) * (d / 0.02));
  return 2 + 60 * (1 - std::exp(-(coast - lat) / 0.08)) - 25 * bump(-69.85, 43.55, 0.04) -
         12 * bump(-69.55, 43.65, 0.025) + trench;
}

}  // namespace

TEST_SUITE("bathymetry") {

TEST_CASE("an Esri grid: sizes, origin at the centre of the south-west cell, rows from the south") {
  const madd::DepthGrid g = madd::parse_esri_ascii_grid(small_grid, "t.asc");
  CHECK(g.cols == 3);
  CHECK(g.rows == 2);
  CHECK(g.x0 == 11.0);  // xllcorner + cellsize / 2
  CHECK(g.y0 == 21.0);
  CHECK(g.dx == 2.0);
  CHECK(g.dy == 2.0);
  CHECK(g.has_nodata);
  CHECK(g.nodata == -9999.0);
  CHECK(g.values == std::vector<double>{4, -9999, 6, 1, 2, 3});  // the file's last row is the south row
  CHECK(g.has_value(0));
  CHECK(!g.has_value(1));
  // The cell centres read back their values exactly.
  const madd::DepthField field = field_of(g);
  CHECK(field.depth_at({11, 21}) == 4.0);
  CHECK(field.depth_at({15, 21}) == 6.0);
  CHECK(field.depth_at({11, 23}) == 1.0);
  CHECK(field.depth_at({13, 23}) == 2.0);
}

TEST_CASE("xllcenter and xllcorner: the same grid half a cell apart") {
  const madd::DepthGrid corner = madd::parse_esri_ascii_grid(small_grid, "t.asc");
  const madd::DepthGrid centre = madd::parse_esri_ascii_grid(
      "ncols 3\nnrows 2\nxllcenter 10\nyllcenter 20\ncellsize 2\nNODATA_value -9999\n1 2 3\n4 -9999 6\n", "t.asc");
  CHECK(centre.x0 == 10.0);
  CHECK(centre.y0 == 20.0);
  CHECK(centre.values == corner.values);
  const madd::DepthField a = field_of(corner), b = field_of(centre);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(9, 17), y(19, 25);
  for (int i = 0; i < 200; ++i) {
    const madd::Point p{x(rng), y(rng)};
    CHECK(b.depth_at(p) == a.depth_at({p.x + 1.0, p.y + 1.0}));
  }
}

TEST_CASE("header keys in any case and order, dx and dy, the default NODATA value, rows over any lines") {
  const madd::DepthGrid g = madd::parse_esri_ascii_grid(
      "CELLSIZE 0.5\r\nYllCorner -1\r\nNRows 2\r\nxllcorner 3\r\nNCOLS 2\r\n  7\t8 9\r\n -9999 \r\n", "t.asc");
  CHECK(g.cols == 2);
  CHECK(g.x0 == 3.25);
  CHECK(g.y0 == -0.75);
  CHECK(g.nodata == -9999.0);  // Esri's default
  CHECK(g.values == std::vector<double>{9, -9999, 7, 8});
  CHECK(!g.has_value(1));
  const madd::DepthGrid d =
      madd::parse_esri_ascii_grid("ncols 2 nrows 1 xllcenter 0 yllcenter 0 dx 4 dy 0.25 nodata_value nan 1 nan", "t");
  CHECK(d.dx == 4.0);
  CHECK(d.dy == 0.25);
  CHECK(std::isnan(d.nodata));
  CHECK(d.has_value(0));
  CHECK(!d.has_value(1));
  CHECK(field_of(d).depth_at({3, 0}) == 1.0);  // the one cell with a depth, nearest
}

TEST_CASE("bilinear is exact on a plane, inside and (clamped) outside the grid; the gradient is the plane's") {
  const double a = 3.0, b = 0.5, c = -0.25;
  madd::DepthGrid g;
  g.cols = 7, g.rows = 5, g.x0 = -1.5, g.y0 = 2.0, g.dx = 1.3, g.dy = 0.7;
  for (std::size_t r = 0; r < g.rows; ++r)
    for (std::size_t k = 0; k < g.cols; ++k)
      g.values.push_back(a + b * (g.x0 + static_cast<double>(k) * g.dx) + c * (g.y0 + static_cast<double>(r) * g.dy));
  const madd::DepthField field = field_of(g);
  const double x1 = g.x0 + 6 * g.dx, y1 = g.y0 + 4 * g.dy;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> x(g.x0, x1), y(g.y0, y1);
  for (int i = 0; i < 2000; ++i) {
    const madd::Point p{x(rng), y(rng)};
    CHECK(std::abs(field.depth_at(p) - (a + b * p.x + c * p.y)) <= 1e-12);
    const madd::Point grad = field.gradient_at(p);
    CHECK(std::abs(grad.x - b) <= 1e-12);
    CHECK(std::abs(grad.y - c) <= 1e-12);
  }
  // Outside, the value at the nearest point of the rectangle of the centres;
  // no slope along a clamped direction.
  CHECK(std::abs(field.depth_at({x1 + 10, y1 + 3}) - (a + b * x1 + c * y1)) <= 1e-12);
  const madd::Point west{g.x0 - 2, 2.9};
  CHECK(std::abs(field.depth_at(west) - (a + b * g.x0 + c * 2.9)) <= 1e-12);
  CHECK(field.gradient_at(west).x == 0.0);
  CHECK(std::abs(field.gradient_at(west).y - c) <= 1e-12);
}

TEST_CASE("linear over the scatter's Delaunay triangulation is exact on a plane; the nearest point outside") {
  const double a = -2.0, b = 0.75, c = 1.5;
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 10.0);
  std::vector<madd::ValuedPoint> points;
  for (const madd::Point corner : {madd::Point{0, 0}, madd::Point{10, 0}, madd::Point{10, 10}, madd::Point{0, 10}})
    points.push_back({corner, a + b * corner.x + c * corner.y});
  for (int i = 0; i < 300; ++i) {
    const madd::Point p{u(rng), u(rng)};
    points.push_back({p, a + b * p.x + c * p.y});
  }
  const madd::DepthField field(madd::Bathymetry{points});
  for (int i = 0; i < 2000; ++i) {
    const madd::Point p{u(rng), u(rng)};  // the hull is the square
    CHECK(std::abs(field.depth_at(p) - (a + b * p.x + c * p.y)) <= 1e-12);
    const madd::Point grad = field.gradient_at(p);
    CHECK(std::abs(grad.x - b) <= 1e-10);
    CHECK(std::abs(grad.y - c) <= 1e-10);
  }
  for (const madd::ValuedPoint& s : points) CHECK(std::abs(field.depth_at(s.at) - s.value) <= 1e-12);
  // Outside the hull: the nearest point's value (brute force), no slope.
  std::uniform_real_distribution<double> far(-30.0, 40.0);
  for (int i = 0; i < 500; ++i) {
    const madd::Point p{far(rng), far(rng)};
    if (p.x >= 0 && p.x <= 10 && p.y >= 0 && p.y <= 10) continue;
    std::size_t best = 0;
    for (std::size_t k = 1; k < points.size(); ++k)
      if (madd::distance(p, points[k].at) < madd::distance(p, points[best].at)) best = k;
    CHECK(field.depth_at(p) == points[best].value);
    CHECK(field.gradient_at(p) == madd::Point{0, 0});
  }
}

TEST_CASE("NODATA corners are left out and the weights of the others renormalised") {
  // Centres (0,0) 1, (1,0) 3, (0,1) NODATA, (1,1) 7.
  const madd::DepthField field =
      field_of(madd::parse_esri_ascii_grid("ncols 2 nrows 2 xllcenter 0 yllcenter 0 cellsize 1\n-9999 7\n1 3\n", "t"));
  CHECK(field.depth_at({0.5, 0.5}) == doctest::Approx((1.0 + 3.0 + 7.0) / 3.0).epsilon(1e-15));
  // At (0.25, 0.5): weights 0.375 (1), 0.125 (3), 0.125 (7) of the kept corners.
  CHECK(field.depth_at({0.25, 0.5}) == doctest::Approx((0.375 * 1 + 0.125 * 3 + 0.125 * 7) / 0.625).epsilon(1e-15));
  // Along the south edge the NODATA corner has weight 0: the plain linear.
  CHECK(field.depth_at({0.5, 0.0}) == 2.0);
  // Along y at x = 0.5 the kept corners give f(t) = N/D with N = 0.5(1 - t) + 1.5(1 - t) + 3.5t = 2 + 1.5t and
  // D = 0.5(1 - t) + 0.5(1 - t) + 0.5t = 1 - 0.5t: f'(0.5) = (1.5 * 0.75 + 0.5 * 2.75) / 0.75^2 = 40/9.
  CHECK(field.gradient_at({0.5, 0.5}).y == doctest::Approx(40.0 / 9.0).epsilon(1e-14));
  // Along x at y = 0.5: N = 0.5(1 - s) + 1.5s + 3.5s = 0.5 + 4.5s, D = 0.5(1 - s) + s = 0.5 + 0.5s:
  // f'(0.5) = (4.5 * 0.75 - 0.5 * 2.75) / 0.75^2 = 32/9.
  CHECK(field.gradient_at({0.5, 0.5}).x == doctest::Approx(32.0 / 9.0).epsilon(1e-14));
  // The NODATA centre itself: no kept corner has weight, the nearest cell with
  // a depth decides (1 and 7 are both 1 away: the one of the lower column).
  CHECK(field.depth_at({0.0, 1.0}) == 1.0);
  CHECK(field.gradient_at({0.0, 1.0}) == madd::Point{0, 0});
}

TEST_CASE("where no corner has a depth: the nearest cell with one, as brute force finds it") {
  const std::pair<std::size_t, std::size_t> shapes[] = {{23, 17}, {1, 9}, {9, 1}, {2, 2}, {40, 3}};
  for (const auto& shape : shapes)
    for (const double dy : {1.0, 2.5, 0.3}) {
      const std::size_t cols = shape.first, rows = shape.second;
      CAPTURE(cols);
      CAPTURE(rows);
      CAPTURE(dy);
      std::mt19937_64 rng(cols * 1000 + rows + static_cast<std::uint64_t>(dy * 10));
      madd::DepthGrid g;
      g.cols = cols, g.rows = rows, g.x0 = 0, g.y0 = 0, g.dx = 1.0, g.dy = dy, g.has_nodata = true, g.nodata = -1;
      std::bernoulli_distribution valid(0.06);
      for (std::size_t k = 0; k < cols * rows; ++k) g.values.push_back(valid(rng) ? static_cast<double>(k) : -1.0);
      g.values[cols * rows / 2] = static_cast<double>(cols * rows / 2);  // at least one
      const madd::DepthField field = field_of(g);
      for (std::size_t r = 0; r < rows; ++r)
        for (std::size_t c = 0; c < cols; ++c) {
          if (g.has_value(r * cols + c)) continue;
          // At a NODATA centre the only corner with weight is the cell itself;
          // the values are the cells' indices, so the depth names the cell.
          const double got = field.depth_at({static_cast<double>(c), static_cast<double>(r) * dy});
          const auto at = static_cast<std::size_t>(got);
          REQUIRE(at < g.values.size());
          REQUIRE(g.has_value(at));
          const auto d2 = [&](std::size_t m) {
            const double ex = static_cast<double>(m % cols) - static_cast<double>(c);
            const double ey = (static_cast<double>(m / cols) - static_cast<double>(r)) * dy;
            return ex * ex + ey * ey;
          };
          double best = std::numeric_limits<double>::infinity();
          for (std::size_t m = 0; m < g.values.size(); ++m)
            if (g.has_value(m)) best = std::min(best, d2(m));
          CHECK(d2(at) == doctest::Approx(best).epsilon(1e-12));
        }
      // Far outside: the rectangle's nearest point, and the cell nearest to it.
      CHECK(std::isfinite(field.depth_at({-100, 1e6})));
    }
}

TEST_CASE("read_bathymetry: by extension; positive_up turns elevations round, NODATA too") {
  const TempFile grid("g.ASC", small_grid);
  const madd::Bathymetry down = madd::read_bathymetry(grid.path.string());
  const madd::Bathymetry up = madd::read_bathymetry(grid.path.string(), true);
  const auto& gd = std::get<madd::DepthGrid>(down.data);
  const auto& gu = std::get<madd::DepthGrid>(up.data);
  CHECK(gu.values == std::vector<double>{-4, 9999, -6, -1, -2, -3});
  CHECK(gu.nodata == 9999.0);
  for (std::size_t k = 0; k < gd.values.size(); ++k) CHECK(gu.has_value(k) == gd.has_value(k));
  CHECK(madd::DepthField(up).depth_at({12, 22}) == -madd::DepthField(down).depth_at({12, 22}));

  const TempFile scatter("s.csv", "x,y,z\n0,0,1\n1,0,-2\n0,1,3.5\n");
  const madd::Bathymetry scattered = madd::read_bathymetry(scatter.path.string(), true);
  const auto& pu = std::get<std::vector<madd::ValuedPoint>>(scattered.data);
  CHECK(pu == std::vector<madd::ValuedPoint>{{{0, 0}, -1}, {{1, 0}, 2}, {{0, 1}, -3.5}});

  const std::string missing = (fs::temp_directory_path() / "madd_no_such_bathymetry.asc").string();
  try {
    madd::read_bathymetry(missing);
    FAIL("expected an InputFileError");
  } catch (const madd::InputFileError& e) {
    CHECK(std::string(e.what()) == missing + ": cannot read file");
    CHECK(e.kind() == madd::ErrorKind::bad_input);
  }
  const std::string directory = fs::temp_directory_path().string();
  try {
    madd::read_bathymetry(directory);
    FAIL("expected an InputFileError");
  } catch (const madd::InputFileError& e) {
    CHECK(std::string(e.what()) == directory + ": cannot read file (it is a directory)");
  }
}

TEST_CASE("the x y z reader: separators, comments, a header line") {
  const auto points =
      madd::parse_xyz("# survey\n\nlon, lat , depth\n 1 2 3 # first\n4,5,6\r\n7 ,8\t9\n1e1 -2.5 +4\n", "t");
  CHECK(points == std::vector<madd::ValuedPoint>{{{1, 2}, 3}, {{4, 5}, 6}, {{7, 8}, 9}, {{10, -2.5}, 4}});
  // A spreadsheet's UTF-8 byte order mark before the text (columns count from after it).
  CHECK(madd::parse_xyz("\xEF\xBB\xBFx,y,z\n0,0,1\n1,0,2\n0,1,3\n", "t").size() == 3);
  CHECK(madd::parse_esri_ascii_grid("\xEF\xBB\xBFncols 1 nrows 1 xllcorner 0 yllcorner 0 cellsize 1 5", "t").values ==
        std::vector<double>{5});
  CHECK(parse_error_of("\xEF\xBB\xBF"
                       "0 0 x\n",
                       false) == "t.xyz:1:5: expected a number for z, got 'x'");
}

TEST_CASE("every grid error, with its place and message") {
  const std::string header = "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
  const std::string keys = "(expected ncols, nrows, xllcorner or xllcenter, yllcorner or yllcenter, cellsize or dx "
                           "and dy, NODATA_value)";
  const std::pair<std::string, std::string> cases[] = {
      {"", "t.asc:1:1: unexpected end of file: expected the header key ncols"},
      {"foo 3\n", "t.asc:1:1: unknown header key 'foo' " + keys},
      {"ncols 3\nnCols 4\n", "t.asc:2:1: header key ncols is repeated (first on line 1)"},
      {"ncols", "t.asc:1:6: unexpected end of file: expected the value of ncols"},
      {"ncols x\n", "t.asc:1:7: expected a whole number >= 1 for ncols, got 'x'"},
      {"ncols 2.5\n", "t.asc:1:7: expected a whole number >= 1 for ncols, got '2.5'"},
      {"ncols -3\n", "t.asc:1:7: expected a whole number >= 1 for ncols, got '-3'"},
      {"nrows 0\n", "t.asc:1:7: nrows must be at least 1"},
      {"nrows 2147483648\n", "t.asc:1:7: nrows is too large: '2147483648'"},
      {"cellsize 0\n", "t.asc:1:10: cellsize must be > 0, got '0'"},
      {"cellsize -1\n", "t.asc:1:10: cellsize must be > 0, got '-1'"},
      {"dy nan\n", "t.asc:1:4: dy is not finite: 'nan'"},
      {"xllcorner inf\n", "t.asc:1:11: xllcorner is not finite: 'inf'"},
      {"xllcorner 1e999\n", "t.asc:1:11: xllcorner is out of the range of a double: '1e999'"},
      {"yllcenter 1,5\n", "t.asc:1:11: expected a number for yllcenter, got '1,5'"},
      {"NODATA_value none\n", "t.asc:1:14: expected a number for NODATA_value, got 'none'"},
      {"ncols 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n", "t.asc:5:1: expected the header key nrows"},
      {"ncols 3\nnrows 1\nxllcorner 0\nyllcorner 0\n", "t.asc:5:1: unexpected end of file: expected the header key "
                                                       "cellsize (or dx and dy)"},
      {"ncols 3\nnrows 1\nyllcorner 0\ncellsize 1\n1 2 3\n",
       "t.asc:5:1: expected the header key xllcorner or xllcenter"},
      {header + "xllcenter 0\n1 2 3 4 5 6\n",
       "t.asc:6:11: xllcenter and xllcorner both given: the origin is one or the other"},
      {"ncols 3\nnrows 2\nxllcorner 0\nyllcenter 0\ncellsize 1\n1 2 3 4 5 6\n",
       "t.asc:4:11: yllcenter with xllcorner: the origin must be the lower left corner in both x and y, or the "
       "centre in both"},
      {header + "dx 1\n1 2 3 4 5 6\n", "t.asc:6:4: dx and cellsize both given: the spacing is one or the other"},
      {"ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ndy 1\n1 2 3 4 5 6\n",
       "t.asc:5:4: dy needs dx beside it (or cellsize alone)"},
      {"ncols 3\nnrows 2\nxllcorner 1.7e308\nyllcorner 0\ncellsize 1e307\n1 2 3 4 5 6\n",
       "t.asc:3:11: the grid's x extent (ncols times the cell width from the origin) is not finite"},
      {"ncols 1\nnrows 2\nxllcorner 0\nyllcorner 1e308\ncellsize 1e308\n1 2\n",
       "t.asc:4:11: the grid's y extent (nrows times the cell height from the origin) is not finite"},
      {header, "t.asc:2:7: the header declares 3 x 2 = 6 values, but the remaining 0 bytes of the file cannot "
               "hold them"},
      {"ncols 100000\nnrows 100000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n",
       "t.asc:2:7: the header declares 100000 x 100000 = 10000000000 values, but the remaining 6 bytes of the file "
       "cannot hold them"},
      {header + "10 20 30\n40 50\n", "t.asc:8:1: unexpected end of file: expected value 6 (row 2 from the top, "
                                     "column 3) of 6 (line 7 holds 2 values, not ncols 3)"},
      {header + "1 2 3\n4 5 6 7\n",
       "t.asc:7:7: unexpected text after the last of the 6 values: '7' (line 7 holds 4 values, not ncols 3)"},
      {header + "1 2 x\n4 5 6\n", "t.asc:6:5: expected a number for value 3 (row 1 from the top, column 3), got 'x'"},
      {header + "1 2 3\n4 1.5abc 6\n",
       "t.asc:7:3: expected a number for value 5 (row 2 from the top, column 2), got '1.5abc'"},
      {header + "1 2 3\n4 5 # 6\n", "t.asc:7:5: expected a number for value 6 (row 2 from the top, column 3), got '#'"},
      {header + "1 2 3\n4 5 1e400\n",
       "t.asc:7:5: value 6 (row 2 from the top, column 3) is out of the range of a double: '1e400'"},
      {header + "1 -inf 3\n4 5 6\n",
       "t.asc:6:3: value 2 (row 1 from the top, column 2) is not finite (and not the NODATA value): '-inf'"},
      {header + "1 2 3\n4 5 nan\n",
       "t.asc:7:5: value 6 (row 2 from the top, column 3) is not finite (and not the NODATA value): 'nan'"},
      {header + "NODATA_value -1\n-1 -1 -1\n-1 -1 -1\n",
       "t.asc:7:1: every value is the NODATA value -1: the grid holds no depth"},
      {header + "-9999 -9999 -9999 -9999 -9999 -9999",
       "t.asc:6:1: every value is the NODATA value -9999: the grid holds no depth"},
  };
  for (const auto& c : cases) {
    const std::string& text = c.first;
    const std::string& message = c.second;
    CAPTURE(text);
    CHECK(parse_error_of(text, true) == message);
  }
}

TEST_CASE("every x y z error, with its place and message") {
  const std::pair<std::string, std::string> cases[] = {
      {"", "t.xyz:1:1: a scatter needs at least 3 points, the file holds 0"},
      {"# nothing\n\n", "t.xyz:2:1: a scatter needs at least 3 points, the file holds 0"},
      {"0 0 1\n1 0 1\n", "t.xyz:2:1: a scatter needs at least 3 points, the file holds 2"},
      {"x y z\n", "t.xyz:1:1: a scatter needs at least 3 points, the file holds 0"},
      {"0 0\n", "t.xyz:1:4: missing z (a line holds x y z)"},
      {"0 0 1\n5 # only x\n", "t.xyz:2:3: missing y (a line holds x y z)"},
      {"0 0 1 2\n", "t.xyz:1:7: unexpected extra field after z (a line holds x y z)"},
      {"0,,1\n", "t.xyz:1:3: empty field before ','"},
      {",0,1,2\n", "t.xyz:1:1: empty field before ','"},
      {"0,1,2,\n", "t.xyz:1:7: empty field after ','"},
      {"0 0 1\nx y z\n", "t.xyz:2:1: expected a number for x, got 'x'"},
      {"0 0 x\n", "t.xyz:1:5: expected a number for z, got 'x'"},
      {"x 0 1\n", "t.xyz:1:1: expected a number for x, got 'x'"},
      {"0 0;1 2\n", "t.xyz:1:3: expected a number for y, got '0;1'"},
      {"0 0 nan\n", "t.xyz:1:5: z is not finite: 'nan'"},
      {"0 -inf 1\n", "t.xyz:1:3: y is not finite: '-inf'"},
      {"1e999 0 1\n", "t.xyz:1:1: x is out of the range of a double: '1e999'"},
      {"1e71 0 1\n", "t.xyz:1:1: x 1e71 is outside the supported range: a coordinate must be 0 or of magnitude within "
                     "[1e-40, 1e70]"},
      {"0 -1e-41 1\n", "t.xyz:1:3: y -1e-41 is outside the supported range: a coordinate must be 0 or of magnitude "
                       "within [1e-40, 1e70]"},
      {"0 0 1\n1 0 1\n2 2 2\n1 0 3\n0 0 2\n", "t.xyz:4:1: the point (1, 0) is given again (first on line 2)"},
      {"0 0 1\n1 1 1\n\n2 2 1\n-3 -3 4\n",
       "t.xyz:1:1: the 4 points all lie on one line: a scatter needs 3 points not on one line"},
  };
  for (const auto& c : cases) {
    const std::string& text = c.first;
    const std::string& message = c.second;
    CAPTURE(text);
    CHECK(parse_error_of(text, false) == message);
  }
}

TEST_CASE("a DepthField refuses a bathymetry no reader returns") {
  madd::DepthGrid g;
  g.cols = 2, g.rows = 1, g.dx = 1, g.dy = 1, g.values = {1, 2};
  const auto with = [&](auto change) {
    madd::DepthGrid h = g;
    change(h);
    return invalid_error_of(madd::Bathymetry{h});
  };
  CHECK(with([](madd::DepthGrid& h) { h.cols = 0; }) == "bathymetry: a grid needs at least one column and one row");
  CHECK(with([](madd::DepthGrid& h) { h.values.pop_back(); }) == "bathymetry: the grid has 1 values for 2 x 1 cells");
  CHECK(with([](madd::DepthGrid& h) { h.dy = 0; }) == "bathymetry: the cell width and height must be finite and > 0");
  CHECK(with([](madd::DepthGrid& h) { h.x0 = 1.7e308, h.dx = 1e308; }) ==
        "bathymetry: the grid's origin and extent must be finite");
  CHECK(with([](madd::DepthGrid& h) { h.values[1] = std::numeric_limits<double>::infinity(); }) ==
        "bathymetry: the grid's value 1 is not finite");
  CHECK(with([](madd::DepthGrid& h) {
          h.has_nodata = true, h.nodata = 1, h.values = {1, 1};
        }) == "bathymetry: the grid holds no depth (every value is the NODATA value)");
  CHECK(with([](madd::DepthGrid& h) { h.cols = std::size_t{1} << 31, h.rows = 2; }) ==
        "bathymetry: the grid has more than 2^32 - 2 cells");
  using P = std::vector<madd::ValuedPoint>;
  CHECK(invalid_error_of({P{{{0, 0}, 1}, {{1, 0}, 1}}}) == "bathymetry: a scatter needs at least 3 points, it has 2");
  CHECK(invalid_error_of({P{{{0, 0}, 1}, {{1, 1}, 1}, {{2, 2}, 1}}}) ==
        "bathymetry: the scatter's points all lie on one line");
  CHECK(invalid_error_of({P{{{0, 0}, 1}, {{1, 0}, 1}, {{0, 1e80}, 1}}}) ==
        "bathymetry: scatter point 2 has a coordinate that is not 0 or of magnitude within [1e-40, 1e70], or a value "
        "that is not finite");
  CHECK(invalid_error_of({P{{{0, 0}, 1}, {{1, 0}, std::nan("")}, {{0, 1}, 1}}}).find("scatter point 1 ") !=
        std::string::npos);
  try {
    const madd::DepthField field(madd::Bathymetry{P{{{0, 0}, 1}, {{1, 0}, 1}, {{0, 1}, 1}, {{1, 0}, 2}}});
    FAIL("expected the duplicate to be refused");
  } catch (const madd::InvalidInputError& e) {
    CHECK(e.problem() == madd::InputProblem::duplicate_vertex);
  }
}

TEST_CASE("an empty field and non-finite points give NaN") {
  const madd::DepthField empty;
  CHECK(empty.empty());
  CHECK(std::isnan(empty.depth_at({0, 0})));
  CHECK(std::isnan(empty.gradient_at({0, 0}).x));
  CHECK(std::get<std::vector<madd::ValuedPoint>>(empty.bathymetry().data).empty());
  const madd::DepthField grid = field_of(madd::parse_esri_ascii_grid(small_grid, "t"));
  const madd::DepthField scatter(madd::Bathymetry{madd::parse_xyz("0 0 1\n1 0 2\n0 1 3\n", "t")});
  for (const madd::DepthField* f : {&grid, &scatter}) {
    CHECK(std::isnan(f->depth_at({std::nan(""), 0})));
    CHECK(std::isnan(f->depth_at({0, std::numeric_limits<double>::infinity()})));
    CHECK(std::isnan(f->gradient_at({std::nan(""), 0}).y));
  }
  CHECK(grid == field_of(madd::parse_esri_ascii_grid(small_grid, "other")));
  CHECK(!(grid == scatter));
}

TEST_CASE("truncated text at every byte gives only madd::Error") {
  const std::string grid = "ncols 3\r\nnrows 2\nxllcenter -1.5\nyllcenter 2e1\ndx 0.5\ndy 2\nNODATA_value -9999\n"
                           "1.25 -9999 3\n4 5e-1 +6\n";
  const std::string xyz = "# c\nlon,lat,z\n0 0 1\n1.5, 0 ,2\n0\t1 3e0\n2 2 -4\n";
  for (const std::string* text : {&grid, &xyz})
    for (std::size_t n = 0; n <= text->size(); ++n) {
      const std::string_view cut(text->data(), n);
      CAPTURE(cut);
      try {
        if (text == &grid) {
          (void)madd::DepthField(madd::Bathymetry{madd::parse_esri_ascii_grid(cut, "t")});
        } else {
          (void)madd::DepthField(madd::Bathymetry{madd::parse_xyz(cut, "t")});
        }
      } catch (const madd::Error&) {
      } catch (...) {
        FAIL("an exception other than madd::Error");
      }
    }
  CHECK(madd::parse_esri_ascii_grid(grid, "t").values == std::vector<double>{4, 0.5, 6, 1.25, -9999, 3});
  CHECK(madd::parse_xyz(xyz, "t").size() == 4);
}

TEST_CASE("the two depth rules against hand values") {
  const double inf = std::numeric_limits<double>::infinity();
  // T sqrt(g d) / K = 44714.16 s * sqrt(9.81 * 10 m) / 50 = 44714.16 * 9.9045444 / 50 = 8857.468 m.
  CHECK(madd::wavelength_edge(10, 50) == doctest::Approx(8857.4677).epsilon(1e-8));
  // 1 m of water, 1 cell: the whole wavelength, 44714.16 * 3.1320920 = 140048.86 m.
  CHECK(madd::wavelength_edge(1, 1) == doctest::Approx(140048.8607).epsilon(1e-9));
  CHECK(madd::wavelength_edge(40, 50) == doctest::Approx(2 * madd::wavelength_edge(10, 50)).epsilon(1e-15));
  CHECK(madd::wavelength_edge(0, 50) == inf);
  CHECK(madd::wavelength_edge(-2, 50) == inf);
  CHECK(madd::wavelength_edge(std::nan(""), 50) == inf);
  CHECK(madd::wavelength_edge(10, 0) == inf);
  // 2 pi d / (K |grad d|) = 2 pi 10 / (50 * 0.01) = 40 pi = 125.66371.
  CHECK(madd::slope_edge(10, 0.01, 50) == doctest::Approx(125.663706).epsilon(1e-8));
  CHECK(madd::slope_edge(10, 0, 50) == inf);
  CHECK(madd::slope_edge(0, 0.01, 50) == inf);
  CHECK(madd::slope_edge(-1, 0.01, 50) == inf);
  CHECK(madd::slope_edge(10, std::nan(""), 50) == inf);
  CHECK(madd::slope_edge(10, 0.01, -1) == inf);
}

TEST_CASE("depths_at gives the same values on 1 and 3 threads") {
  const madd::DepthField grid(madd::read_bathymetry(std::string(MADD_DATA_DIR) + "/coast/depth.asc"));
  const madd::DepthField scatter(madd::read_bathymetry(std::string(MADD_DATA_DIR) + "/coast/depth.xyz"));
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> lon(-70.3, -69.2), lat(43.2, 44.1);
  std::vector<madd::Point> points(100000);
  for (madd::Point& p : points) p = {lon(rng), lat(rng)};
  for (const madd::DepthField* f : {&grid, &scatter}) {
    const std::vector<double> one = madd::depths_at(*f, points, 1);
    const std::vector<double> three = madd::depths_at(*f, points, 3);
    REQUIRE(one.size() == points.size());
    CHECK(std::memcmp(one.data(), three.data(), one.size() * sizeof(double)) == 0);
    for (std::size_t k = 0; k < points.size(); k += 997) CHECK(one[k] == f->depth_at(points[k]));
    // Points far apart and not finite: each its own depth_at, NaN where not finite.
    const double big = std::numeric_limits<double>::max();
    const std::vector<madd::Point> odd = {{-big, 0}, {big, big}, {std::nan(""), 0}, {-70, 43.5}, {0, -big}};
    const std::vector<double> d = madd::depths_at(*f, odd, 2);
    for (std::size_t k = 0; k < odd.size(); ++k) CHECK((d[k] == f->depth_at(odd[k]) || (k == 2 && std::isnan(d[k]))));
  }
  CHECK(madd::depths_at(grid, {}, 3).empty());
  CHECK(std::isnan(madd::depths_at(madd::DepthField(), points, 1)[7]));
}

TEST_CASE("data/coast: the bay's grid and scatter hold generate_depth.py's function") {
  const madd::Bathymetry b = madd::read_bathymetry(std::string(MADD_DATA_DIR) + "/coast/depth.asc");
  const auto& g = std::get<madd::DepthGrid>(b.data);
  CHECK(g.cols == 180);
  CHECK(g.rows == 140);
  CHECK(g.x0 == doctest::Approx(-70.1975).epsilon(1e-15));
  CHECK(g.y0 == doctest::Approx(43.3025).epsilon(1e-15));
  std::size_t water = 0, land = 0, nodata = 0;
  for (std::size_t r = 0; r < g.rows; ++r)
    for (std::size_t c = 0; c < g.cols; ++c) {
      bool has = false;
      const double want =
          bay_depth(-70.2 + (static_cast<double>(c) + 0.5) * 0.005, 43.3 + (static_cast<double>(r) + 0.5) * 0.005, has);
      const std::size_t k = r * g.cols + c;
      REQUIRE(g.has_value(k) == has);
      if (!has) {
        ++nodata;
        continue;
      }
      CHECK(std::abs(g.values[k] - want) <= 0.0005 + 1e-9);  // written with 3 decimals
      ++(want > 0 ? water : land);
    }
  CHECK(water > 10000);
  CHECK(land > 100);
  CHECK(nodata > 1000);
  const madd::Bathymetry scatter = madd::read_bathymetry(std::string(MADD_DATA_DIR) + "/coast/depth.xyz");
  const auto& s = std::get<std::vector<madd::ValuedPoint>>(scatter.data);
  CHECK(s.size() == 300);
  for (const madd::ValuedPoint& p : s) {
    bool has = false;
    CHECK(std::abs(p.value - bay_depth(p.at.x, p.at.y, has)) <= 0.0005 + 1e-9);
    CHECK(has);
  }
}
}
