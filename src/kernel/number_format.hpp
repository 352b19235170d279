#pragma once
// Number formatting shared by the output writers and the messages.
#include <charconv>
#include <cstdint>
#include <string>

namespace madd::detail {

// Appends v as %.17g would (round-trips exactly), without the locale: the
// same bytes as std::to_chars(general, 17), 1.6-1.9 times faster on the
// coordinates of mesh files (src/kernel/number_format.cpp; `madd_bench
// number_format`).
void append_g17(std::string& out, double v);

// Appends the shortest text that reads back as exactly v (JSON outputs).
inline void append_shortest(std::string& out, double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, result.ptr);
}

// v as %.17g would write it (every digit, so the exact value), for messages.
inline std::string number_text(double v) {
  std::string text;
  append_g17(text, v);
  return text;
}

inline void append_int(std::string& out, std::int64_t v) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, result.ptr);
}

}  // namespace madd::detail
