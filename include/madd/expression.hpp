#pragma once
// A small arithmetic expression language in x and y, so that grading functions
// (paper Sec. 5.2, case 3) are given as text ("1e-4*(1+r^12)") instead of the
// dynamically loaded libraries of the paper's Sec. 6. Grammar in docs/script.md.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace madd {

namespace detail {
// One instruction of a compiled expression: a stack machine in postfix order.
enum class ExprOp : std::uint8_t {
  constant, x, y, r, add, sub, mul, div, pow, neg,
  sqrt, exp, log, sin, cos, tan, abs, floor, ceil, min, max, hypot,
};
struct ExprInstruction {
  ExprOp op = ExprOp::constant;
  double value = 0.0;  // the number, for ExprOp::constant only
  friend bool operator==(const ExprInstruction&, const ExprInstruction&) = default;
};
} // namespace detail

// Deepest nesting of parentheses, function calls, unary signs and '^' that
// parse_expression accepts; deeper input is a ParseError, never a stack overflow.
inline constexpr std::size_t max_expression_depth = 200;

// A compiled expression f(x, y): a value type, cheap to copy, safe to share
// between threads (evaluation does not modify it).
class Expression {
public:
  // The constant 0.
  Expression();

  // Evaluates at (x, y) with IEEE semantics: log(-1) is NaN, 1/0 is inf.
  // Never throws.
  double operator()(double x, double y) const noexcept;

  // A copy wrapped for DecomposeOptions::weight_function / DecomposeOptions::subdomain_area_function.
  std::function<double(double x, double y)> function() const;

  // The text it was compiled from.
  const std::string& text() const noexcept { return text_; }

  // The postfix program (for tests and tools); evaluation needs stack_size() slots.
  const std::vector<detail::ExprInstruction>& program() const noexcept { return program_; }
  std::size_t stack_size() const noexcept { return stack_size_; }

  friend bool operator==(const Expression&, const Expression&) = default;

private:
  friend Expression parse_expression(std::string_view, const std::string&);
  std::vector<detail::ExprInstruction> program_;
  std::size_t stack_size_ = 1;
  std::string text_;
};

// Compiles `text`. Numbers (1, .5, 2.5e-3), + - * / ^ (right associative and
// tighter than unary minus: -x^2 = -(x^2), 2^-1 = 0.5), parentheses,
// variables x, y, r (= hypot(x, y)), constants pi and e, and the functions
// sqrt exp log sin cos tan abs floor ceil (1 argument), hypot pow (2), min max
// (2 or more). Throws ParseError(name, line 1, column of the offending
// character, message) on malformed text or nesting deeper than
// max_expression_depth. Uses no recursion deeper than that bound.
Expression parse_expression(std::string_view text, const std::string& name = "<expression>");

} // namespace madd
