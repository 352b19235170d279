#include "gis/json_lexer.hpp"

#include <limits>

#include "madd/error.hpp"

namespace madd::detail {

namespace {

bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

// A byte as a message shows it: the character when printable ASCII.
std::string byte_text(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
  static const char digits[] = "0123456789abcdef";
  return std::string("byte 0x") + digits[u >> 4] + digits[u & 15];
}

void append_utf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xc0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3f));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xe0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (code & 0x3f));
  } else {
    out += static_cast<char>(0xf0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3f));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (code & 0x3f));
  }
}

}  // namespace

const char* json_type_name(JsonType type) noexcept {
  switch (type) {
  case JsonType::object:
    return "an object";
  case JsonType::array:
    return "an array";
  case JsonType::string:
    return "a string";
  case JsonType::number:
    return "a number";
  case JsonType::boolean:
    return "a boolean";
  case JsonType::null:
    return "null";
  }
  return "a value";
}

JsonLexer::JsonLexer(std::string_view text, std::string path) : text_(text), path_(std::move(path)) {
  if (text_.substr(0, 3) == "\xef\xbb\xbf") at_ = line_begin_ = 3;
}

void JsonLexer::NameSet::clear() {
  used_ = 0;
  if (!large_.empty()) large_ = {};  // a fresh set: clearing a big one would cost its bucket count every time
}

bool JsonLexer::NameSet::insert(const std::string& name) {
  if (!large_.empty()) return large_.insert(name).second;
  for (std::size_t i = 0; i < used_; ++i)
    if (small_[i] == name) return false;
  if (used_ < small_limit) {
    if (small_.size() == used_) small_.emplace_back();
    small_[used_++].assign(name);  // reuses the string's storage from earlier objects
    return true;
  }
  large_.insert(small_.begin(), small_.begin() + static_cast<std::ptrdiff_t>(used_));
  return large_.insert(name).second;
}

void JsonLexer::open(char bracket, bool object) {
  skip_space();
  if (at_ >= text_.size() || text_[at_] != bracket) fail_expected(object ? "'{'" : "'['");
  if (depth_ == max_depth) fail_at(at_, "nesting deeper than " + std::to_string(max_depth) + " levels");
  ++at_;
  pending_ = false;
  Level& level = levels_[depth_++];
  level.object = object;
  level.first = true;
  if (object) level.names.clear();
}

bool JsonLexer::next_member(std::string& name) {
  skip_space();
  Level& level = levels_[depth_ - 1];
  if (at_ < text_.size() && text_[at_] == '}') {
    ++at_;
    --depth_;
    pending_ = false;
    return false;
  }
  if (!level.first) {
    if (at_ >= text_.size() || text_[at_] != ',') fail_expected("',' or '}'");
    ++at_;
    skip_space();
  }
  level.first = false;
  if (at_ >= text_.size() || text_[at_] != '"') fail_expected("a member name (a string)");
  const std::size_t begin = at_;
  name.clear();
  scan_string(&name);
  if (!level.names.insert(name)) fail_at(begin, "repeated member name \"" + name + "\" in one object");
  skip_space();
  if (at_ >= text_.size() || text_[at_] != ':') fail_expected("':' after the member name");
  ++at_;
  pending_ = true;
  return true;
}

// -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?, RFC 8259 section 6.
void JsonLexer::scan_number() {
  const std::size_t n = text_.size();
  if (at_ < n && text_[at_] == '-') ++at_;
  if (at_ >= n || !is_digit(text_[at_])) fail_expected("a digit");
  if (text_[at_] == '0') {
    ++at_;
    if (at_ < n && is_digit(text_[at_])) fail_at(at_ - 1, "a number may not start with the digit 0 followed by digits");
  } else {
    while (at_ < n && is_digit(text_[at_])) ++at_;
  }
  if (at_ < n && text_[at_] == '.') {
    ++at_;
    if (at_ >= n || !is_digit(text_[at_])) fail_expected("a digit after the decimal point");
    while (at_ < n && is_digit(text_[at_])) ++at_;
  }
  if (at_ < n && (text_[at_] == 'e' || text_[at_] == 'E')) {
    ++at_;
    if (at_ < n && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
    if (at_ >= n || !is_digit(text_[at_])) fail_expected("a digit in the exponent");
    while (at_ < n && is_digit(text_[at_])) ++at_;
  }
}

// from_chars says "out of range" both for a magnitude too large for a
// double and for one too small; which it was follows from the number's
// decimal order (the power of ten of its leading digit), far from 0 either way.
double JsonLexer::out_of_range_value(std::string_view number) const {
  const bool negative = number[0] == '-';
  std::size_t i = negative ? 1 : 0;
  std::int64_t order = 0;  // decimal order of the leading nonzero digit, plus one
  bool seen_nonzero = false;
  for (; i < number.size() && is_digit(number[i]); ++i) {
    if (number[i] != '0') seen_nonzero = true;
    if (seen_nonzero) ++order;
  }
  if (i < number.size() && number[i] == '.') {
    for (++i; i < number.size() && is_digit(number[i]); ++i) {
      if (number[i] != '0') seen_nonzero = true;
      if (!seen_nonzero) --order;
    }
  }
  std::int64_t exponent = 0;
  if (i < number.size()) {  // 'e' or 'E'
    ++i;
    const bool negative_exponent = number[i] == '-';
    if (number[i] == '+' || number[i] == '-') ++i;
    for (; i < number.size(); ++i) exponent = std::min<std::int64_t>(exponent * 10 + (number[i] - '0'), 1000000);
    if (negative_exponent) exponent = -exponent;
  }
  const double magnitude = order + exponent > 0 ? std::numeric_limits<double>::infinity() : 0.0;
  return negative ? -magnitude : magnitude;
}

void JsonLexer::string(std::string& out) {
  skip_space();
  if (at_ >= text_.size() || text_[at_] != '"') fail_expected("a string");
  out.clear();
  scan_string(&out);
}

// From the opening quote to past the closing one; unescaped into *out when
// out is not null.
void JsonLexer::scan_string(std::string* out) {
  ++at_;
  const std::size_t n = text_.size();
  while (true) {
    const std::size_t run = at_;
    while (at_ < n) {
      const auto c = static_cast<unsigned char>(text_[at_]);
      if (c == '"' || c == '\\' || c < 0x20 || c >= 0x80) break;
      ++at_;
    }
    if (out) out->append(text_.data() + run, at_ - run);
    if (at_ >= n) fail_at(at_, "unexpected end of text in a string");
    const auto c = static_cast<unsigned char>(text_[at_]);
    if (c == '"') {
      ++at_;
      pending_ = false;
      return;
    }
    if (c == '\\') {
      scan_escape(out);
    } else if (c < 0x20) {
      fail_at(at_, "control character " + byte_text(text_[at_]) + " in a string (write it as an escape)");
    } else {
      const std::size_t begin = at_;
      scan_utf8();
      if (out) out->append(text_.data() + begin, at_ - begin);
    }
  }
}

void JsonLexer::scan_escape(std::string* out) {
  const std::size_t begin = at_++;
  if (at_ >= text_.size()) fail_at(at_, "unexpected end of text in a string escape");
  const char c = text_[at_++];
  char plain = 0;
  switch (c) {
  case '"':
  case '\\':
  case '/':
    plain = c;
    break;
  case 'b':
    plain = '\b';
    break;
  case 'f':
    plain = '\f';
    break;
  case 'n':
    plain = '\n';
    break;
  case 'r':
    plain = '\r';
    break;
  case 't':
    plain = '\t';
    break;
  case 'u': {
    std::uint32_t code = scan_hex4();
    if (code >= 0xdc00 && code <= 0xdfff) fail_at(begin, "unpaired low surrogate in a \\u escape");
    if (code >= 0xd800 && code <= 0xdbff) {
      if (text_.substr(at_, 2) != "\\u") fail_at(begin, "high surrogate not followed by a \\u low surrogate");
      at_ += 2;
      const std::uint32_t low = scan_hex4();
      if (low < 0xdc00 || low > 0xdfff) fail_at(begin, "high surrogate not followed by a \\u low surrogate");
      code = 0x10000 + ((code - 0xd800) << 10) + (low - 0xdc00);
    }
    if (out) append_utf8(*out, code);
    return;
  }
  default:
    fail_at(begin, "invalid escape \\" + std::string(1, c) + " in a string");
  }
  if (out) *out += plain;
}

std::uint32_t JsonLexer::scan_hex4() {
  std::uint32_t code = 0;
  for (int k = 0; k < 4; ++k, ++at_) {
    if (at_ >= text_.size()) fail_at(at_, "unexpected end of text in a \\u escape");
    const char c = text_[at_];
    std::uint32_t digit = 0;
    if (c >= '0' && c <= '9') {
      digit = static_cast<std::uint32_t>(c - '0');
    } else if (c >= 'a' && c <= 'f') {
      digit = static_cast<std::uint32_t>(c - 'a' + 10);
    } else if (c >= 'A' && c <= 'F') {
      digit = static_cast<std::uint32_t>(c - 'A' + 10);
    } else {
      fail_at(at_, "expected 4 hexadecimal digits after \\u, got " + byte_text(c));
    }
    code = code * 16 + digit;
  }
  return code;
}

// One multi-byte UTF-8 character (RFC 3629): no overlong forms, no
// surrogates, nothing beyond U+10FFFF.
void JsonLexer::scan_utf8() {
  const auto lead = static_cast<unsigned char>(text_[at_]);
  std::size_t length = 0;
  unsigned char low = 0x80;
  unsigned char high = 0xbf;  // the range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    if (lead == 0xe0) low = 0xa0;
    if (lead == 0xed) high = 0x9f;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    if (lead == 0xf0) low = 0x90;
    if (lead == 0xf4) high = 0x8f;
  } else {
    fail_at(at_, "invalid UTF-8 in a string (" + byte_text(text_[at_]) + ")");
  }
  for (std::size_t k = 1; k < length; ++k) {
    const std::size_t i = at_ + k;
    if (i >= text_.size()) fail_at(at_, "unexpected end of text in a UTF-8 character");
    const auto c = static_cast<unsigned char>(text_[i]);
    if (c < (k == 1 ? low : 0x80) || c > (k == 1 ? high : 0xbf))
      fail_at(at_, "invalid UTF-8 in a string (" + byte_text(text_[i]) + " after " + byte_text(text_[at_]) + ")");
  }
  at_ += length;
}

void JsonLexer::literal(std::string_view word) {
  if (text_.substr(at_, word.size()) != word) fail_at(at_, "invalid literal: expected '" + std::string(word) + "'");
  at_ += word.size();
  pending_ = false;
}

bool JsonLexer::boolean() {
  skip_space();
  if (at_ < text_.size() && text_[at_] == 't') {
    literal("true");
    return true;
  }
  if (at_ < text_.size() && text_[at_] == 'f') {
    literal("false");
    return false;
  }
  fail_expected("true or false");
}

void JsonLexer::null() {
  skip_space();
  literal("null");
}

// Iterative, over the same levels as the reading functions: the depth limit
// holds and nothing grows with the nesting.
void JsonLexer::skip_value() {
  const std::uint32_t outer = depth_;
  std::string name;
  do {
    if (depth_ > outer) {
      const bool more = levels_[depth_ - 1].object ? next_member(name) : next_element();
      if (!more) continue;
    }
    switch (peek()) {
    case JsonType::object:
      begin_object();
      break;
    case JsonType::array:
      begin_array();
      break;
    case JsonType::string:
      scan_string(nullptr);
      break;
    case JsonType::number:
      scan_number();
      pending_ = false;
      break;
    case JsonType::boolean:
      (void)boolean();
      break;
    case JsonType::null:
      null();
      break;
    }
  } while (depth_ > outer);
}

void JsonLexer::skip_rest() {
  if (pending_) skip_value();
  std::string name;
  while (depth_ > 0) {
    const bool more = levels_[depth_ - 1].object ? next_member(name) : next_element();
    if (more) skip_value();
  }
  finish();
}

void JsonLexer::finish() {
  skip_space();
  if (at_ < text_.size()) fail_at(at_, "unexpected " + byte_text(text_[at_]) + " after the end of the JSON value");
}

void JsonLexer::fail_expected(const char* what) {
  if (at_ >= text_.size()) fail_at(at_, std::string("unexpected end of text: expected ") + what);
  fail_at(at_, std::string("expected ") + what + ", got " + byte_text(text_[at_]));
}

// Only ever called at or after the current line's start.
void JsonLexer::fail_at(std::size_t offset, const std::string& message) const {
  throw ParseError(path_, line_, offset - line_begin_ + 1, message);
}

}  // namespace madd::detail
