// The outputs of docs/formats.md read back: .poly files through parse_poly,
// the subdomain file through a small parser here, SVG and JSON structurally.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>

#include "madd/decomposition.hpp"
#include "madd/metrics.hpp"
#include "madd/output.hpp"
#include "madd/poly_io.hpp"
#include "interior_fixtures.hpp"
#include "metrics_fixtures.hpp"
#include "scratch_files.hpp"

namespace {

using namespace madd;
using madd::test::read_text;
using madd::test::TempDir;
namespace fs = std::filesystem;

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// Parses the subdomain file (docs/formats.md, output 3) back into a Decomposition
// (points, segments, rings' segments, areas, weights, hole points).
Decomposition parse_subdomain_file(const std::string& text) {
  std::string clean;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) clean += line.substr(0, line.find('#')) + "\n";
  std::istringstream in(clean);
  Decomposition d;
  std::size_t n = 0, dim = 0, k = 0;
  in >> n >> dim;
  for (std::size_t i = 0; i < n; ++i) {
    Point p;
    in >> k >> p.x >> p.y;
    REQUIRE(k == i + 1);
    d.points.push_back(p);
  }
  int has_markers = 0;
  in >> n >> has_markers;
  for (std::size_t i = 0; i < n; ++i) {
    Segment s;
    in >> k >> s.a >> s.b >> s.marker;
    --s.a;
    --s.b;
    d.segments.push_back(s);
  }
  in >> n;
  d.subdomains.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Subdomain& sub = d.subdomains[i];
    std::size_t rings = 0;
    in >> k >> sub.area >> sub.weight >> rings;
    REQUIRE(k == i);
    sub.ring_segments.resize(rings);
    for (auto& ring : sub.ring_segments) {
      std::size_t m = 0;
      in >> m;
      ring.resize(m);
      for (auto& s : ring) {
        in >> s;
        --s;
      }
    }
  }
  in >> n;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t holes = 0;
    in >> k >> holes;
    d.subdomains[k].hole_points.resize(holes);
    for (auto& h : d.subdomains[k].hole_points) in >> h.x >> h.y;
  }
  REQUIRE(!in.fail());
  // Section 5, interior constraints, is there only when some subdomain has some.
  if (in >> n) {
    REQUIRE(n == d.subdomains.size());
    for (std::size_t i = 0; i < n; ++i) {
      in >> k;
      REQUIRE(k == i);
      for (auto* ids : {&d.subdomains[k].interior_segments, &d.subdomains[k].interior_points}) {
        std::size_t m = 0;
        in >> m;
        ids->resize(m);
        for (auto& id : *ids) {
          in >> id;
          --id;
        }
      }
    }
    REQUIRE(!in.fail());
    std::string rest;
    REQUIRE(!(in >> rest));
  }
  return d;
}

}  // namespace

TEST_SUITE("output") {

TEST_CASE("output 1 parses back with every point, segment, hole and one region per subdomain") {
  for (const test::Fixture& f : test::all_fixtures()) {
    const Decomposition& d = f.decomposition;
    const PolyFile back = parse_poly(format_decomposition_poly(d, "a comment\non two lines"));
    CHECK(back.pslg.points == d.points);  // %.17g round-trips exactly
    REQUIRE(back.pslg.segments.size() == d.segments.size());
    for (std::size_t s = 0; s < d.segments.size(); ++s) CHECK(back.pslg.segments[s] == d.segments[s]);
    CHECK(back.pslg.holes == d.holes);
    REQUIRE(back.pslg.regions.size() == d.subdomains.size());
    for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
      CHECK(back.pslg.regions[k].at == d.subdomains[k].interior_point);
      CHECK(back.pslg.regions[k].attribute == double(k));
      CHECK(back.pslg.regions[k].max_area == -1.0);
    }
  }
}

TEST_CASE("output 2: each subdomain file parses; shared separators are bit-identical") {
  const test::Fixture f = test::rectangle_with_hole();
  const Decomposition& d = f.decomposition;
  std::map<std::pair<std::pair<double, double>, std::pair<double, double>>, int> seen;
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    const PolyFile back = parse_poly(format_subdomain_poly(d, k));
    const Subdomain& sub = d.subdomains[k];
    std::size_t edges = 0;
    for (const auto& ring : sub.rings) edges += ring.size();
    CHECK(back.pslg.points.size() == edges);  // rings here share no vertex
    REQUIRE(back.pslg.segments.size() == edges);
    CHECK(back.pslg.first_index == 1);
    CHECK(back.pslg.holes == sub.hole_points);
    for (const Segment& s : back.pslg.segments) {
      auto a = std::make_pair(back.pslg.points[s.a].x, back.pslg.points[s.a].y);
      auto b = std::make_pair(back.pslg.points[s.b].x, back.pslg.points[s.b].y);
      if (b < a) std::swap(a, b);
      seen[{a, b}] += s.marker == 0 ? 10 : 1;
    }
  }
  // The separator (1,0)-(1,1) appears in both files with marker 0; boundary pieces once.
  CHECK(seen[{{1.0, 0.0}, {1.0, 1.0}}] == 20);
  CHECK(seen[{{0.0, 0.0}, {1.0, 0.0}}] == 1);
  CHECK(seen[{{0.25, 0.25}, {0.75, 0.25}}] == 1);
  CHECK(seen.size() == 4 + 4 + 3);
}

TEST_CASE("output 2 of a real decomposition: every separator in two files, every boundary piece in one") {
  const Pslg domain = read_domain(std::string(MADD_DATA_DIR) + "/key.poly");
  DecomposeOptions options;
  options.subdomains = 8;
  const Decomposition d = decompose(domain, options);
  REQUIRE(verify_decomposition(d, domain, 8).ok());
  TempDir tmp("output");
  write_split(d, (tmp.path / "parts").string(), "key");
  std::map<std::pair<std::pair<double, double>, std::pair<double, double>>, std::pair<int, int>> seen;  // count, marker
  std::size_t files = 0;
  for (std::uint32_t k = 0; k < 8; ++k) {
    const fs::path file = tmp.path / "parts" / split_file_name("key", k, 8);
    const PolyFile back = parse_poly(read_text(file), file.string());
    ++files;
    CHECK(back.pslg.holes.size() + 1 == d.subdomains[k].rings.size());
    for (const Segment& s : back.pslg.segments) {
      auto a = std::make_pair(back.pslg.points[s.a].x, back.pslg.points[s.a].y);
      auto b = std::make_pair(back.pslg.points[s.b].x, back.pslg.points[s.b].y);
      if (b < a) std::swap(a, b);
      auto& entry = seen[{a, b}];
      ++entry.first;
      entry.second = s.marker;
    }
  }
  CHECK(files == 8);
  CHECK(seen.size() == d.segments.size());  // shared coordinates are bit-identical
  for (const auto& [key, entry] : seen) CHECK(entry.first == (entry.second == 0 ? 2 : 1));
}

TEST_CASE("output 2: names are zero-padded to the width of N-1") {
  CHECK(split_file_name("key", 0, 1) == "key-0.poly");
  CHECK(split_file_name("key", 7, 10) == "key-7.poly");
  CHECK(split_file_name("key", 7, 11) == "key-07.poly");
  CHECK(split_file_name("key", 42, 1000) == "key-042.poly");
}

TEST_CASE("write_split writes exactly N files, replacing an earlier run's") {
  TempDir tmp("output");
  const fs::path dir = tmp.path / "split";
  const test::Fixture quad = test::square_quadrants();
  write_split(quad.decomposition, dir.string(), "sq");
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  CHECK(names == std::set<std::string>{"sq-0.poly", "sq-1.poly", "sq-2.poly", "sq-3.poly"});
  CHECK(read_text(dir / "sq-2.poly") == format_subdomain_poly(quad.decomposition, 2));

  std::ofstream(dir / "notes.txt") << "kept";
  write_split(test::square_halves().decomposition, dir.string(), "sq");
  names.clear();
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  CHECK(names == std::set<std::string>{"notes.txt", "sq-0.poly", "sq-1.poly"});
  // No staging directory is left behind.
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(tmp.path)) ++entries;
  CHECK(entries == 1);
}

TEST_CASE("write_split into a path that is a file fails and leaves nothing") {
  TempDir tmp("output");
  const fs::path file = tmp.path / "plain";
  std::ofstream(file) << "x";
  CHECK_THROWS_AS(write_split(test::square_halves().decomposition, file.string(), "sq"), Error);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(tmp.path)) ++entries;
  CHECK(entries == 1);
}

namespace {

// The subdomain file of `d`, parsed back, holds what the file format carries.
void check_subdomain_file_round_trip(const Decomposition& d) {
  const Decomposition back = parse_subdomain_file(format_subdomain_file(d));
  CHECK(back.points == d.points);
  CHECK(back.segments == d.segments);
  REQUIRE(back.subdomains.size() == d.subdomains.size());
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    CHECK(back.subdomains[k].ring_segments == d.subdomains[k].ring_segments);
    CHECK(back.subdomains[k].area == d.subdomains[k].area);
    CHECK(back.subdomains[k].weight == d.subdomains[k].weight);
    CHECK(back.subdomains[k].hole_points == d.subdomains[k].hole_points);
    CHECK(back.subdomains[k].interior_segments == d.subdomains[k].interior_segments);
    CHECK(back.subdomains[k].interior_points == d.subdomains[k].interior_points);
  }
}

}  // namespace

TEST_CASE("output 3: the subdomain file parses back to the same decomposition") {
  for (const test::Fixture& f : test::all_fixtures()) check_subdomain_file_round_trip(f.decomposition);
}

TEST_CASE("output 3: interior segments and isolated points in section 5, only when there are some") {
  for (const test::Fixture& f : test::all_fixtures())
    CHECK(format_subdomain_file(f.decomposition).find("section 5") == std::string::npos);
  const Decomposition d = test::interior_square().decomposition;
  CHECK(!d.subdomains[0].interior_segments.empty());
  check_subdomain_file_round_trip(d);
}

TEST_CASE("output 4: SVG has one path per subdomain plus two edge paths, balanced tags") {
  const test::Fixture f = test::annulus_halves();
  SvgOptions options;
  options.numbers = true;
  options.mark_angles_below_deg = 95;  // every angle here is 90
  const std::string svg = format_svg(f.decomposition, options);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(count_of(svg, "<path ") == f.decomposition.subdomains.size() + 2);
  CHECK(count_of(svg, "<text ") == 2);
  CHECK(count_of(svg, "<circle ") == 8);
  CHECK(count_of(svg, "<g ") == count_of(svg, "</g>"));
  CHECK(count_of(svg, "<svg ") == 1);
  CHECK(count_of(svg, "</svg>") == 1);
  CHECK(count_of(svg, "fill-rule=\"evenodd\"") == 1);
  // Path data holds only commands and plain numbers.
  for (std::size_t at = svg.find(" d=\""); at != std::string::npos; at = svg.find(" d=\"", at + 1)) {
    const std::size_t end = svg.find('"', at + 4);
    const std::string data = svg.substr(at + 4, end - at - 4);
    CHECK(data.find_first_not_of("0123456789.- MLZ") == std::string::npos);
  }
  // The picture of a 4 x 4 domain keeps its aspect ratio.
  CHECK(svg.find("width=\"1040\" height=\"1040\"") != std::string::npos);
}

TEST_CASE("output 5: the report is one JSON object with every figure") {
  std::vector<PhaseTime> times{{"read", 0.25}, {"dec\"ompose", 1.5}};
  const std::string json = format_report_json(metrics(test::surrounded().decomposition, times));
  // A minimal structural check: balanced braces outside strings, keys quoted.
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{') {
      ++depth;
    } else if (c == '}') {
      --depth;
      CHECK(depth >= 0);
    }
  }
  CHECK(depth == 0);
  CHECK(!in_string);
  for (const char* key : {"subdomains", "angle_min", "angle_p10", "angle_median", "angle_p90", "boundary_angle_median",
                          "separator_length", "separator_length_norm", "mean_separator_per_subdomain",
                          "max_sep_len_over_area_norm", "max_area_over_mean", "min_area_over_mean",
                          "max_weight_over_mean", "min_weight_over_mean", "shortest_new_segment_norm", "times"}) {
    std::string quoted = "\"";
    quoted += key;
    quoted += "\": ";
    CHECK_MESSAGE(json.find(quoted) != std::string::npos, key);
  }
  CHECK(json.find("\"boundary_angle_median\": null") != std::string::npos);  // no boundary corner: NaN -> null
  CHECK(json.find("\"dec\\\"ompose\": 1.5") != std::string::npos);
  CHECK(json.find("nan") == std::string::npos);
}

}  // TEST_SUITE("output")
