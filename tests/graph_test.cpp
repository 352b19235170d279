// Tests for the CSR graph and the METIS graph reader.
#include <doctest/doctest.h>

#include <string>

#include "madd/error.hpp"
#include "madd/graph.hpp"
#include "madd/metis_io.hpp"

namespace {

// Parses `text` expecting failure; returns the error for inspection.
madd::ParseError parse_failure(const std::string& text) {
  try {
    (void)madd::parse_metis(text, "g.graph");
  } catch (const madd::ParseError& e) {
    return e;
  }
  FAIL("expected a ParseError for: " << text);
  return madd::ParseError("", 0, 0, "");
}

bool symmetric(const madd::Graph& g) {
  for (std::uint32_t u = 0; u < g.vertex_count(); ++u) {
    for (std::uint32_t i = g.offsets[u]; i < g.offsets[u + 1]; ++i) {
      const std::uint32_t v = g.adjacency[i];
      bool found = false;
      for (std::uint32_t j = g.offsets[v]; j < g.offsets[v + 1]; ++j)
        found = found || (g.adjacency[j] == u && g.edge_weights[j] == g.edge_weights[i]);
      if (!found || v == u) return false;
    }
  }
  return true;
}

}  // namespace

TEST_SUITE("graph") {
TEST_CASE("make_graph merges parallel edges and drops self-loops") {
  const madd::Graph g = madd::make_graph({1, 2, 3}, {{0, 1, 1.5}, {1, 0, 2.0}, {1, 1, 9.0}, {1, 2, 0.25}});
  REQUIRE(g.vertex_count() == 3);
  CHECK(g.edge_count() == 2);
  CHECK(symmetric(g));
  CHECK(g.adjacency[g.offsets[0]] == 1);
  CHECK(g.edge_weights[g.offsets[0]] == doctest::Approx(3.5));
  CHECK(g.vertex_weights[2] == 3.0);
}

TEST_CASE("empty graph") {
  const madd::Graph g = madd::make_graph({}, {});
  CHECK(g.vertex_count() == 0);
  CHECK(g.edge_count() == 0);
  CHECK(madd::parse_metis("0 0\n").vertex_count() == 0);
}

TEST_CASE("METIS formats 000, 001, 010, 011 with comments") {
  // A triangle 1-2-3 plus an isolated vertex 4 (its line is blank).
  const madd::Graph plain = madd::parse_metis("% a comment\n4 3\n2 3\n1 3\n% mid comment\n1 2\n\n");
  CHECK(plain.vertex_count() == 4);
  CHECK(plain.edge_count() == 3);
  CHECK(plain == madd::make_graph({1, 1, 1, 1}, {{0, 1, 1}, {0, 2, 1}, {1, 2, 1}}));
  const madd::Graph ew = madd::parse_metis("3 2 001\n2 5\n1 5 3 7\n2 7\n");
  CHECK(ew == madd::make_graph({1, 1, 1}, {{0, 1, 5}, {1, 2, 7}}));
  const madd::Graph vw = madd::parse_metis("3 2 10\n4 2\n5 1 3\n6 2\n");
  CHECK(vw == madd::make_graph({4, 5, 6}, {{0, 1, 1}, {1, 2, 1}}));
  const madd::Graph both = madd::parse_metis("2 1 011 1\r\n10 2 3\r\n20 1 3\r\n");
  CHECK(both == madd::make_graph({10, 20}, {{0, 1, 3}}));
  CHECK(symmetric(both));
}

TEST_CASE("malformed METIS files get line:column errors") {
  struct Case {
    const char* text;
    std::size_t line, column;
    const char* words;
  };
  const Case cases[] = {
      {"", 1, 1, "empty file"},
      {"3\n", 1, 1, "at least"},
      {"3 2 001 1 9\n", 1, 11, "more than 4"},
      {"2 1 012\n2\n1\n", 1, 5, "fmt"},
      {"2 1 100\n2\n1\n", 1, 5, "vertex sizes"},
      {"2 1 010 2\n1 2\n1 1\n", 1, 9, "ncon"},
      {"3 1\n2\n1\n", 4, 1, "file ends after 2 of 3"},
      {"2 1\n2\nx\n", 3, 1, "non-negative integer"},
      {"2 1\n2\n1 -1\n", 3, 3, "non-negative integer"},
      {"2 1\n3\n1\n", 2, 1, "out of range"},
      {"2 1\n0\n1\n", 2, 1, "out of range"},
      {"2 1\n1 2\n1\n", 2, 1, "self-loop"},
      {"3 1\n2\n\n\n", 1, 3, "edges but the lists hold 1"},
      {"3 2\n2 3\n1\n2\n", 4, 1, "asymmetric edge: vertex 3 lists 2"},
      {"2 1 001\n2 4\n1 5\n", 3, 1, "asymmetric edge weight"},
      {"2 1 001\n2\n1 5\n", 2, 1, "no edge weight"},
      {"2 1 001\n2 0\n1 0\n", 2, 3, "positive"},
      {"2 1 010\n\n1\n", 2, 1, "no weight"},
      {"3 1\n2 2\n1\n\n", 2, 3, "listed twice"},
      {"2 1\n2\n1\n7\n", 4, 1, "after the 2 vertex lines"},
      {"3 1\n2 3\n1\n1\n", 3, 1, "more adjacency entries"},
      {"99999999999 5\n", 1, 1, "vertices but only"},
      {"2 4000000000\n2\n1\n", 1, 3, "edges but only"},
      {"2 1\n2\n99999999999999999999999\n", 3, 1, "too large"},
  };
  for (const Case& c : cases) {
    const madd::ParseError e = parse_failure(c.text);
    CAPTURE(std::string(c.text));
    CAPTURE(std::string(e.what()));
    CHECK(e.path() == "g.graph");
    CHECK(e.line() == c.line);
    CHECK(e.column() == c.column);
    CHECK(e.message().find(c.words) != std::string::npos);
  }
}

TEST_CASE("read_metis_file reports a missing file as an InputFileError (exit 3 in the CLI)") {
  CHECK_THROWS_AS(madd::read_metis_file("/nonexistent/dir/none.graph"), madd::InputFileError);
}
}  // TEST_SUITE("graph")
