// Evaluation of a compiled Expression: a postfix stack machine. The parser
// bounds the stack (expression_parser.cpp), so evaluation uses a fixed array
// and never allocates, which matters when grading evaluates it on a grid
// for every subdomain (paper Sec. 5.2, case 3).
#include <array>
#include <cassert>
#include <cmath>
#include <memory>
#include <utility>

#include "madd/expression.hpp"
#include "script/expression_program.hpp"

namespace madd {

using detail::ExprInstruction;
using detail::ExprOp;

Expression::Expression()
    : program_(std::make_shared<const detail::ExprProgram>(detail::ExprProgram{{{ExprOp::constant, 0.0}}, 1})),
      text_("0") {}

std::size_t Expression::stack_size() const noexcept { return program_->stack_size; }

bool operator==(const Expression& a, const Expression& b) noexcept {
  return a.text_ == b.text_ && (a.program_ == b.program_ || *a.program_ == *b.program_);
}

namespace {

double apply_unary(ExprOp op, double a) noexcept {
  switch (op) {
  case ExprOp::neg:
    return -a;
  case ExprOp::sqrt:
    return std::sqrt(a);
  case ExprOp::exp:
    return std::exp(a);
  case ExprOp::log:
    return std::log(a);
  case ExprOp::sin:
    return std::sin(a);
  case ExprOp::cos:
    return std::cos(a);
  case ExprOp::tan:
    return std::tan(a);
  case ExprOp::abs:
    return std::fabs(a);
  case ExprOp::floor:
    return std::floor(a);
  case ExprOp::ceil:
    return std::ceil(a);
  default:
    return a;
  }
}

// min and max follow C's fmin/fmax: a NaN argument is ignored, so the result
// does not depend on the order of the arguments.
double apply_binary(ExprOp op, double a, double b) noexcept {
  switch (op) {
  case ExprOp::add:
    return a + b;
  case ExprOp::sub:
    return a - b;
  case ExprOp::mul:
    return a * b;
  case ExprOp::div:
    return a / b;
  case ExprOp::pow:
    return std::pow(a, b);
  case ExprOp::min:
    return std::fmin(a, b);
  case ExprOp::max:
    return std::fmax(a, b);
  case ExprOp::hypot:
    return std::hypot(a, b);
  default:
    return a;
  }
}

}  // namespace

double Expression::operator()(double x, double y) const noexcept {
  std::array<double, 4 * max_expression_depth + 8> stack;
  assert(program_->stack_size <= stack.size());
  std::size_t top = 0;  // number of values on the stack
  for (const ExprInstruction& in : program_->code) {
    switch (in.op) {
    case ExprOp::constant:
      stack[top++] = in.value;
      break;
    case ExprOp::x:
      stack[top++] = x;
      break;
    case ExprOp::y:
      stack[top++] = y;
      break;
    case ExprOp::r:
      stack[top++] = std::hypot(x, y);
      break;
    default:
      if (is_binary(in.op)) {
        --top;
        stack[top - 1] = apply_binary(in.op, stack[top - 1], stack[top]);
      } else {
        stack[top - 1] = apply_unary(in.op, stack[top - 1]);
      }
    }
  }
  return stack[0];
}

std::function<double(double x, double y)> Expression::function() const {
  return [e = *this](double x, double y) { return e(x, y); };
}

}  // namespace madd
