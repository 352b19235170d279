#pragma once
// Line-oriented tokenizer for Triangle's .poly/.node text (internal).
// Triangle reads one line at a time, skips blank lines and '#' comments, and
// pulls whitespace-separated fields from the line. We do the same over the
// whole file held in memory, with std::from_chars for speed, and keep the
// line and column of every token for ParseError.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "madd/error.hpp"

namespace madd::detail {

class PolyLexer {
public:
  PolyLexer(std::string_view text, std::string path) : text_(text), path_(std::move(path)) {}

  const std::string& path() const noexcept { return path_; }
  std::uint32_t line() const noexcept { return line_; }

  // Moves to the next line holding a token; false at the end of the text.
  bool next_line() {
    while (next_ < text_.size()) {
      ++line_;
      line_begin_ = next_;
      std::size_t end = text_.find('\n', next_);
      if (end == std::string_view::npos) end = text_.size();
      next_ = end < text_.size() ? end + 1 : end;
      const std::size_t hash = text_.substr(line_begin_, end - line_begin_).find('#');
      line_end_ = hash == std::string_view::npos ? end : line_begin_ + hash;
      cursor_ = line_begin_;
      skip_space();
      if (cursor_ < line_end_) return true;
    }
    line_begin_ = cursor_ = line_end_ = text_.size();
    return false;
  }

  // Like next_line, but a missing line is a truncated file.
  void require_line(const char* what) {
    if (!next_line()) fail_at_end(std::string("unexpected end of file: expected ") + what);
  }
  // Item `index` of `count` in a section; the message is built only on failure.
  void require_item(const char* what, std::int64_t index, std::uint32_t count) {
    if (!next_line())
      fail_at_end("unexpected end of file: expected " + std::string(what) + " " + std::to_string(index) + " of " +
                  std::to_string(count));
  }

  bool has_token() const noexcept { return cursor_ < line_end_; }

  // The next token of the current line, or a ParseError naming `what`.
  std::string_view token(const char* what) {
    if (!has_token()) fail(cursor_, std::string("missing ") + what);
    token_begin_ = cursor_;
    while (cursor_ < line_end_ && !is_space(text_[cursor_])) ++cursor_;
    std::string_view tok = text_.substr(token_begin_, cursor_ - token_begin_);
    skip_space();
    return tok;
  }

  // Rejects extra fields. Triangle silently ignores them, but in practice an
  // extra field means the header's attribute or marker count disagrees with
  // the lines, so madd reports it instead of guessing (docs/formats.md, "Bad input").
  void end_of_line(const char* what) {
    if (has_token())
      fail(cursor_, std::string("unexpected extra field after ") + what +
                        " (do the header counts match the lines that follow?)");
  }

  // Bytes left after the current line, to bound counts before allocating.
  std::size_t remaining_bytes() const noexcept { return text_.size() - next_; }

  // Non-negative count below 2^32 - 1 (32-bit indices).
  std::uint32_t count(const char* what) {
    std::string_view tok = token(what);
    std::uint64_t v = 0;
    if (!parse_integer(tok, v))
      fail(token_begin_, std::string("expected a non-negative integer ") + what + ", got '" + printable(tok) + "'");
    if (v >= std::numeric_limits<std::uint32_t>::max()) fail(token_begin_, std::string(what) + " is too large");
    return static_cast<std::uint32_t>(v);
  }

  // An id or endpoint, kept signed so that out-of-range values can be reported.
  std::int64_t id(const char* what) {
    std::string_view tok = token(what);
    std::string_view digits = tok;
    bool negative = false;
    if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) {
      negative = digits[0] == '-';
      digits.remove_prefix(1);
    }
    std::uint64_t v = 0;
    if (!parse_integer(digits, v) || v > (std::uint64_t{1} << 62))
      fail(token_begin_, std::string("expected an integer ") + what + ", got '" + printable(tok) + "'");
    return negative ? -static_cast<std::int64_t>(v) : static_cast<std::int64_t>(v);
  }

  int marker(const char* what) {
    std::string_view tok = token(what);
    if (!tok.empty() && tok[0] == '+') tok.remove_prefix(1);
    int v = 0;
    auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec != std::errc() || ptr != tok.data() + tok.size() || tok.empty())
      fail(token_begin_, std::string("expected an integer ") + what + ", got '" + printable(tok) + "'");
    return v;
  }

  // A finite real number (coordinates): NaN and infinities are errors.
  double coordinate(const char* what) {
    double v = real(what);
    if (!std::isfinite(v)) fail(token_begin_, std::string(what) + " is not finite: '" + printable(last()) + "'");
    return v;
  }

  // Any real number that from_chars accepts, including nan and inf (attributes:
  // non-finite weights are checked by validate() only when they matter).
  double real(const char* what) {
    std::string_view tok = token(what);
    std::string_view num = tok;
    if (num.size() > 1 && num[0] == '+' && num[1] != '-') num.remove_prefix(1);
    double v = 0.0;
    auto [ptr, ec] = std::from_chars(num.data(), num.data() + num.size(), v);
    if (ec == std::errc::result_out_of_range)
      fail(token_begin_, std::string(what) + " is out of the range of a double: '" + printable(tok) + "'");
    if (ec != std::errc() || ptr != num.data() + num.size() || num.empty())
      fail(token_begin_, std::string("expected a number for ") + what + ", got '" + printable(tok) + "'");
    return v;
  }

  // Column (1-based) of the last token read.
  std::size_t token_column() const noexcept { return token_begin_ - line_begin_ + 1; }

  [[noreturn]] void fail_token(const std::string& message) const { fail(token_begin_, message); }
  [[noreturn]] void fail_column(std::size_t column, const std::string& message) const {
    throw ParseError(path_, line_, column, message);
  }
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw ParseError(path_, line_, offset - line_begin_ + 1, message);
  }
  [[noreturn]] void fail_at_end(const std::string& message) const {
    // Point just past the last byte: the line after a final newline.
    std::size_t line = 1;
    std::size_t begin = 0;
    for (std::size_t i = 0; i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        begin = i + 1;
      }
    }
    throw ParseError(path_, line, text_.size() - begin + 1, message);
  }

private:
  static bool is_space(char c) noexcept { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
  void skip_space() noexcept {
    while (cursor_ < line_end_ && is_space(text_[cursor_])) ++cursor_;
  }
  std::string_view last() const noexcept {
    std::size_t end = token_begin_;
    while (end < line_end_ && !is_space(text_[end])) ++end;
    return text_.substr(token_begin_, end - token_begin_);
  }
  static bool parse_integer(std::string_view tok, std::uint64_t& v) noexcept {
    if (tok.empty() || tok[0] < '0' || tok[0] > '9') return false;
    auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    return ec == std::errc() && ptr == tok.data() + tok.size();
  }
  // Tokens are echoed in messages: keep them short and printable.
  static std::string printable(std::string_view tok) {
    std::string out;
    for (char c : tok.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
    if (tok.size() > 40) out += "...";
    return out;
  }

  std::string_view text_;
  std::string path_;
  std::size_t next_ = 0;        // start of the line after the current one
  std::size_t line_begin_ = 0;  // start of the current line
  std::size_t line_end_ = 0;    // end of the current line's fields (before '#')
  std::size_t cursor_ = 0;
  std::size_t token_begin_ = 0;
  std::uint32_t line_ = 0;
};

}  // namespace madd::detail
