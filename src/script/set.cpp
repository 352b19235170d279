// `set <param>=<value>` (paper Table III) and setWeightFunction /
// setAreaFunction, which take an expression (madd/expression.hpp) where the
// paper loaded a function from a shared library (Sec. 6).
#include <charconv>
#include <cmath>

#include "madd/expression.hpp"
#include "script/script_detail.hpp"

namespace madd::detail {
namespace {

bool parse_real(const std::string& text, double& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

bool parse_whole(const std::string& text, unsigned long long limit, unsigned long long& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end && !text.empty() && text[0] != '-' && value <= limit;
}

// Applies one parameter of Table III (plus the engineering ones); returns a
// message on a bad name or value, empty on success.
std::string apply_parameter(const std::string& name, const std::string& value, DecomposeOptions& o) {
  double x = 0;
  unsigned long long k = 0;
  const bool real = parse_real(value, x);
  if (name == "f") {
    // The paper's f is the minimum angle as a fraction of pi (f = 1/3 is 60 degrees).
    if (!real || x < 0 || x >= 0.5) return "f (the minimum angle as a fraction of pi) must be in [0, 0.5)";
    o.min_angle_deg = x * 180.0;
  } else if (name == "r") {
    if (!real || x <= 0) return "r (the refinement factor) must be > 0";
    o.refine = x;
  } else if (name == "a") {
    if (!real || x < 0) return "a (the gradation factor) must be >= 0";
    o.gradation = x;
  } else if (name == "p") {
    if (!real || x < 0) return "p (the interpolation factor) must be >= 0";
    o.interpolation = x;
  } else if (name == "i") {
    if (!real || x <= 0 || x > 1) return "i (the acceptable imbalance) must be in (0, 1]";
    o.min_balance_quality = x;
  } else if (name == "s" || name == "smooth") {
    if (!parse_whole(value, 1000, k)) return name + " (smoothing iterations) must be a whole number in [0, 1000]";
    o.smoothing_iterations = static_cast<int>(k);
  } else if (name == "ratio") {
    if (!real || x <= 0) return "ratio (the area ratio bound) must be > 0";
    o.area_ratio_bound = x;
  } else if (name == "n") {
    if (!parse_whole(value, 0xFFFFFFFFull, k) || k == 0)
      return "n (the number of subdomains) must be a whole number >= 1";
    o.subdomains = static_cast<std::uint32_t>(k);
  } else if (name == "j" || name == "threads") {
    if (!parse_whole(value, 4096, k))
      return name + " (worker threads, 0 = all cores) must be a whole number in [0, 4096]";
    o.threads = static_cast<unsigned>(k);
  } else if (name == "seed") {
    if (!parse_whole(value, ~0ull, k)) return "seed must be a whole number";
    o.seed = k;
  } else {
    return "unknown parameter '" + printable(name) + "' (parameters: f r a p i s ratio n j seed)";
  }
  return {};
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The paper writes `set f=0.35`; blanks around '=' and several assignments
// on one line (`set f = 0.35 r=3`) are accepted too.
struct Assignment {
  std::string name, value;
  std::size_t name_column = 0, value_column = 0;
};

std::vector<Assignment> split_assignments(const ScriptCommand& c) {
  const std::string& s = c.rest;
  std::vector<Assignment> out;
  std::size_t i = 0;
  const auto skip = [&] { while (i < s.size() && is_blank(s[i])) ++i; };
  const auto column = [&](std::size_t at) { return c.rest_column + at; };
  skip();
  if (i == s.size()) c.fail(c.end_column, "missing <parameter>=<value> (for example: set f=0.35)");
  while (i < s.size()) {
    Assignment a;
    a.name_column = column(i);
    while (i < s.size() && !is_blank(s[i]) && s[i] != '=') a.name.push_back(s[i++]);
    skip();
    if (a.name.empty()) c.fail(column(i), "missing the parameter name before '='");
    if (i == s.size() || s[i] != '=')
      c.fail(column(i), "expected '=' after '" + printable(a.name) + "' (set <parameter>=<value>)");
    ++i;
    skip();
    a.value_column = column(i);
    while (i < s.size() && !is_blank(s[i])) a.value.push_back(s[i++]);
    if (a.value.empty()) c.fail(a.value_column, "missing the value of '" + printable(a.name) + "'");
    skip();
    out.push_back(std::move(a));
  }
  return out;
}

bool looks_like_library(const std::string& word) {
  const auto ends_with = [&](std::string_view suffix) {
    return word.size() >= suffix.size() && word.compare(word.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return ends_with(".so") || word.find(".so.") != std::string::npos || ends_with(".dylib") || ends_with(".dll");
}

} // namespace

void script_set(const ScriptCommand& c, ScriptContext& context) {
  // All assignments of the line are checked before any applies, so a bad
  // line changes nothing.
  DecomposeOptions options = context.options;
  for (const Assignment& a : split_assignments(c)) {
    const std::string problem = apply_parameter(a.name, a.value, options);
    if (problem.empty()) continue;
    const bool bad_name = problem.rfind("unknown parameter", 0) == 0;
    c.fail(bad_name ? a.name_column : a.value_column,
           problem + (bad_name ? std::string() : ", got '" + printable(a.value) + "'"));
  }
  context.options = std::move(options);
  if (context.log) context.log("set " + c.rest);
}

// setWeightFunction EXPR / setAreaFunction EXPR: grading case 3 of Sec. 5.2.
// `none` removes the function.
void script_set_function(const ScriptCommand& c, ScriptContext& context, bool areas) {
  const std::string command = c.words[0].text;
  auto& target = areas ? context.options.area_function : context.options.weight_function;
  if (c.words.size() == 1)
    c.fail(c.end_column, "missing the expression in x, y and r (for example: " + command + " 1e-4*(1+r^12))");
  if (c.words.size() == 3 && looks_like_library(c.words[1].text))
    c.fail(c.words[1].column, "shared libraries are not loaded: expressions replace them, so " + command +
                                  " takes an expression in x, y and r instead of LIBRARY FUNCTION (for example: " +
                                  command + " 1e-4*(1+r^12); see docs/script.md)");
  if (c.words.size() == 2 && c.words[1].text == "none") {
    target = nullptr;
    if (context.log) context.log(command + " none");
    return;
  }
  Expression e;
  try {
    e = parse_expression(c.rest, c.script);
  } catch (const ParseError& pe) {
    c.fail(c.rest_column + pe.column() - 1, pe.message());
  }
  target = e.function();
  if (context.log) context.log(command + " " + c.rest);
}

} // namespace madd::detail
