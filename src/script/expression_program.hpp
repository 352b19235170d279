#pragma once
// What parse_expression compiles to (include/madd/expression.hpp): a stack
// machine in postfix order. Private to the library; an Expression holds one,
// shared by its copies (it never changes once compiled).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace madd::detail {

enum class ExprOp : std::uint8_t {
  constant,
  x,
  y,
  r,
  add,
  sub,
  mul,
  div,
  pow,
  neg,
  sqrt,
  exp,
  log,
  sin,
  cos,
  tan,
  abs,
  floor,
  ceil,
  min,
  max,
  hypot,
};

// What an instruction does to the stack: a leaf pushes a value, a binary
// operator takes two and leaves one, every other operator replaces the top.
// The evaluator and the parser's stack bound both read these.
inline bool is_leaf(ExprOp op) noexcept {
  return op == ExprOp::constant || op == ExprOp::x || op == ExprOp::y || op == ExprOp::r;
}
inline bool is_binary(ExprOp op) noexcept {
  switch (op) {
  case ExprOp::add:
  case ExprOp::sub:
  case ExprOp::mul:
  case ExprOp::div:
  case ExprOp::pow:
  case ExprOp::min:
  case ExprOp::max:
  case ExprOp::hypot:
    return true;
  default:
    return false;
  }
}

struct ExprInstruction {
  ExprOp op = ExprOp::constant;
  double value = 0.0;  // the number, for ExprOp::constant only
  friend bool operator==(const ExprInstruction&, const ExprInstruction&) = default;
};

struct ExprProgram {
  std::vector<ExprInstruction> code;
  std::size_t stack_size = 1;  // the most values the stack holds while evaluating
  friend bool operator==(const ExprProgram&, const ExprProgram&) = default;
};

}  // namespace madd::detail
