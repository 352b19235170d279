// Strict readers of bathymetry files (docs/formats.md, "Bathymetry"): the
// Esri ASCII grid (.asc) and the x y z scatter.
//
// The grid as Esri defines it: "key value" header pairs, then nrows*ncols
// numbers, the north row first, separated by whitespace (a row need not end
// its line: the column count decides where a row ends). Keys in any case and
// any order (GDAL writes dx and dy instead of cellsize for cells that are not
// square; we read both). Stricter than most readers, on purpose: every value
// a whole number token, the NODATA value the only non-finite value allowed,
// the count exact, x and y origins of one kind (both corners or both
// centres, as Esri requires), and nothing after the last value.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <new>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "kernel/coordinate_range.hpp"
#include "kernel/number_format.hpp"
#include "madd/bathymetry.hpp"
#include "madd/error.hpp"
#include "madd/predicates.hpp"

namespace madd {
namespace {

using detail::number_text;

// A UTF-8 byte order mark (spreadsheets write one before CSV text) is not
// part of the text: columns count from after it.
std::string_view without_bom(std::string_view text) noexcept {
  return text.substr(0, 3) == "\xEF\xBB\xBF" ? text.substr(3) : text;
}

bool is_space(char c) noexcept { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Tokens are echoed in messages: keep them short and printable.
std::string printable(std::string_view tok) {
  std::string out;
  for (char c : tok.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
  if (tok.size() > 40) out += "...";
  return out;
}

// A real number as from_chars reads it (nan and inf included), with an
// optional '+' sign; nullopt unless the whole token is the number, and an
// out-of-range value reported through `out_of_range`.
std::optional<double> parse_real(std::string_view tok, bool* out_of_range = nullptr) {
  if (tok.size() > 1 && tok[0] == '+' && tok[1] != '-') tok.remove_prefix(1);
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec == std::errc::result_out_of_range && ptr == tok.data() + tok.size() && out_of_range != nullptr) {
    *out_of_range = true;
    return std::nullopt;
  }
  if (ec != std::errc() || ptr != tok.data() + tok.size() || tok.empty()) return std::nullopt;
  return v;
}

// Whitespace-separated tokens over the whole text, newlines included (the
// grid's rows need not end their lines), each with its line and column.
class GridLexer {
public:
  GridLexer(std::string_view text, std::string path) : text_(text), path_(std::move(path)) {}

  // The next token (and moves past it); empty at the end of the text.
  std::string_view next() {
    skip_space();
    begin_ = pos_;
    token_line_ = line_;
    token_line_begin_ = line_begin_;
    while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    return text_.substr(begin_, pos_ - begin_);
  }
  // The next token without moving past it.
  std::string_view peek() {
    skip_space();
    std::size_t end = pos_;
    while (end < text_.size() && !is_space(text_[end]) && text_[end] != '\n') ++end;
    return text_.substr(pos_, end - pos_);
  }
  std::size_t line() const noexcept { return token_line_; }
  std::size_t column() const noexcept { return begin_ - token_line_begin_ + 1; }
  // Bytes from the next token on, to bound counts before allocating.
  std::size_t remaining_bytes() {
    skip_space();
    return text_.size() - pos_;
  }

  [[noreturn]] void fail(const std::string& message) const { throw ParseError(path_, line(), column(), message); }
  [[noreturn]] void fail_at(std::size_t line, std::size_t column, const std::string& message) const {
    throw ParseError(path_, line, column, message);
  }
  // Just past the last byte.
  [[noreturn]] void fail_at_end(const std::string& message) {
    skip_space();
    throw ParseError(path_, line_, text_.size() - line_begin_ + 1, "unexpected end of file: " + message);
  }

private:
  void skip_space() noexcept {
    for (; pos_ < text_.size(); ++pos_) {
      if (text_[pos_] == '\n') {
        ++line_;
        line_begin_ = pos_ + 1;
      } else if (!is_space(text_[pos_])) {
        return;
      }
    }
  }

  std::string_view text_;
  std::string path_;
  std::size_t pos_ = 0, line_ = 1, line_begin_ = 0;
  std::size_t begin_ = 0, token_line_ = 1, token_line_begin_ = 0;
};

enum Key : std::size_t { ncols, nrows, xllcorner, xllcenter, yllcorner, yllcenter, cellsize, dx, dy, nodata, keys };
constexpr std::array<std::string_view, keys> key_names = {
    "ncols", "nrows", "xllcorner", "xllcenter", "yllcorner", "yllcenter", "cellsize", "dx", "dy", "NODATA_value"};

bool same_name(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

struct HeaderValue {
  bool given = false;
  std::size_t line = 0, column = 0;  // of the value
  double value = 0.0;
};
using Header = std::array<HeaderValue, keys>;

// A count (ncols, nrows): a whole number >= 1 below 2^31.
double read_count(GridLexer& lx, std::string_view tok, std::string_view name) {
  std::uint64_t v = 0;
  const auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (tok.empty() || tok[0] < '0' || tok[0] > '9' || ec != std::errc() || ptr != tok.data() + tok.size())
    lx.fail("expected a whole number >= 1 for " + std::string(name) + ", got '" + printable(tok) + "'");
  if (v == 0) lx.fail(std::string(name) + " must be at least 1");
  if (v >= (std::uint64_t{1} << 31)) lx.fail(std::string(name) + " is too large: '" + printable(tok) + "'");
  return static_cast<double>(v);
}

double read_header_real(GridLexer& lx, std::string_view tok, Key key) {
  const std::string name(key_names[key]);
  bool out_of_range = false;
  const std::optional<double> v = parse_real(tok, &out_of_range);
  if (out_of_range) lx.fail(name + " is out of the range of a double: '" + printable(tok) + "'");
  if (!v) lx.fail("expected a number for " + name + ", got '" + printable(tok) + "'");
  if (key == nodata) return *v;  // NaN is a NODATA value some writers use
  if (!std::isfinite(*v)) lx.fail(name + " is not finite: '" + printable(tok) + "'");
  if ((key == cellsize || key == dx || key == dy) && !(*v > 0.0))
    lx.fail(name + " must be > 0, got '" + printable(tok) + "'");
  return *v;
}

// "key value" pairs up to the first token that is a number (the first value).
Header read_header(GridLexer& lx) {
  Header h;
  for (;;) {
    const std::string_view tok = lx.peek();
    if (tok.empty() || parse_real(tok)) return h;
    lx.next();
    std::size_t key = 0;
    while (key < keys && !same_name(tok, key_names[key])) ++key;
    if (key == keys)
      lx.fail("unknown header key '" + printable(tok) +
              "' (expected ncols, nrows, xllcorner or xllcenter, yllcorner or yllcenter, cellsize or dx and dy, "
              "NODATA_value)");
    if (h[key].given)
      lx.fail("header key " + std::string(key_names[key]) + " is repeated (first on line " +
              std::to_string(h[key].line) + ")");
    const std::string_view value = lx.next();
    if (value.empty()) lx.fail_at_end("expected the value of " + std::string(key_names[key]));
    h[key].given = true;
    h[key].line = lx.line();
    h[key].column = lx.column();
    h[key].value = key == ncols || key == nrows ? read_count(lx, value, key_names[key])
                                                : read_header_real(lx, value, static_cast<Key>(key));
  }
}

// Where the header ends: at the first value, or at the end of the text.
[[noreturn]] void fail_after_header(GridLexer& lx, const std::string& message) {
  if (lx.peek().empty()) lx.fail_at_end(message);
  lx.next();
  lx.fail(message);
}

// One of two keys that say the same thing (xllcorner or xllcenter): the
// centre of the first cell along that axis.
double origin_of(GridLexer& lx, const Header& h, Key corner, Key centre, double cell) {
  const std::string a(key_names[corner]), b(key_names[centre]);
  if (h[corner].given && h[centre].given)
    lx.fail_at(h[centre].line, h[centre].column, b + " and " + a + " both given: the origin is one or the other");
  if (!h[corner].given && !h[centre].given) fail_after_header(lx, "expected the header key " + a + " or " + b);
  return h[corner].given ? h[corner].value + 0.5 * cell : h[centre].value;
}

void check_spacing(GridLexer& lx, const Header& h) {
  if (h[cellsize].given && (h[dx].given || h[dy].given)) {
    const Key other = h[dx].given ? dx : dy;
    lx.fail_at(h[other].line, h[other].column,
               std::string(key_names[other]) + " and cellsize both given: the spacing is one or the other");
  }
  if (h[dx].given != h[dy].given) {
    const Key given = h[dx].given ? dx : dy;
    lx.fail_at(h[given].line, h[given].column,
               std::string(key_names[given]) + " needs " + (given == dx ? "dy" : "dx") +
                   " beside it (or cellsize alone)");
  }
  if (!h[cellsize].given && !h[dx].given) fail_after_header(lx, "expected the header key cellsize (or dx and dy)");
}

// The grid's frame from the header (no values yet), every check that needs
// no value done: the keys there, one of each kind, the extent finite.
DepthGrid grid_frame(GridLexer& lx, const Header& h) {
  for (const Key key : {ncols, nrows})
    if (!h[key].given) fail_after_header(lx, "expected the header key " + std::string(key_names[key]));
  check_spacing(lx, h);
  DepthGrid g;
  g.cols = static_cast<std::size_t>(h[ncols].value);
  g.rows = static_cast<std::size_t>(h[nrows].value);
  g.dx = h[cellsize].given ? h[cellsize].value : h[dx].value;
  g.dy = h[cellsize].given ? h[cellsize].value : h[dy].value;
  g.x0 = origin_of(lx, h, xllcorner, xllcenter, g.dx);
  g.y0 = origin_of(lx, h, yllcorner, yllcenter, g.dy);
  if (h[xllcorner].given != h[yllcorner].given) {
    const Key y = h[yllcenter].given ? yllcenter : yllcorner;
    lx.fail_at(h[y].line, h[y].column,
               std::string(key_names[y]) + " with " + (y == yllcenter ? "xllcorner" : "xllcenter") +
                   ": the origin must be the lower left corner in both x and y, or the centre in both");
  }
  // Every coordinate of the grid (corners and centres) and its width must
  // be finite, so that the interpolation's arithmetic never overflows.
  const double width = static_cast<double>(g.cols) * g.dx, height = static_cast<double>(g.rows) * g.dy;
  const auto finite = [](double a, double b) { return std::isfinite(a) && std::isfinite(b); };
  const Key x = h[xllcorner].given ? xllcorner : xllcenter, y = h[yllcorner].given ? yllcorner : yllcenter;
  if (!finite(width, g.x0 - g.dx) || !std::isfinite(g.x0 + width))
    lx.fail_at(h[x].line, h[x].column,
               "the grid's x extent (ncols times the cell width from the origin) is not finite");
  if (!finite(height, g.y0 - g.dy) || !std::isfinite(g.y0 + height))
    lx.fail_at(h[y].line, h[y].column,
               "the grid's y extent (nrows times the cell height from the origin) is not finite");
  g.has_nodata = true;  // Esri's default NODATA value, -9999, when none is given
  g.nodata = h[nodata].given ? h[nodata].value : -9999.0;
  return g;
}

// cols*rows values need at least 2*cols*rows - 1 bytes (a digit and a
// separator each): a header that lies about its sizes fails before any
// allocation. The cell indices of the interpolant are 32-bit.
void check_count_fits(GridLexer& lx, const Header& h, const DepthGrid& g) {
  const std::uint64_t n = std::uint64_t{g.cols} * g.rows;  // < 2^62
  const std::uint64_t avail = std::uint64_t{lx.remaining_bytes()} + 1;
  if (n > avail / 2)
    lx.fail_at(h[nrows].line, h[nrows].column,
               "the header declares " + std::to_string(g.cols) + " x " + std::to_string(g.rows) + " = " +
                   std::to_string(n) + " values, but the remaining " + std::to_string(avail - 1) +
                   " bytes of the file cannot hold them");
  if (n >= std::numeric_limits<std::uint32_t>::max())
    lx.fail_at(h[nrows].line, h[nrows].column, "the grid has more than 2^32 - 2 cells");
}

// The first data line that does not hold exactly ncols values: a count
// mismatch is usually a row too short or too long, and that line says where.
struct RowLayout {
  std::size_t line = 0, count = 0;          // the line being counted
  std::size_t odd_line = 0, odd_count = 0;  // the first line of another count
  void add(std::size_t at, std::size_t cols) {
    if (at != line) close(cols), line = at, count = 0;
    ++count;
  }
  void close(std::size_t cols) {
    if (odd_line == 0 && line != 0 && count != cols) odd_line = line, odd_count = count;
  }
  std::string hint(std::size_t cols) {
    close(cols);
    if (odd_line == 0) return "";
    return " (line " + std::to_string(odd_line) + " holds " + std::to_string(odd_count) + " values, not ncols " +
           std::to_string(cols) + ")";
  }
};

std::string cell_name(std::size_t k, std::size_t cols) {
  return "value " + std::to_string(k + 1) + " (row " + std::to_string(k / cols + 1) + " from the top, column " +
         std::to_string(k % cols + 1) + ")";
}

// The values, north row first in the text, south row first in the grid.
void read_values(GridLexer& lx, DepthGrid& g) {
  const std::size_t n = g.cols * g.rows;
  g.values.resize(n);
  const bool nan_nodata = std::isnan(g.nodata);
  RowLayout layout;
  std::size_t row = g.rows - 1, col = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::string_view tok = lx.next();
    if (tok.empty())
      lx.fail_at_end("expected " + cell_name(k, g.cols) + " of " + std::to_string(n) + layout.hint(g.cols));
    layout.add(lx.line(), g.cols);
    bool out_of_range = false;
    const std::optional<double> v = parse_real(tok, &out_of_range);
    if (out_of_range) lx.fail(cell_name(k, g.cols) + " is out of the range of a double: '" + printable(tok) + "'");
    if (!v) lx.fail("expected a number for " + cell_name(k, g.cols) + ", got '" + printable(tok) + "'");
    if (!std::isfinite(*v) && !(*v == g.nodata || (nan_nodata && std::isnan(*v))))
      lx.fail(cell_name(k, g.cols) + " is not finite (and not the NODATA value): '" + printable(tok) + "'");
    g.values[row * g.cols + col] = *v;
    if (++col == g.cols) col = 0, --row;
  }
  const std::string_view extra = lx.next();
  if (extra.empty()) return;
  layout.add(lx.line(), g.cols);
  lx.fail("unexpected text after the last of the " + std::to_string(n) + " values: '" + printable(extra) + "'" +
          layout.hint(g.cols));
}

}  // namespace

DepthGrid parse_esri_ascii_grid(std::string_view text, const std::string& path) {
  GridLexer lx(without_bom(text), path);
  const Header header = read_header(lx);
  DepthGrid grid = grid_frame(lx, header);
  check_count_fits(lx, header, grid);
  GridLexer first = lx;  // where the values start, for the message of a grid without depth
  read_values(lx, grid);
  for (std::size_t k = 0; k < grid.values.size(); ++k)
    if (grid.has_value(k)) return grid;
  first.next();
  first.fail("every value is the NODATA value " + number_text(grid.nodata) + ": the grid holds no depth");
}

namespace {

// The x y z scatter: one point a line, fields separated by whitespace or
// one comma, '#' comments, blank lines, an optional header line of names.
class XyzReader {
public:
  XyzReader(std::string_view text, std::string path) : text_(text), path_(std::move(path)) {}

  // Moves to the next line holding a field and splits it; false at the end.
  bool next_line() {
    while (next_ < text_.size()) {
      ++line_;
      begin_ = next_;
      std::size_t end = text_.find('\n', next_);
      if (end == std::string_view::npos) end = text_.size();
      next_ = end < text_.size() ? end + 1 : end;
      const std::size_t hash = text_.substr(begin_, end - begin_).find('#');
      const std::string_view line = text_.substr(begin_, hash == std::string_view::npos ? end - begin_ : hash);
      if (split(line) > 0) return true;
    }
    return false;
  }

  // The current line's fields as numbers, or nullopt when it is a header of
  // three names (allowed on the first line with fields only).
  std::optional<ValuedPoint> point(bool header_allowed) const {
    static constexpr const char* names[3] = {"x", "y", "z"};
    if (count_ < 3) fail(line_length_ + 1, std::string("missing ") + names[count_] + " (a line holds x y z)");
    if (header_allowed &&
        std::none_of(fields_.begin(), fields_.end(), [](const Field& f) { return parse_real(f.text); }))
      return std::nullopt;
    double v[3];
    for (int i = 0; i < 3; ++i) {
      const Field& f = fields_[i];
      bool out_of_range = false;
      const std::optional<double> r = parse_real(f.text, &out_of_range);
      if (out_of_range)
        fail(f.column, std::string(names[i]) + " is out of the range of a double: '" + printable(f.text) + "'");
      if (!r) fail(f.column, std::string("expected a number for ") + names[i] + ", got '" + printable(f.text) + "'");
      if (!std::isfinite(*r)) fail(f.column, std::string(names[i]) + " is not finite: '" + printable(f.text) + "'");
      // The exact range of the predicates that triangulate the points, as validate() keeps it.
      if (i < 2 && !detail::in_exact_range(*r))
        fail(f.column,
             std::string(names[i]) + " " + printable(f.text) +
                 " is outside the supported range: a coordinate must be 0 or of magnitude within [1e-40, 1e70]");
      v[i] = *r;
    }
    return ValuedPoint{{v[0], v[1]}, v[2]};
  }

  std::size_t line() const noexcept { return line_; }
  [[noreturn]] void fail(std::size_t column, const std::string& message) const {
    throw ParseError(path_, line_, column, message);
  }
  [[noreturn]] void fail_at(std::size_t line, const std::string& message) const {
    throw ParseError(path_, line, 1, message);
  }

private:
  struct Field {
    std::string_view text;
    std::size_t column = 0;
  };
  // Splits `line` into its fields (at most three); returns their count.
  std::size_t split(std::string_view line) {
    count_ = 0;
    line_length_ = line.size();
    std::size_t pos = 0;
    const auto skip = [&] {
      while (pos < line.size() && is_space(line[pos])) ++pos;
    };
    skip();
    while (pos < line.size()) {
      if (line[pos] == ',') fail(pos + 1, "empty field before ','");
      const std::size_t start = pos;
      while (pos < line.size() && !is_space(line[pos]) && line[pos] != ',') ++pos;
      if (count_ == 3) fail(start + 1, "unexpected extra field after z (a line holds x y z)");
      fields_[count_++] = {line.substr(start, pos - start), start + 1};
      skip();
      if (pos < line.size() && line[pos] == ',') {
        ++pos;
        skip();
        if (pos == line.size()) fail(pos + 1, "empty field after ','");
      }
    }
    return count_;
  }

  std::string_view text_;
  std::string path_;
  std::size_t next_ = 0, begin_ = 0, line_ = 0, line_length_ = 0;
  std::array<Field, 3> fields_{};
  std::size_t count_ = 0;
};

// A point given twice: the repeat on the earliest line is reported, with
// the line of the first.
void check_distinct(const XyzReader& reader, std::span<const ValuedPoint> points, std::span<const std::size_t> lines) {
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Point p = points[a].at, q = points[b].at;
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  std::size_t repeat = points.size(), first = 0;
  for (std::size_t k = 1, group = 0; k < order.size(); ++k) {
    if (!(points[order[k]].at == points[order[group]].at)) {
      group = k;
      continue;
    }
    if (repeat == points.size() || order[k] < repeat) repeat = order[k], first = order[group];
  }
  if (repeat == points.size()) return;
  const Point p = points[repeat].at;
  reader.fail_at(lines[repeat], "the point (" + number_text(p.x) + ", " + number_text(p.y) +
                                    ") is given again (first on line " + std::to_string(lines[first]) + ")");
}

}  // namespace

std::vector<ValuedPoint> parse_xyz(std::string_view text, const std::string& path) {
  XyzReader reader(without_bom(text), path);
  std::vector<ValuedPoint> points;
  std::vector<std::size_t> lines;
  for (bool first = true; reader.next_line(); first = false) {
    const std::optional<ValuedPoint> p = reader.point(first);
    if (!p) continue;
    if (points.size() + 1 >= std::numeric_limits<std::uint32_t>::max()) reader.fail(1, "more than 2^32 - 2 points");
    points.push_back(*p);
    lines.push_back(reader.line());
  }
  if (points.size() < 3)
    throw ParseError(path, std::max<std::size_t>(reader.line(), 1), 1,
                     "a scatter needs at least 3 points, the file holds " + std::to_string(points.size()));
  check_distinct(reader, points, lines);
  // Distinct points: the first two make a line, and some point must be off it.
  for (std::size_t k = 2; k < points.size(); ++k)
    if (orient2d(points[0].at, points[1].at, points[k].at) != 0.0) return points;
  reader.fail_at(lines[0], "the " + std::to_string(points.size()) +
                               " points all lie on one line: a scatter needs 3 points not on one line");
}

namespace {

// One read of the whole file: the parsers then work on memory, and the file
// size bounds every count before allocation. A directory opens, and says a
// size it does not have: it is refused first; a file larger than memory is
// a file that cannot be read.
void read_whole_file(const std::string& path, std::string& text) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputFileError(path + ": cannot read file (it is a directory)");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
  if (size < 0) throw InputFileError(path + ": cannot read file");
  try {
    text.resize(static_cast<std::size_t>(size));
  } catch (const std::bad_alloc&) {
    throw InputFileError(path + ": cannot read file (" + std::to_string(size) + " bytes do not fit in memory)");
  }
  in.seekg(0);
  if (size > 0 && !in.read(text.data(), size)) throw InputFileError(path + ": cannot read file");
}

bool is_esri_grid_path(const std::string& path) {
  if (path.size() < 4) return false;
  return same_name(std::string_view(path).substr(path.size() - 4), ".asc");
}

}  // namespace

Bathymetry read_bathymetry(const std::string& path, bool positive_up) {
  std::string text;
  read_whole_file(path, text);
  Bathymetry out;
  if (is_esri_grid_path(path)) {
    DepthGrid grid = parse_esri_ascii_grid(text, path);
    if (positive_up) {
      for (double& v : grid.values) v = -v;
      grid.nodata = -grid.nodata;  // the same cells stay without depth
    }
    out.data = std::move(grid);
  } else {
    std::vector<ValuedPoint> points = parse_xyz(text, path);
    if (positive_up)
      for (ValuedPoint& p : points) p.value = -p.value;
    out.data = std::move(points);
  }
  return out;
}

}  // namespace madd
