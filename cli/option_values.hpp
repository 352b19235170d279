#pragma once
// Reading an option's value: a finite number, or a whole number up to a
// limit. Shared by the subcommands that parse numbers (decompose, mesh).
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace madd::cli {

// The whole of `text` as a finite double.
inline bool parse_number(const char* text, double& value) {
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(value);
}

// The whole of `text` as a whole number <= limit (digits only: no sign).
inline bool parse_count(const char* text, unsigned long long limit, unsigned long long& value) {
  if (text[0] < '0' || text[0] > '9') return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtoull(text, &end, 10);
  return *end == '\0' && errno == 0 && value <= limit;
}

}  // namespace madd::cli
