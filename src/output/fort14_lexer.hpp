#pragma once
// Record-per-line tokenizer for fort.14 text (src/output/fort14_reader.cpp).
// ADCIRC reads each record with a Fortran list-directed READ, which takes the
// values it asks for from the line and ignores the rest: real files put
// their comments there ("3 4 ! NE NP", "2 = Number of open boundaries"). The
// lexer takes the same view, more strictly: after a record's values the rest
// of the line must be empty or start with a word that is not a number (an
// extra number usually means a count and the lines disagree). Fields are
// separated by blanks and tabs (CRLF accepted); blank lines are skipped;
// every error is a ParseError at the token's line and column.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "madd/error.hpp"

namespace madd::detail {

class Fort14Lexer {
public:
  Fort14Lexer(std::string_view text, std::string path) : text_(text), path_(std::move(path)) {}

  std::size_t line() const noexcept { return line_; }

  // The first line, whole, without its line break: AGRID (any text, even none).
  std::string title() {
    if (text_.empty()) fail_at_end("empty file: expected the grid title (AGRID) on the first line");
    advance();
    std::string_view title = text_.substr(line_begin_, line_end_ - line_begin_);
    if (!title.empty() && title.back() == '\r') title.remove_suffix(1);
    return std::string(title);
  }

  // Moves to the next line that holds a field; false at the end of the text.
  bool next_line() {
    while (next_ < text_.size()) {
      advance();
      skip_blanks();
      if (cursor_ < line_end_) return true;
    }
    line_begin_ = cursor_ = line_end_ = text_.size();
    return false;
  }

  // The next record's line, or a ParseError saying what was expected there.
  void require_line(const std::string& what) {
    if (!next_line()) fail_at_end("unexpected end of file: expected " + what);
  }

  // A non-negative integer below 2^32 - 1 (counts; ids are read with id()).
  std::uint32_t count(const char* what) {
    const std::int64_t v = integer(what);
    if (v < 0) fail_token(std::string(what) + " must not be negative, got " + std::to_string(v));
    if (v >= std::numeric_limits<std::uint32_t>::max()) fail_token(std::string(what) + " is too large");
    return static_cast<std::uint32_t>(v);
  }

  // An integer of at most 18 digits with an optional sign.
  std::int64_t integer(const char* what) {
    std::string_view tok = token(what);
    if (tok.size() > 1 && tok[0] == '+' && tok[1] != '-') tok.remove_prefix(1);
    std::int64_t v = 0;
    const auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec != std::errc() || ptr != tok.data() + tok.size() || tok.empty() || tok.size() > 19)
      fail_token(std::string("expected an integer ") + what + ", got '" + printable(last_) + "'");
    return v;
  }

  // A finite real; Fortran's 'D' exponent ("1.5D+01") is read as 'E'.
  double real(const char* what) {
    const std::string_view tok = token(what);
    double v = 0.0;
    const Number n = parse_real(tok, v);
    if (n == Number::out_of_range)
      fail_token(std::string(what) + " is out of the range of a double: '" + printable(tok) + "'");
    if (n != Number::ok) fail_token(std::string("expected a number for ") + what + ", got '" + printable(tok) + "'");
    if (!std::isfinite(v)) fail_token(std::string(what) + " is not finite: '" + printable(tok) + "'");
    return v;
  }

  // The end of a record: nothing more on the line, or a comment (the rest of
  // the line, its first word not a number).
  void end_of_record(const char* what) {
    if (cursor_ >= line_end_) return;
    const std::size_t at = cursor_;
    double ignored = 0.0;
    if (parse_real(token(what), ignored) == Number::not_a_number) return;
    fail(at, std::string("unexpected extra field after ") + what +
                 " (a comment must start with a word that is not a number; do the counts match the lines?)");
  }

  // Only blank lines left.
  void expect_end(const char* after) {
    if (next_line()) fail(cursor_, std::string("unexpected text after ") + after);
  }

  // Bytes after the current line, to bound counts before allocating.
  std::size_t remaining_bytes() const noexcept { return text_.size() - next_; }

  std::size_t token_column() const noexcept { return token_begin_ - line_begin_ + 1; }
  [[noreturn]] void fail_token(const std::string& message) const { fail(token_begin_, message); }
  [[noreturn]] void fail_column(std::size_t column, const std::string& message) const {
    throw ParseError(path_, line_, column, message);
  }
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw ParseError(path_, line_, offset - line_begin_ + 1, message);
  }
  // Just past the last byte: the line after a final line break.
  [[noreturn]] void fail_at_end(const std::string& message) const {
    const std::size_t lines = static_cast<std::size_t>(std::count(text_.begin(), text_.end(), '\n'));
    const std::size_t last = text_.rfind('\n');
    const std::size_t begin = last == std::string_view::npos ? 0 : last + 1;
    throw ParseError(path_, lines + 1, text_.size() - begin + 1, message);
  }

private:
  enum class Number { ok, out_of_range, not_a_number };

  static bool is_blank(char c) noexcept { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
  void skip_blanks() noexcept {
    while (cursor_ < line_end_ && is_blank(text_[cursor_])) ++cursor_;
  }
  void advance() noexcept {
    ++line_;
    line_begin_ = cursor_ = next_;
    const void* nl = std::memchr(text_.data() + next_, '\n', text_.size() - next_);
    line_end_ = nl != nullptr ? static_cast<std::size_t>(static_cast<const char*>(nl) - text_.data()) : text_.size();
    next_ = line_end_ < text_.size() ? line_end_ + 1 : line_end_;
  }

  std::string_view token(const char* what) {
    if (cursor_ >= line_end_) fail(cursor_, std::string("missing ") + what);
    token_begin_ = cursor_;
    while (cursor_ < line_end_ && !is_blank(text_[cursor_])) ++cursor_;
    last_ = text_.substr(token_begin_, cursor_ - token_begin_);
    skip_blanks();
    return last_;
  }

  // A whole-token real, the way a Fortran list-directed read takes one: an
  // optional sign, digits with an optional point, an exponent with E or D.
  static Number parse_real(std::string_view tok, double& v) {
    if (tok.empty() || tok.size() > 64) return Number::not_a_number;
    const char first = tok[0];
    if (!(first == '+' || first == '-' || first == '.' || (first >= '0' && first <= '9'))) return Number::not_a_number;
    char buffer[65];
    std::size_t n = 0;
    for (std::size_t i = first == '+' ? 1 : 0; i < tok.size(); ++i)
      buffer[n++] = tok[i] == 'd' || tok[i] == 'D' ? 'e' : tok[i];
    if (n == 0 || buffer[0] == '+' || (n > 1 && buffer[0] == '-' && buffer[1] == '+')) return Number::not_a_number;
    const auto [ptr, ec] = std::from_chars(buffer, buffer + n, v, std::chars_format::general);
    if (ec == std::errc::result_out_of_range && ptr == buffer + n) return Number::out_of_range;
    if (ec != std::errc() || ptr != buffer + n) return Number::not_a_number;
    return Number::ok;
  }

  // Tokens are echoed in messages: short and printable.
  static std::string printable(std::string_view tok) {
    std::string out;
    for (const char c : tok.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
    if (tok.size() > 40) out += "...";
    return out;
  }

  std::string_view text_;
  std::string path_;
  std::string_view last_;
  std::size_t next_ = 0;        // start of the line after the current one
  std::size_t line_begin_ = 0;  // start of the current line
  std::size_t line_end_ = 0;    // end of the current line (its '\n' or the text's end)
  std::size_t cursor_ = 0;
  std::size_t token_begin_ = 0;
  std::size_t line_ = 0;
};

}  // namespace madd::detail
