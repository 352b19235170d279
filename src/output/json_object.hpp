#pragma once
// The JSON reports' writer (format_report_json, format_mesh_report_json): one
// object, one member per line, as `jq` and a reader of the text both like.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "kernel/number_format.hpp"

namespace madd::detail {

// A JSON string: quotes, backslashes and control characters escaped.
inline void append_json_string(std::string& out, std::string_view s) {
  out += '"';
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
      out += buffer;
    } else {
      out += c;
    }
  }
  out += '"';
}

// "{", then `"name": value` members separated by ",\n", then "\n}\n".
class JsonObject {
public:
  explicit JsonObject(std::string& out) : out_(out) { out_ += "{"; }
  // Starts a member; the caller appends its value.
  void key(std::string_view name) {
    out_ += first_ ? "\n  \"" : ",\n  \"";
    first_ = false;
    out_.append(name);
    out_ += "\": ";
  }
  // How a number is written: the shortest text that reads back as it, or every digit (%.17g).
  enum class Digits { shortest, all };
  // v, or null when not finite (JSON has no NaN or infinity).
  void number(std::string_view name, double v, Digits digits = Digits::shortest) {
    key(name);
    if (!std::isfinite(v)) out_ += "null";
    else if (digits == Digits::all) append_g17(out_, v);
    else append_shortest(out_, v);
  }
  void count(std::string_view name, std::uint64_t v) {
    key(name);
    append_int(out_, static_cast<std::int64_t>(v));
  }
  void close() { out_ += "\n}\n"; }

private:
  std::string& out_;
  bool first_ = true;
};

}  // namespace madd::detail
