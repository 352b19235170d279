#pragma once
// A strict JSON (RFC 8259) pull reader over text held in memory (internal).
//
// The caller walks the text value by value (begin_object / next_member,
// begin_array / next_element, number, string, skip_value) and builds only
// what it needs: the GeoJSON reader streams coordinates straight into
// vectors of points, with no tree of the document. Every malformed byte is a
// ParseError "path:line:column: message" (lines from 1, columns in bytes
// from 1). Strict on purpose:
// - only the RFC's grammar: no comments, no trailing commas, no NaN or
//   Infinity, no leading zeros or '+', no single quotes;
// - strings are valid UTF-8 with no control characters, and escapes are the
//   RFC's (\uXXXX, surrogates in pairs only);
// - member names are distinct within an object (RFC 8259 leaves repeated
//   names to the reader; a repeated "coordinates" or "marker" would be
//   ambiguous, so it is refused, not resolved);
// - nesting deeper than max_depth is refused, so that nothing in the reader
//   or its callers grows with the nesting (skip_value uses no recursion).
// A leading UTF-8 byte order mark is skipped, as RFC 8259 allows.
// Numbers are read by std::from_chars: the nearest double, exactly; a
// magnitude beyond a double's range reads as an infinity (the caller decides
// whether that is an error), one too small for a double as zero.
#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace madd::detail {

enum class JsonType : std::uint8_t { object, array, string, number, boolean, null };

// "an object", "an array", "a string", ... for messages.
const char* json_type_name(JsonType type) noexcept;

// Where a token starts: line from 1, column in bytes from 1.
struct JsonPosition {
  std::size_t line = 1;
  std::size_t column = 1;
};

// A place in the text to come back to: a member whose meaning depends on a
// sibling that comes later (JSON objects are unordered).
struct JsonMark {
  std::size_t offset = 0;
  std::size_t line = 1;
  std::size_t line_begin = 0;
  std::uint32_t depth = 0;
  bool pending = false;
};

class JsonLexer {
public:
  static constexpr std::uint32_t max_depth = 64;

  JsonLexer(std::string_view text, std::string path);

  const std::string& path() const noexcept { return path_; }

  // The type of the next value, without reading it; ParseError if no value
  // starts there.
  JsonType peek() {
    skip_space();
    if (at_ < text_.size()) {
      switch (text_[at_]) {
      case '{':
        return JsonType::object;
      case '[':
        return JsonType::array;
      case '"':
        return JsonType::string;
      case 't':
      case 'f':
        return JsonType::boolean;
      case 'n':
        return JsonType::null;
      default:
        if (text_[at_] == '-' || (text_[at_] >= '0' && text_[at_] <= '9')) return JsonType::number;
      }
    }
    fail_expected("a value");
  }

  // Where the next token starts (after white space).
  JsonPosition position() {
    skip_space();
    return {line_, at_ - line_begin_ + 1};
  }

  // An object: begin_object, then next_member until it returns false (the
  // '}' is read then); after each true, read or skip the member's value.
  void begin_object() { open('{', true); }
  bool next_member(std::string& name);

  // An array: begin_array, then next_element until it returns false (the
  // ']' is read then); after each true, read or skip the element.
  void begin_array() { open('[', false); }
  bool next_element() {
    skip_space();
    Level& level = levels_[depth_ - 1];
    if (at_ < text_.size() && text_[at_] == ']') {
      ++at_;
      --depth_;
      pending_ = false;
      return false;
    }
    if (level.first) {
      level.first = false;
      pending_ = true;
      return true;
    }
    if (at_ < text_.size() && text_[at_] == ',') {
      ++at_;
      pending_ = true;
      return true;
    }
    fail_expected("',' or ']'");
  }

  // A number, the nearest double to it. number_text() is the number as
  // written, for messages.
  double number() {
    skip_space();
    const std::size_t begin = at_;
    scan_number();
    pending_ = false;
    number_text_ = text_.substr(begin, at_ - begin);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(number_text_.data(), number_text_.data() + number_text_.size(), value);
    if (ec == std::errc::result_out_of_range) return out_of_range_value(number_text_);
    if (ec != std::errc() || end != number_text_.data() + number_text_.size()) fail_at(begin, "invalid number");
    return value;
  }
  std::string_view number_text() const noexcept { return number_text_; }

  // A string, unescaped into `out` (UTF-8).
  void string(std::string& out);
  bool boolean();
  void null();

  // Reads the next value whatever it is, checking it, keeping nothing.
  void skip_value();

  // Only white space may follow the top-level value.
  void finish();

  // Reads and checks the rest of the text from wherever the reading
  // stopped: what is left of the value begun or due, of every container
  // open, then finish(). A caller that finds well-formed JSON it cannot
  // accept calls this first, so that malformed JSON anywhere in the text is
  // reported as such, whatever else is wrong with it.
  void skip_rest();

  JsonMark mark() {
    skip_space();
    return {at_, line_, line_begin_, depth_, pending_};
  }
  // Back to a mark of the same reader. The containers open at the mark must
  // be open now (a mark inside an object, restored once that object has been
  // read, may only be used to read the one value there).
  void restore(const JsonMark& m) {
    at_ = m.offset;
    line_ = m.line;
    line_begin_ = m.line_begin;
    depth_ = m.depth;
    pending_ = m.pending;
  }

  [[noreturn]] void fail(const std::string& message) {
    skip_space();
    fail_at(at_, message);
  }

private:
  // Member names already seen in one open object: a short list, and a hash
  // set once the object has many members (so no object costs quadratic time).
  class NameSet {
  public:
    void clear();
    bool insert(const std::string& name);  // false when the name was there

  private:
    static constexpr std::size_t small_limit = 16;
    std::vector<std::string> small_;
    std::size_t used_ = 0;
    std::unordered_set<std::string> large_;
  };
  struct Level {
    bool object = false;
    bool first = true;
    NameSet names;
  };

  void skip_space() noexcept {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == ' ' || c == '\t' || c == '\r') {
        ++at_;
      } else if (c == '\n') {
        ++at_;
        ++line_;
        line_begin_ = at_;
      } else {
        break;
      }
    }
  }
  void open(char bracket, bool object);
  void scan_number();
  void scan_string(std::string* out);
  void scan_escape(std::string* out);
  void scan_utf8();
  std::uint32_t scan_hex4();
  void literal(std::string_view word);
  double out_of_range_value(std::string_view number) const;
  [[noreturn]] void fail_expected(const char* what);
  [[noreturn]] void fail_at(std::size_t offset, const std::string& message) const;

  std::string_view text_;
  std::string path_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
  std::size_t line_begin_ = 0;
  std::uint32_t depth_ = 0;
  bool pending_ = true;  // a value is due: the top-level one, a member's or an element's
  std::string_view number_text_;
  std::array<Level, max_depth> levels_;
};

}  // namespace madd::detail
