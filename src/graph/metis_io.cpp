// METIS graph-file reader (the format gpmetis reads; docs/formats.md, "Graphs").
// Strict: every malformed input gets a ParseError naming line and column, and
// no count from the header is trusted before the remaining text could hold it.
#include <charconv>
#include <fstream>
#include <sstream>

#include "graph/graph_detail.hpp"
#include "madd/error.hpp"
#include "madd/metis_io.hpp"

namespace madd {

namespace {

struct Token {
  std::string_view text;
  std::size_t column = 0;  // 1-based
};

class Reader {
public:
  Reader(std::string_view text, const std::string& path) : text_(text), path_(path) {}

  [[noreturn]] void fail(std::size_t line, std::size_t column, const std::string& message) const {
    throw ParseError(path_, line, column, message);
  }
  // Next line that is not a '%' comment (blank lines are returned, as METIS
  // reads them as vertices without neighbours). False at end of text.
  bool next_line(bool skip_blank) {
    while (pos_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      line_start_ = pos_;
      line_ = text_.substr(pos_, end - pos_);
      if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
      pos_ = end + 1;
      ++line_no_;
      const std::size_t first = line_.find_first_not_of(" \t");
      if (first != std::string_view::npos && line_[first] == '%') continue;
      if (skip_blank && first == std::string_view::npos) continue;
      return true;
    }
    line_start_ = text_.size();
    line_ = {};
    return false;
  }
  static std::vector<Token> split(std::string_view line) {
    std::vector<Token> tokens;
    split_into(line, tokens);
    return tokens;
  }
  static void split_into(std::string_view line, std::vector<Token>& tokens) {
    tokens.clear();
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      const std::size_t start = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
      if (i > start) tokens.push_back({line.substr(start, i - start), start + 1});
    }
  }
  std::uint64_t number(const Token& t, const char* what) const {
    std::uint64_t value = 0;
    const char* end = t.text.data() + t.text.size();
    const auto [ptr, ec] = std::from_chars(t.text.data(), end, value);
    if (ec == std::errc::result_out_of_range || (ec == std::errc() && ptr == end && value > (1ull << 53)))
      fail(line_no_, t.column, std::string(what) + " '" + std::string(t.text) + "' is too large");
    if (ec != std::errc() || ptr != end)
      fail(line_no_, t.column,
           std::string("expected ") + what + " (a non-negative integer), found '" + std::string(t.text) + "'");
    return value;
  }
  std::string_view line() const noexcept { return line_; }
  std::size_t line_no() const noexcept { return line_no_; }
  std::size_t line_start() const noexcept { return line_start_; }
  std::size_t remaining() const noexcept { return text_.size() - std::min(pos_, text_.size()); }
  std::string_view text() const noexcept { return text_; }

private:
  std::string_view text_;
  const std::string& path_;
  std::string_view line_;
  std::size_t pos_ = 0, line_start_ = 0, line_no_ = 0;
};

struct Header {
  std::uint32_t n = 0;
  std::uint64_t m = 0;
  bool vertex_weights = false, edge_weights = false;
  std::size_t line = 0, m_column = 0;
};

Header read_header(Reader& r) {
  if (!r.next_line(true)) r.fail(r.line_no() + 1, 1, "empty file: expected a header 'n m [fmt [ncon]]'");
  const std::vector<Token> t = Reader::split(r.line());
  Header h;
  h.line = r.line_no();
  if (t.size() < 2) r.fail(h.line, 1, "header needs at least 'n m'");
  if (t.size() > 4) r.fail(h.line, t[4].column, "header has more than 4 fields 'n m fmt ncon'");
  const std::uint64_t n = r.number(t[0], "vertex count");
  h.m = r.number(t[1], "edge count");
  h.m_column = t[1].column;
  if (t.size() >= 3) {
    const std::string_view fmt = t[2].text;
    if (fmt.size() > 3 || fmt.find_first_not_of("01") != std::string_view::npos)
      r.fail(h.line, t[2].column, "fmt must be 000, 001, 010 or 011, found '" + std::string(fmt) + "'");
    const std::string padded = std::string(3 - fmt.size(), '0') + std::string(fmt);
    if (padded[0] == '1') r.fail(h.line, t[2].column, "vertex sizes (fmt 1xx) are not supported");
    h.vertex_weights = padded[1] == '1';
    h.edge_weights = padded[2] == '1';
  }
  if (t.size() == 4 && r.number(t[3], "constraint count") != 1)
    r.fail(h.line, t[3].column, "only one vertex weight per vertex is supported (ncon must be 1)");
  // A lying header must not make us allocate: every vertex needs a line
  // (at least one byte) and every edge two list entries of two bytes each.
  if (n > r.remaining() + 1 || n >= detail::no_vertex)
    r.fail(h.line, t[0].column,
           "header declares " + std::to_string(n) + " vertices but only " + std::to_string(r.remaining()) +
               " bytes follow");
  if (h.m > (r.remaining() + 1) / 4 || 2 * h.m >= detail::no_vertex)
    r.fail(h.line, h.m_column,
           "header declares " + std::to_string(h.m) + " edges but only " + std::to_string(r.remaining()) +
               " bytes follow");
  h.n = static_cast<std::uint32_t>(n);
  return h;
}

// Column of list entry `k` of the vertex whose line starts at `start`.
std::size_t entry_column(std::string_view text, std::size_t start, const Header& h, std::size_t k) {
  std::size_t end = std::min(text.find('\n', start), text.size());
  const std::vector<Token> t = Reader::split(text.substr(start, end - start));
  const std::size_t index = (h.vertex_weights ? 1 : 0) + k * (h.edge_weights ? 2 : 1);
  return index < t.size() ? t[index].column : 1;
}

struct VertexLines {
  std::vector<std::uint32_t> line;  // line number of each vertex
  std::vector<std::size_t> start;   // byte offset of each vertex's line
};

VertexLines read_vertices(Reader& r, const Header& h, Graph& g) {
  VertexLines where;
  where.line.reserve(h.n);
  where.start.reserve(h.n);
  g.offsets.assign(1, 0);
  g.vertex_weights.reserve(h.n);
  g.adjacency.reserve(2 * h.m);
  g.edge_weights.reserve(2 * h.m);
  std::vector<std::uint32_t> listed(h.n, detail::no_vertex);  // who last listed each vertex
  std::vector<Token> t;
  for (std::uint32_t v = 0; v < h.n; ++v) {
    if (!r.next_line(false))
      r.fail(r.line_no() + 1, 1,
             "file ends after " + std::to_string(v) + " of " + std::to_string(h.n) + " vertex lines");
    where.line.push_back(static_cast<std::uint32_t>(r.line_no()));
    where.start.push_back(r.line_start());
    Reader::split_into(r.line(), t);
    std::size_t i = 0;
    if (h.vertex_weights) {
      if (t.empty()) r.fail(r.line_no(), 1, "vertex " + std::to_string(v + 1) + " has no weight");
      g.vertex_weights.push_back(static_cast<double>(r.number(t[i++], "vertex weight")));
    } else {
      g.vertex_weights.push_back(1.0);
    }
    while (i < t.size()) {
      const Token& id = t[i++];
      const std::uint64_t u = r.number(id, "neighbour id");
      if (u < 1 || u > h.n)
        r.fail(r.line_no(), id.column,
               "neighbour id " + std::to_string(u) + " is out of range 1.." + std::to_string(h.n));
      if (u == v + 1) r.fail(r.line_no(), id.column, "self-loop: vertex " + std::to_string(u) + " lists itself");
      if (listed[u - 1] == v) r.fail(r.line_no(), id.column, "vertex " + std::to_string(u) + " is listed twice");
      listed[u - 1] = v;
      double w = 1.0;
      if (h.edge_weights) {
        if (i == t.size()) r.fail(r.line_no(), id.column, "neighbour " + std::to_string(u) + " has no edge weight");
        const Token& wt = t[i++];
        const std::uint64_t value = r.number(wt, "edge weight");
        if (value == 0) r.fail(r.line_no(), wt.column, "edge weight must be positive");
        w = static_cast<double>(value);
      }
      if (g.adjacency.size() == 2 * h.m)
        r.fail(r.line_no(), id.column,
               "more adjacency entries than the header's " + std::to_string(h.m) + " edges allow");
      g.adjacency.push_back(static_cast<std::uint32_t>(u - 1));
      g.edge_weights.push_back(w);
    }
    g.offsets.push_back(static_cast<std::uint32_t>(g.adjacency.size()));
  }
  return where;
}

// Every entry u->v must be matched by v->u with the same weight. Entries are
// bucketed by target (counting sort), then each vertex's own list is checked
// against the entries pointing at it.
void check_symmetric(const Reader& r, const Header& h, const Graph& g, const VertexLines& where) {
  const std::uint32_t n = h.n;
  std::vector<std::uint32_t> start(n + 1, 0);
  for (const std::uint32_t v : g.adjacency) ++start[v + 1];
  for (std::uint32_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> from(g.adjacency.size()), entry(g.adjacency.size());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t u = 0; u < n; ++u) {
    for (std::uint32_t i = g.offsets[u]; i < g.offsets[u + 1]; ++i) {
      from[fill[g.adjacency[i]]] = u;
      entry[fill[g.adjacency[i]]++] = i;
    }
  }
  std::vector<std::uint32_t> mark(n, detail::no_vertex);
  std::vector<double> weight(n, 0.0);
  for (std::uint32_t v = 0; v < n; ++v) {
    for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i) {
      mark[g.adjacency[i]] = v;
      weight[g.adjacency[i]] = g.edge_weights[i];
    }
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
      const std::uint32_t u = from[k], i = entry[k];
      if (mark[u] == v && weight[u] == g.edge_weights[i]) continue;
      const std::size_t col = entry_column(r.text(), where.start[u], h, i - g.offsets[u]);
      const std::string uv = std::to_string(u + 1), vv = std::to_string(v + 1);
      if (mark[u] != v)
        r.fail(where.line[u], col,
               "asymmetric edge: vertex " + uv + " lists " + vv + " but vertex " + vv + " (line " +
                   std::to_string(where.line[v]) + ") does not list " + uv);
      if (weight[u] != g.edge_weights[i])
        r.fail(where.line[u], col,
               "asymmetric edge weight: " + uv + "-" + vv + " has weight " +
                   std::to_string(static_cast<long long>(g.edge_weights[i])) + " here but " +
                   std::to_string(static_cast<long long>(weight[u])) + " on line " + std::to_string(where.line[v]));
    }
  }
}

}  // namespace

Graph parse_metis(std::string_view text, const std::string& path) {
  Reader r(text, path);
  const Header h = read_header(r);
  Graph g;
  const VertexLines where = read_vertices(r, h, g);
  while (r.next_line(true))
    r.fail(r.line_no(), 1, "unexpected data after the " + std::to_string(h.n) + " vertex lines");
  if (g.adjacency.size() != 2 * h.m)
    r.fail(h.line, h.m_column,
           "header declares " + std::to_string(h.m) + " edges but the lists hold " +
               std::to_string(g.adjacency.size()) + " entries (expected " + std::to_string(2 * h.m) + ")");
  check_symmetric(r, h, g, where);
  return g;
}

Graph read_metis_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputFileError(path + ": cannot open file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputFileError(path + ": read error");
  const std::string text = buffer.str();
  return parse_metis(text, path);
}

}  // namespace madd
