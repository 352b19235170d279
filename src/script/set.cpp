// `set <param>=<value>` (paper Table III) and setWeightFunction /
// setAreaFunction, which take an expression (madd/expression.hpp) where the
// paper loaded a function from a shared library (Sec. 6).
#include <charconv>
#include <cmath>
#include <cstdint>

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

// The parameters of Table III (plus the engineering ones), each with the
// DecomposeOptions field it sets. Ranges are the library's (check_options);
// here a value is only parsed.
enum class ValueType : std::uint8_t { real, whole };
struct Parameter {
  const char* name;
  const char* field;  // as OptionError::option() names it
  const char* meaning;
  ValueType type;
};
constexpr Parameter parameters[] = {
    {"f", "separator_angle_deg", "the minimum angle as a fraction of pi", ValueType::real},
    {"r", "boundary_refinement", "the refinement factor", ValueType::real},
    {"a", "gradation", "the gradation factor", ValueType::real},
    {"p", "interpolation", "the interpolation factor", ValueType::real},
    {"i", "min_split_quality", "the acceptable imbalance", ValueType::real},
    {"s", "smoothing_iterations", "smoothing iterations", ValueType::whole},
    {"smooth", "smoothing_iterations", "smoothing iterations", ValueType::whole},
    {"ratio", "subdomain_area_ratio", "the area ratio bound", ValueType::real},
    {"n", "subdomains", "the number of subdomains", ValueType::whole},
    {"j", "threads", "worker threads, 0 = all cores", ValueType::whole},
    {"threads", "threads", "worker threads, 0 = all cores", ValueType::whole},
    {"seed", "seed", "the random seed", ValueType::whole},
};

const Parameter* find_parameter(const std::string& name) {
  for (const Parameter& p : parameters)
    if (name == p.name) return &p;
  return nullptr;
}

// Sets the field of `p` from `value`; false when the value does not parse
// as the parameter's type (or does not fit the field).
bool assign(const Parameter& p, const std::string& value, DecomposeOptions& o) {
  double x = 0;
  unsigned long long k = 0;
  const std::string field = p.field;
  if (p.type == ValueType::real) {
    if (!parse_real(value, x)) return false;
    if (field == "separator_angle_deg") o.separator_angle_deg = x * 180.0;  // the paper's f: f = 1/3 is 60 degrees
    if (field == "boundary_refinement") o.boundary_refinement = x;
    if (field == "gradation") o.gradation = x;
    if (field == "interpolation") o.interpolation = x;
    if (field == "min_split_quality") o.min_split_quality = x;
    if (field == "subdomain_area_ratio") o.subdomain_area_ratio = x;
    return true;
  }
  if (!parse_whole(value, field == "seed" ? ~0ull : 0xFFFFFFFFull, k)) return false;
  if (field == "smoothing_iterations") {
    if (k > 1000000) return false;
    o.smoothing_iterations = static_cast<int>(k);
  }
  if (field == "subdomains") o.subdomains = static_cast<std::uint32_t>(k);
  if (field == "threads") o.threads = static_cast<unsigned>(k);
  if (field == "seed") o.seed = k;
  return true;
}

std::string parameter_names() {
  std::string names;
  for (const Parameter& p : parameters) names += std::string(names.empty() ? "" : " ") + p.name;
  return names;
}

}  // namespace

std::string script_name_of(const std::string& field) {
  if (field == "weight_function") return "setWeightFunction";
  if (field == "subdomain_area_function") return "setAreaFunction";
  if (field == "weight_samples") return "read_weights";
  if (field == "subdomain_area_samples") return "read_areas";
  for (const Parameter& p : parameters)
    if (field == p.field) return std::string(p.name) + " (" + field + ")";
  return field;
}

namespace {

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
  const auto skip = [&] {
    while (i < s.size() && is_blank(s[i])) ++i;
  };
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

}  // namespace

void script_set(const ScriptCommand& c, ScriptContext& context) {
  // All assignments of the line are checked before any applies, so a bad
  // line changes nothing. A value out of its range is a bad option, located
  // at the value and named by its parameter (f, r, ...).
  DecomposeOptions options = context.options;
  const std::vector<Assignment> assignments = split_assignments(c);
  for (const Assignment& a : assignments) {
    const Parameter* p = find_parameter(a.name);
    if (p == nullptr)
      c.fail(a.name_column, "unknown parameter '" + printable(a.name) + "' (parameters: " + parameter_names() + ")");
    if (!assign(*p, a.value, options))
      c.fail_option(a.value_column, p->field,
                    std::string(p->name) + " (" + p->meaning + ") needs " +
                        (p->type == ValueType::real ? "a number" : "a whole number") + ", got '" + printable(a.value) +
                        "'");
  }
  try {
    check_option_ranges(options);
  } catch (const OptionError& e) {
    for (auto a = assignments.rbegin(); a != assignments.rend(); ++a) {
      const Parameter* p = find_parameter(a->name);
      if (e.option() != p->field) continue;
      c.fail_option(a->value_column, e.option(),
                    std::string(p->name) + " (" + p->meaning + ", " + e.option() + ") " + e.requirement() + ", got '" +
                        printable(a->value) + "'");
    }
    throw;
  }
  context.options = std::move(options);
  if (context.log) context.log("set " + c.rest);
}

// setWeightFunction EXPR / setAreaFunction EXPR: grading case 3 of Sec. 5.2.
// `none` removes the function.
void script_set_function(const ScriptCommand& c, ScriptContext& context, bool areas) {
  const std::string command = c.words[0].text;
  auto& target = areas ? context.options.subdomain_area_function : context.options.weight_function;
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

}  // namespace madd::detail
