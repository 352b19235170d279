// libFuzzer target: the expression parser and evaluator. Any exception other
// than madd::Error, any crash or sanitizer report is a bug.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "madd/error.hpp"
#include "madd/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const madd::Expression e = madd::parse_expression(text, "fuzz");
    // Evaluation must be a pure function of (x, y): the same bits every time,
    // through the std::function wrapper too.
    const auto f = e.function();
    constexpr double points[][2] = {{0.0, 0.0}, {1.0, -2.0}, {-0.5, 0.25}, {1e300, -1e-300}, {NAN, 3.0}};
    for (const auto& p : points) {
      const double a = e(p[0], p[1]);
      const double b = f(p[0], p[1]);
      if (!(a == b || (std::isnan(a) && std::isnan(b)))) std::abort();
    }
    if (e.text() != text || madd::parse_expression(e.text(), "again") != e) std::abort();
  } catch (const madd::ParseError& error) {
    // Columns point into the text (one past its end for "unexpected end").
    if (error.line() != 1 || error.column() < 1 || error.column() > size + 1) std::abort();
  } catch (const madd::Error&) {}
  return 0;
}
