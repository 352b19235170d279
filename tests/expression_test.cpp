// The expression language of include/madd/expression.hpp: values compared
// against the same formula computed in C++, every error with its column.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "madd/error.hpp"
#include "madd/expression.hpp"

namespace {

using madd::parse_expression;

constexpr double pi = 3.14159265358979323846;

// Points where every test formula is defined, including negative coordinates.
constexpr double sample_points[][2] = {{0.0, 0.0}, {0.5, 0.25}, {-1.5, 2.0}, {3.0, -0.75}, {1e-3, 7.0}};

template <class F>
void check_against(const std::string& text, F reference) {
  CAPTURE(text);
  const madd::Expression e = parse_expression(text);
  for (const auto& p : sample_points) {
    CAPTURE(p[0]);
    CAPTURE(p[1]);
    const double want = reference(p[0], p[1]);
    const double got = e(p[0], p[1]);
    if (std::isnan(want)) {
      CHECK(std::isnan(got));
    } else if (std::isinf(want)) {
      CHECK(got == want);
    } else {
      CHECK(got == doctest::Approx(want).epsilon(1e-14));
    }
  }
}

// Parses `text`, expecting a ParseError at `column` whose message contains `part`.
void check_error(const std::string& text, std::size_t column, const std::string& part) {
  CAPTURE(text);
  try {
    (void)parse_expression(text, "f");
    FAIL("no error for '" << text << "'");
  } catch (const madd::ParseError& e) {
    CAPTURE(e.what());
    CHECK(e.path() == "f");
    CHECK(e.line() == 1);
    CHECK(e.column() == column);
    CHECK(e.message().find(part) != std::string::npos);
  }
}

}  // namespace

TEST_SUITE("expression") {

TEST_CASE("numbers in every notation") {
  const double x = 0, y = 0;
  CHECK(parse_expression("42")(x, y) == 42.0);
  CHECK(parse_expression("2.5")(x, y) == 2.5);
  CHECK(parse_expression(".5")(x, y) == 0.5);
  CHECK(parse_expression("5.")(x, y) == 5.0);
  CHECK(parse_expression("1e-4")(x, y) == 1e-4);
  CHECK(parse_expression("1E+3")(x, y) == 1000.0);
  CHECK(parse_expression("  3.25e2  ")(x, y) == 325.0);
  CHECK(parse_expression("1e-400")(x, y) == 0.0);  // underflow is zero, not an error
}

TEST_CASE("precedence and associativity") {
  check_against("1+2*3", [](double, double) { return 7.0; });
  check_against("(1+2)*3", [](double, double) { return 9.0; });
  check_against("2^3^2", [](double, double) { return 512.0; });  // right associative
  check_against("(2^3)^2", [](double, double) { return 64.0; });
  check_against("-x^2", [](double x, double) { return -(x * x); });
  check_against("-2^2", [](double, double) { return -4.0; });
  check_against("2^-1", [](double, double) { return 0.5; });
  check_against("2^-x^2", [](double x, double) { return std::pow(2.0, -(x * x)); });
  check_against("8-3-2", [](double, double) { return 3.0; });  // left associative
  check_against("8/4/2", [](double, double) { return 1.0; });
  check_against("x-y*2/4+1", [](double x, double y) { return x - y * 2 / 4 + 1; });
  check_against("--x", [](double x, double) { return x; });
  check_against("+-+x", [](double x, double) { return -x; });
  check_against("x*-y", [](double x, double y) { return x * -y; });
  check_against("2*x^3/y", [](double x, double y) { return 2 * std::pow(x, 3) / y; });
}

TEST_CASE("variables and constants") {
  check_against("x", [](double x, double) { return x; });
  check_against("y", [](double, double y) { return y; });
  check_against("r", [](double x, double y) { return std::hypot(x, y); });
  check_against("pi", [](double, double) { return pi; });
  check_against("e", [](double, double) { return std::exp(1.0); });
  check_against("1e-4*(1+r^12)", [](double x, double y) { return 1e-4 * (1 + std::pow(std::hypot(x, y), 12)); });
  check_against("hypot(x-0.5, y)^2", [](double x, double y) { return std::pow(std::hypot(x - 0.5, y), 2); });
  check_against("min(1, exp(-x))", [](double x, double) { return std::fmin(1.0, std::exp(-x)); });
}

TEST_CASE("every function") {
  check_against("sqrt(abs(x)+1)", [](double x, double) { return std::sqrt(std::fabs(x) + 1); });
  check_against("exp(x)", [](double x, double) { return std::exp(x); });
  check_against("log(y)", [](double, double y) { return std::log(y); });  // NaN for y < 0
  check_against("sin(x*pi)", [](double x, double) { return std::sin(x * pi); });
  check_against("cos(y)", [](double, double y) { return std::cos(y); });
  check_against("tan(x/3)", [](double x, double) { return std::tan(x / 3); });
  check_against("abs(x-y)", [](double x, double y) { return std::fabs(x - y); });
  check_against("floor(x*2)", [](double x, double) { return std::floor(x * 2); });
  check_against("ceil(y/2)", [](double, double y) { return std::ceil(y / 2); });
  check_against("hypot(x, 2*y)", [](double x, double y) { return std::hypot(x, 2 * y); });
  check_against("pow(abs(x), 0.5)", [](double x, double) { return std::pow(std::fabs(x), 0.5); });
  check_against("min(x, y)", [](double x, double y) { return std::fmin(x, y); });
  check_against("max(x, y)", [](double x, double y) { return std::fmax(x, y); });
  check_against("min(x, y, 1, -x)", [](double x, double y) { return std::fmin(std::fmin(x, y), std::fmin(1.0, -x)); });
  check_against("max(x, y, 0.5)", [](double x, double y) { return std::fmax(std::fmax(x, y), 0.5); });
}

TEST_CASE("IEEE results instead of errors when evaluating") {
  const madd::Expression e = parse_expression("1/x");
  CHECK(std::isinf(e(0.0, 0.0)));
  CHECK(std::isnan(parse_expression("sqrt(x)")(-1.0, 0.0)));
  CHECK(parse_expression("max(log(x), 3)")(-1.0, 0.0) == 3.0);  // fmax ignores the NaN
}

TEST_CASE("default expression, copies and std::function") {
  const madd::Expression zero;
  CHECK(zero(3.0, 4.0) == 0.0);
  const madd::Expression e = parse_expression("x + 2*y");
  const madd::Expression copy = e;
  CHECK(copy == e);
  CHECK(copy.text() == "x + 2*y");
  const std::function<double(double, double)> f = e.function();
  CHECK(f(1.0, 2.0) == 5.0);
  CHECK(parse_expression("x + 2*y") == e);
  CHECK_FALSE(parse_expression("x + 3*y") == e);
  CHECK_FALSE(parse_expression("x+2*y") == e);  // the same program, another text
}

TEST_CASE("every error names its column") {
  check_error("", 1, "empty expression");
  check_error("   ", 4, "empty expression");
  check_error("sine(x)", 1, "unknown function 'sine'");
  check_error("1+sine(x)", 3, "unknown function 'sine'");
  check_error("(1+2", 5, "expected ')'");
  check_error("(1+2", 5, "'(' at column 1");
  check_error("1+", 3, "unexpected end of expression");
  check_error("x*", 3, "unexpected end of expression");
  check_error("-", 2, "unexpected end of expression");
  check_error("z+1", 1, "unknown variable 'z'");
  check_error("x $ y", 3, "unexpected character '$'");
  check_error("x\x01", 2, "byte 0x01");
  check_error("x y", 3, "expected an operator");
  check_error("x)", 2, "without a matching '('");
  check_error("*x", 1, "found '*'");
  check_error("x**2", 3, "found '*'");
  check_error("()", 2, "found ')'");
  check_error("2x", 2, "multiplication needs '*'");
  check_error("1.2.3", 4, "unexpected '.'");
  check_error("1e+", 2, "the exponent needs digits");
  check_error("1e999", 1, "too large");
  check_error("sin", 1, "needs its arguments in parentheses");
  check_error("x(1)", 1, "'x' is not a function");
  check_error("sin(1, 2)", 1, "takes 1 argument, got 2");
  check_error("sqrt()", 1, "takes 1 argument, got 0");
  check_error("hypot(1)", 1, "takes 2 arguments, got 1");
  check_error("pow(1,2,3)", 1, "takes 2 arguments, got 3");
  check_error("min(1)", 1, "takes 2 or more arguments, got 1");
  check_error("max(1 2)", 7, "expected ')' or ','");
  check_error("min(1,)", 7, "found ')'");
}

TEST_CASE("the default name is <expression>") {
  try {
    (void)parse_expression("1+");
    FAIL("no error");
  } catch (const madd::ParseError& e) {
    CHECK(std::string(e.what()) == "<expression>:1:3: unexpected end of expression");
  }
}

TEST_CASE("deep nesting is rejected cleanly, shallow nesting accepted") {
  const std::size_t limit = madd::max_expression_depth;
  // Nesting just inside the limit works (the top-level operand is one level).
  const std::string ok = std::string(limit - 1, '(') + "x" + std::string(limit - 1, ')');
  CHECK(parse_expression(ok)(2.0, 0.0) == 2.0);
  for (const std::string& deep : {std::string(limit, '(') + "x" + std::string(limit, ')'), std::string(100000, '('),
                                  std::string(100000, '-') + "x",
                                  [] {
                                    std::string s;
                                    for (int i = 0; i < 50000; ++i) s += "sin(";
                                    return s;
                                  }(),
                                  [] {
                                    std::string s = "2";
                                    for (int i = 0; i < 50000; ++i) s += "^2";
                                    return s;
                                  }()}) {
    try {
      (void)parse_expression(deep);
      FAIL("deep nesting accepted");
    } catch (const madd::ParseError& e) {
      CHECK(e.message().find("nested too deeply") != std::string::npos);
    }
  }
}

TEST_CASE("long flat expressions are fine") {
  std::string sum = "0";
  std::string mins = "min(0";
  for (int i = 1; i <= 20000; ++i) {
    const std::string number = std::to_string(i);
    sum.push_back('+');
    sum += number;
    mins.push_back(',');
    mins += number;
  }
  mins += ")";
  CHECK(parse_expression(sum)(0, 0) == 20000.0 * 20001.0 / 2);
  const madd::Expression m = parse_expression(mins);
  CHECK(m(0, 0) == 0.0);
  CHECK(m.stack_size() <= 3);
}

TEST_CASE("the deepest accepted right-nested sum evaluates correctly") {
  // 1+(1+(1+...)) keeps one pending value per level: the stack bound's worst case.
  std::string s;
  const std::size_t levels = madd::max_expression_depth - 1;
  for (std::size_t i = 0; i < levels; ++i) s += "1+x*(";
  s += "1";
  s += std::string(levels, ')');
  const madd::Expression e = parse_expression(s);
  CHECK(e(0.0, 0.0) == 1.0);
  CHECK(e(1.0, 0.0) == static_cast<double>(levels + 1));
}

}  // TEST_SUITE("expression")
