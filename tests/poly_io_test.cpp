// Tests of the .poly/.node reader and writer (include/madd/poly_io.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>

#include "madd/atomic_write.hpp"
#include "madd/error.hpp"
#include "madd/poly_io.hpp"
#include "madd/triangulation.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// InputProblem names as used in data/bad/*.expected: to_string with '_'.
std::string kind_name(madd::InputProblem problem) {
  std::string s = madd::to_string(problem);
  for (char& c : s)
    if (c == ' ' || c == '-') c = '_';
  return s;
}

std::vector<fs::path> files_with_extension(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ext) out.push_back(entry.path());
  std::sort(out.begin(), out.end());
  return out;
}

madd::ParseError parse_error_of(std::string_view text) {
  try {
    madd::parse_poly(text, "t.poly");
  } catch (const madd::ParseError& e) {
    return e;
  }
  FAIL("expected a ParseError for: " << text);
  return madd::ParseError("", 0, 0, "");
}

const char* const square = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n";

}  // namespace

TEST_SUITE("poly_io") {

TEST_CASE("every data/*.poly round-trips exactly through format_poly") {
  const auto files = files_with_extension(MADD_DATA_DIR, ".poly");
  REQUIRE(files.size() >= 6);
  for (const auto& path : files) {
    CAPTURE(path.string());
    const madd::PolyFile read = madd::read_poly_file(path.string());
    CHECK(!read.pslg.segments.empty());
    const std::string text = madd::format_poly(read.pslg, "round trip");
    const madd::PolyFile again = madd::parse_poly(text, "again.poly");
    CHECK(again.pslg == read.pslg);
    CHECK(madd::format_poly(again.pslg, "round trip") == text);
  }
}

// The error a check gives for a data/bad file, as "<kind> <line>" (kind =
// parse or an InputProblem name), or "ok".
template <class Check>
std::string verdict_of(const std::string& poly, Check&& check) {
  try {
    const madd::PolyFile file = madd::read_poly_file(poly);
    check(file);
  } catch (const madd::ParseError& e) {
    CHECK(e.path() == poly);
    CHECK(std::string(e.what()).find(poly + ":" + std::to_string(e.line()) + ":") == 0);
    return "parse " + std::to_string(e.line());
  } catch (const madd::InvalidInputError& e) {
    const std::string kind = kind_name(e.problem());
    CHECK(!e.ids().empty() == (kind != "empty_domain" || e.line() != 0));
    if (e.line() != 0) CHECK(std::string(e.what()).find(poly + ":" + std::to_string(e.line()) + ":1: ") == 0);
    return kind + " " + std::to_string(e.line());
  }
  return "ok";
}

TEST_CASE("every data/bad file fails with the expected kind and line, as a domain and as a PSLG") {
  const auto expected_files = files_with_extension(fs::path(MADD_DATA_DIR) / "bad", ".expected");
  REQUIRE(expected_files.size() >= 24);
  for (const auto& expected_path : expected_files) {
    std::istringstream expected(slurp(expected_path));
    std::string kind, pslg_word, pslg_verdict;
    std::size_t line = 0;
    expected >> kind >> line >> pslg_word;
    std::getline(expected >> std::ws, pslg_verdict);
    const std::string poly = fs::path(expected_path).replace_extension(".poly").string();
    CAPTURE(poly);
    CHECK(pslg_word == "pslg");
    CHECK(verdict_of(poly, [](const madd::PolyFile& f) { madd::validate(f.pslg, f.source); }) ==
          kind + " " + std::to_string(line));
    CHECK(verdict_of(poly, [](const madd::PolyFile& f) { madd::validate_pslg(f.pslg, f.source); }) == pslg_verdict);
    if (pslg_verdict != "ok") continue;
    // What triangulate takes, it triangulates, and the result verifies.
    const madd::PolyFile file = madd::read_poly_file(poly);
    const madd::Triangulation tri = madd::triangulate(file.pslg);
    const madd::Verification check = madd::verify_triangulation(tri, &file.pslg);
    CHECK_MESSAGE(check.ok(), (check.ok() ? "" : check.problems.front()));
  }
}

TEST_CASE("Triangle's lenient layout: comments, blank lines, CRLF, defaults, 0-based ids") {
  const std::string text = "# a comment\n\n  4 2 # dimension only\r\n0 0 0\r\n1 1 0 # trailing comment\n2 1 1\n3 0 1\n"
                           "\n4\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n";
  const madd::PolyFile f = madd::parse_poly(text, "x.poly");
  CHECK(f.pslg.first_index == 0);
  CHECK(f.pslg.points.size() == 4);
  CHECK(f.pslg.points[2] == madd::Point{1, 1});
  CHECK(f.pslg.segments[3] == madd::Segment{3, 0, 0});
  CHECK(!f.pslg.has_segment_markers);
  CHECK(f.source.point_lines == std::vector<std::uint32_t>{4, 5, 6, 7});
  CHECK(f.source.segment_lines.front() == 10);
  CHECK(f.pslg.regions.empty());
}

TEST_CASE("attributes, markers, holes and regions are read; a region without max area uses its attribute") {
  const std::string text = "3 2 2 1\n1 0 0 0.5 -1 7\n2 +1 0 nan inf 8\n3 0 1e0 1 2 9\n3 1\n1 1 2 4\n2 2 3 5\n"
                           "3 3 1 6\n1\n1 0.1 0.1\n2\n1 0.2 0.2 3 0.5\n2 0.3 0.3 4\n";
  const madd::PolyFile f = madd::parse_poly(text);
  CHECK(f.pslg.attributes_per_point == 2);
  CHECK(f.pslg.attribute(0, 1) == -1.0);
  CHECK(std::isnan(f.pslg.attribute(1, 0)));
  CHECK(std::isinf(f.pslg.attribute(1, 1)));
  CHECK(f.pslg.point_markers == std::vector<int>{7, 8, 9});
  CHECK(f.pslg.segments[2].marker == 6);
  CHECK(f.pslg.holes == std::vector<madd::Point>{{0.1, 0.1}});
  REQUIRE(f.pslg.regions.size() == 2);
  CHECK(f.pslg.regions[0].max_area == 0.5);
  CHECK(f.pslg.regions[1].attribute == 4.0);
  CHECK(f.pslg.regions[1].max_area == 4.0);
}

TEST_CASE("parse errors carry line and column") {
  auto e = parse_error_of("4 2 0 0\n1 0 0\n2 1 0\n3 1 1x\n4 0 1\n");
  CHECK(e.line() == 4);
  CHECK(e.column() == 5);
  e = parse_error_of("4 2 0 0\n1 0 0\n2 1 0\n3 1 1 5\n4 0 1\n");
  CHECK(e.line() == 4);
  CHECK(e.column() == 7);
  e = parse_error_of("4 3 0 0\n");
  CHECK(e.line() == 1);
  e = parse_error_of("2 2 0 0\n2 0 0\n3 1 0\n");
  CHECK(e.message().find("0 or 1") != std::string::npos);
  e = parse_error_of("1 2 0 0\n1 1e999 0\n");
  CHECK(e.line() == 2);
  e = parse_error_of("-4 2 0 0\n");
  CHECK(e.line() == 1);
  e = parse_error_of(std::string(square) + "1\n1 0.5 0.5 1 -1\nextra\n");
  CHECK(e.line() == 14);
  e = parse_error_of(std::string(square) + "1\n1 0.5 0.5\n");  // a region needs x, y and an attribute
  CHECK(e.line() == 13);
}

TEST_CASE("truncation is reported at the end of the file") {
  const std::string full = square;
  for (std::size_t cut = 0; cut + 2 < full.size(); ++cut) {
    const std::string text = full.substr(0, cut);
    CAPTURE(text);
    CHECK_THROWS_AS(madd::parse_poly(text), madd::ParseError);
  }
}

TEST_CASE("a lying header fails fast without allocating") {
  auto e = parse_error_of("100000000 2 0 0\n1 0 0\n2 1 0\n3 1 1\n");
  CHECK(e.line() == 1);
  e = parse_error_of("3 2 4000000000 0\n1 0 0\n2 1 0\n3 1 1\n");
  CHECK(e.line() == 1);
  e = parse_error_of("3 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4294967294 0\n1 1 2\n");
  CHECK(e.line() == 5);
  e = parse_error_of("3 2 0 0\n1 0 0\n2 1 0\n3 1 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n3000000000\n1 1 1\n");
  CHECK(e.line() == 9);
}

TEST_CASE("vertex count 0 reads the companion .node file") {
  const std::string path = std::string(MADD_DATA_DIR) + "/l_shape.poly";
  const madd::PolyFile f = madd::read_poly_file(path);
  CHECK(f.pslg.first_index == 0);
  CHECK(f.pslg.points.size() == 6);
  CHECK(f.pslg.attributes_per_point == 1);
  CHECK(f.pslg.attribute(5, 0) == 2.5);
  CHECK(f.pslg.point_markers.size() == 6);
  CHECK(f.source.point_path == std::string(MADD_DATA_DIR) + "/l_shape.node");
  CHECK(f.source.point_lines.front() == 3);
  CHECK(f.pslg.segments.size() == 6);
  CHECK(f.pslg.segments[5] == madd::Segment{5, 0, 2});
  const madd::PolyFile node = madd::read_poly_file(std::string(MADD_DATA_DIR) + "/l_shape.node");
  CHECK(node.pslg.points == f.pslg.points);
  CHECK_THROWS_AS(madd::parse_poly("0 2 0 0\n0 0\n0\n", "/nonexistent/x.poly"), madd::ParseError);
}

TEST_CASE("read_background_samples: the first attribute of each node, refused where the kind cannot have it") {
  const fs::path dir = fs::temp_directory_path() / ("madd-background-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto put = [&](const char* name, const char* text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string zero = put("zero.node", "# a zero value\n3 2 2 0\n1 0 0 4 7\n2 1 0 0 7\n3 0 1 0.5 7\n");
  const std::vector<madd::ValuedPoint> weights = madd::read_background_samples(zero, madd::SampleValue::weight);
  REQUIRE(weights.size() == 3);
  CHECK(weights[0] == madd::ValuedPoint{{0, 0}, 4.0});  // the first attribute, not the second
  CHECK(weights[1].value == 0.0);                       // a weight may be 0
  try {
    madd::read_background_samples(zero, madd::SampleValue::area);  // an area may not
    FAIL("a zero area was taken");
  } catch (const madd::ParseError& e) {
    CHECK(e.line() == 4);  // located at the node's line
    CHECK(std::string(e.what()).find("node 2") != std::string::npos);
  }
  const std::string bare = put("bare.node", "1 2 0 0\n1 0 0\n");
  CHECK_THROWS_AS(madd::read_background_samples(bare, madd::SampleValue::weight), madd::ParseError);
  const std::string nan = put("nan.node", "1 2 1 0\n1 0 0 nan\n");
  CHECK_THROWS_AS(madd::read_background_samples(nan, madd::SampleValue::weight), madd::ParseError);
  CHECK_THROWS_AS(madd::read_background_samples((dir / "missing.node").string(), madd::SampleValue::area),
                  madd::InputFileError);
  fs::remove_all(dir);
}

TEST_CASE("random Pslgs round-trip bit-exactly") {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> coord(-1e6, 1e6);
  for (int round = 0; round < 20; ++round) {
    madd::Pslg p;
    p.first_index = static_cast<std::uint32_t>(round % 2);
    p.attributes_per_point = static_cast<std::uint32_t>(round % 3);
    const int n = 1 + round * 7;
    for (int i = 0; i < n; ++i) {
      const double scale = std::ldexp(1.0, static_cast<int>(rng() % 600) - 300);
      p.points.push_back({coord(rng) * scale, coord(rng)});
      for (std::uint32_t k = 0; k < p.attributes_per_point; ++k) p.attributes.push_back(coord(rng));
      if (round % 2) p.point_markers.push_back(static_cast<int>(rng() % 100) - 50);
    }
    p.has_segment_markers = round % 4 == 1;
    for (int i = 0; i < n; ++i)
      p.segments.push_back({static_cast<std::uint32_t>(rng() % n), static_cast<std::uint32_t>(rng() % n),
                            p.has_segment_markers ? static_cast<int>(rng() % 9) : 0});
    p.holes.push_back({coord(rng), 5e-324});
    if (round % 3 == 0) p.regions.push_back({{coord(rng), coord(rng)}, coord(rng), -1.0});
    CHECK(madd::parse_poly(madd::format_poly(p, "line one\nline two")).pslg == p);
  }
}

TEST_CASE("write_file_atomically writes through a rename and reports failures") {
  const fs::path dir = fs::temp_directory_path() / ("madd_poly_io_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "out.poly").string();
  madd::write_file_atomically(path, square);
  CHECK(slurp(path) == square);
  madd::write_file_atomically(path, "replaced");
  CHECK(slurp(path) == "replaced");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
  CHECK_THROWS_AS(madd::write_file_atomically((dir / "missing" / "x.poly").string(), "x"), madd::Error);
  fs::remove_all(dir);
  CHECK_THROWS_AS(madd::read_poly_file((dir / "none.poly").string()), madd::Error);
}

}  // TEST_SUITE("poly_io")

TEST_CASE("read_poly_file of a directory is an input file error (it was bad_alloc: tellg of a directory)") {
  CHECK_THROWS_AS(madd::read_poly_file(MADD_DATA_DIR), madd::InputFileError);
  CHECK_THROWS_AS(madd::read_domain(MADD_DATA_DIR "/bad"), madd::InputFileError);
}
