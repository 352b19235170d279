// Recursive-descent parser of the expression language (docs/script.md),
// compiling straight to a postfix program. Recursion is bounded by a nesting
// counter (max_expression_depth), so hostile input fails with a ParseError
// instead of overflowing the stack (docs/design.md, "Errors").
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <utility>

#include "madd/error.hpp"
#include "madd/expression.hpp"
#include "script/expression_program.hpp"

namespace madd {
namespace {

using detail::ExprInstruction;
using detail::ExprOp;

// Evaluation keeps its stack in a fixed array of this size (expression.cpp);
// the parser rejects programs that would need more.
constexpr std::size_t max_stack = 4 * max_expression_depth + 8;

struct FunctionInfo {
  std::string_view name;
  ExprOp op;
  int min_args;
  int max_args;  // -1 = any number >= min_args
};

constexpr std::array<FunctionInfo, 13> functions{{
    {"sqrt", ExprOp::sqrt, 1, 1},
    {"exp", ExprOp::exp, 1, 1},
    {"log", ExprOp::log, 1, 1},
    {"sin", ExprOp::sin, 1, 1},
    {"cos", ExprOp::cos, 1, 1},
    {"tan", ExprOp::tan, 1, 1},
    {"abs", ExprOp::abs, 1, 1},
    {"floor", ExprOp::floor, 1, 1},
    {"ceil", ExprOp::ceil, 1, 1},
    {"hypot", ExprOp::hypot, 2, 2},
    {"pow", ExprOp::pow, 2, 2},
    {"min", ExprOp::min, 2, -1},
    {"max", ExprOp::max, 2, -1},
}};

const FunctionInfo* find_function(std::string_view name) {
  for (const FunctionInfo& f : functions)
    if (f.name == name) return &f;
  return nullptr;
}

// Variables and named constants: what a bare name compiles to.
bool name_value(std::string_view name, ExprInstruction& out) {
  if (name == "x") out = {ExprOp::x, 0.0};
  else if (name == "y") out = {ExprOp::y, 0.0};
  else if (name == "r") out = {ExprOp::r, 0.0};
  else if (name == "pi") out = {ExprOp::constant, 3.14159265358979323846};
  else if (name == "e") out = {ExprOp::constant, 2.71828182845904523536};
  else return false;
  return true;
}

enum class Tok : std::uint8_t { number, name, plus, minus, star, slash, caret, lparen, rparen, comma, end };

struct Token {
  Tok kind = Tok::end;
  std::size_t begin = 0;  // byte offsets into the text
  std::size_t end = 0;
  double value = 0.0;
};

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Parser {
public:
  Parser(std::string_view text, const std::string& name) : text_(text), name_(name) { advance(); }

  std::vector<ExprInstruction> run() {
    if (cur_.kind == Tok::end) fail(cur_.begin, "empty expression");
    parse_sum();
    if (cur_.kind == Tok::rparen) fail(cur_.begin, "unexpected ')' without a matching '('");
    if (cur_.kind != Tok::end)
      fail(cur_.begin, "expected an operator or the end of the expression, found " + describe(cur_));
    return std::move(program_);
  }

private:
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw ParseError(name_, 1, offset + 1, message);
  }

  std::string describe(const Token& t) const {
    if (t.kind == Tok::end) return "the end of the expression";
    std::string quoted = "'";
    quoted.append(text_.substr(t.begin, t.end - t.begin));
    quoted.push_back('\'');
    return quoted;
  }

  void emit(ExprOp op, double value = 0.0) { program_.push_back({op, value}); }

  void advance() {
    std::size_t p = cur_.end;
    while (p < text_.size() && std::isspace(static_cast<unsigned char>(text_[p])) != 0) ++p;
    cur_ = {Tok::end, p, p, 0.0};
    if (p == text_.size()) return;
    const char c = text_[p];
    if (is_digit(c) || (c == '.' && p + 1 < text_.size() && is_digit(text_[p + 1]))) return lex_number(p);
    if (is_name_start(c)) {
      std::size_t q = p;
      while (q < text_.size() && is_name_char(text_[q])) ++q;
      cur_ = {Tok::name, p, q, 0.0};
      return;
    }
    static constexpr std::string_view ops = "+-*/^(),";
    static constexpr std::array<Tok, 8> kinds{Tok::plus,  Tok::minus,  Tok::star,   Tok::slash,
                                              Tok::caret, Tok::lparen, Tok::rparen, Tok::comma};
    const std::size_t k = ops.find(c);
    if (k == std::string_view::npos) fail(p, "unexpected character " + quote_char(c));
    cur_ = {kinds[k], p, p + 1, 0.0};
  }

  static std::string quote_char(char c) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "0x%02x", static_cast<unsigned>(u));
    return std::string("byte ") + buffer;
  }

  void lex_number(std::size_t p) {
    std::size_t q = p;
    while (q < text_.size() && is_digit(text_[q])) ++q;
    if (q < text_.size() && text_[q] == '.') ++q;
    while (q < text_.size() && is_digit(text_[q])) ++q;
    if (q < text_.size() && (text_[q] == 'e' || text_[q] == 'E')) {
      std::size_t d = q + 1;
      if (d < text_.size() && (text_[d] == '+' || text_[d] == '-')) ++d;
      if (d >= text_.size() || !is_digit(text_[d]))
        fail(q, "malformed number '" + std::string(text_.substr(p, d - p)) + "': the exponent needs digits");
      while (d < text_.size() && is_digit(text_[d])) ++d;
      q = d;
    }
    if (q < text_.size() && (is_name_char(text_[q]) || text_[q] == '.'))
      fail(q, "unexpected " + quote_char(text_[q]) + " after the number '" + std::string(text_.substr(p, q - p)) +
                  "' (multiplication needs '*')");
    cur_ = {Tok::number, p, q, number_value(p, q)};
  }

  double number_value(std::size_t p, std::size_t q) const {
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(text_.data() + p, text_.data() + q, value);
    if (ec == std::errc() && ptr == text_.data() + q) return value;
    // Out of range: strtod tells overflow (inf) from underflow (0, accepted).
    const std::string token(text_.substr(p, q - p));
    value = std::strtod(token.c_str(), nullptr);
    if (!std::isfinite(value)) fail(p, "number '" + token + "' is too large");
    return value;
  }

  void expect(Tok kind, const std::string& message) {
    if (cur_.kind != kind) fail(cur_.begin, message + ", found " + describe(cur_));
    advance();
  }

  void parse_sum() {
    parse_product();
    while (cur_.kind == Tok::plus || cur_.kind == Tok::minus) {
      const ExprOp op = cur_.kind == Tok::plus ? ExprOp::add : ExprOp::sub;
      advance();
      parse_product();
      emit(op);
    }
  }

  void parse_product() {
    parse_unary();
    while (cur_.kind == Tok::star || cur_.kind == Tok::slash) {
      const ExprOp op = cur_.kind == Tok::star ? ExprOp::mul : ExprOp::div;
      advance();
      parse_unary();
      emit(op);
    }
  }

  // Every nested construct passes through here, so this one counter bounds
  // the recursion: parentheses, call arguments, unary signs, exponents.
  void parse_unary() {
    if (++depth_ > max_expression_depth)
      fail(cur_.begin, "expression nested too deeply (more than " + std::to_string(max_expression_depth) + " levels)");
    if (cur_.kind == Tok::plus) {
      advance();
      parse_unary();
    } else if (cur_.kind == Tok::minus) {
      advance();
      parse_unary();
      emit(ExprOp::neg);
    } else {
      parse_power();
    }
    --depth_;
  }

  // '^' is right associative and its exponent may carry a sign: 2^-1, 2^3^2 = 2^9.
  void parse_power() {
    parse_primary();
    if (cur_.kind == Tok::caret) {
      advance();
      parse_unary();
      emit(ExprOp::pow);
    }
  }

  void parse_primary() {
    const Token t = cur_;
    switch (t.kind) {
    case Tok::number:
      emit(ExprOp::constant, t.value);
      advance();
      return;
    case Tok::name:
      advance();
      if (cur_.kind == Tok::lparen) return parse_call(t);
      return parse_name(t);
    case Tok::lparen:
      advance();
      parse_sum();
      expect(Tok::rparen, "expected ')' to close the '(' at column " + std::to_string(t.begin + 1));
      return;
    case Tok::end:
      fail(t.begin, "unexpected end of expression");
    default:
      fail(t.begin, "expected a number, variable, function or '(', found " + describe(t));
    }
  }

  void parse_name(const Token& t) {
    const std::string_view name = text_.substr(t.begin, t.end - t.begin);
    ExprInstruction value;
    if (name_value(name, value)) return program_.push_back(value);
    if (find_function(name) != nullptr)
      fail(t.begin, "function '" + std::string(name) + "' needs its arguments in parentheses");
    fail(t.begin, "unknown variable '" + std::string(name) + "' (variables are x, y, r; constants pi, e)");
  }

  void parse_call(const Token& t) {
    const std::string name(text_.substr(t.begin, t.end - t.begin));
    const FunctionInfo* f = find_function(name);
    ExprInstruction unused;
    if (f == nullptr && name_value(name, unused)) fail(t.begin, "'" + name + "' is not a function");
    if (f == nullptr) fail(t.begin, "unknown function '" + name + "'");
    const std::size_t open = cur_.begin;
    advance();
    int args = 0;
    if (cur_.kind != Tok::rparen) {
      for (;;) {
        parse_sum();
        // min and max fold as they go, so many arguments never deepen the stack.
        if (++args >= 2 && f->max_args < 0) emit(f->op);
        if (cur_.kind != Tok::comma) break;
        advance();
      }
    }
    expect(Tok::rparen,
           "expected ')' or ',' in the call of '" + name + "' opened at column " + std::to_string(open + 1));
    if (args < f->min_args || (f->max_args >= 0 && args > f->max_args)) {
      const std::string wanted =
          f->max_args < 0 ? std::to_string(f->min_args) + " or more" : std::to_string(f->min_args);
      fail(t.begin, "function '" + name + "' takes " + wanted + (wanted == "1" ? " argument" : " arguments") +
                        ", got " + std::to_string(args));
    }
    if (f->max_args >= 0) emit(f->op);
  }

  std::string_view text_;
  const std::string& name_;
  Token cur_;
  std::size_t depth_ = 0;
  std::vector<ExprInstruction> program_;
};

// Slots the stack machine needs: +1 per push, -1 per binary operator.
std::size_t stack_needed(const std::vector<ExprInstruction>& program) {
  std::size_t size = 0, most = 1;
  for (const ExprInstruction& in : program) {
    if (is_leaf(in.op)) most = std::max(most, ++size);
    else if (is_binary(in.op)) --size;
  }
  return most;
}

}  // namespace

Expression parse_expression(std::string_view text, const std::string& name) {
  Expression e;
  detail::ExprProgram program{Parser(text, name).run(), 1};
  program.stack_size = stack_needed(program.code);
  if (program.stack_size > max_stack)
    throw ParseError(name, 1, 1,
                     "expression too complex (needs more than " + std::to_string(max_stack) + " intermediate values)");
  e.program_ = std::make_shared<const detail::ExprProgram>(std::move(program));
  e.text_ = std::string(text);
  return e;
}

}  // namespace madd
