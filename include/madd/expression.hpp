#pragma once
// A small arithmetic expression language in x and y, so that grading functions
// (paper Sec. 5.2, case 3) are given as text ("1e-4*(1+r^12)") instead of the
// dynamically loaded libraries of the paper's Sec. 6. Grammar in docs/script.md.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace madd {

namespace detail {
struct ExprProgram;  // the compiled program (src/script/expression_program.hpp)
}  // namespace detail

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

  // The most intermediate values evaluation holds (bounded: the parser
  // refuses expressions that need more).
  std::size_t stack_size() const noexcept;

  // The same text compiled to the same program.
  friend bool operator==(const Expression& a, const Expression& b) noexcept;

private:
  friend Expression parse_expression(std::string_view, const std::string&);
  std::shared_ptr<const detail::ExprProgram> program_;  // shared by copies: it never changes
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

}  // namespace madd
