#include "keywords.hpp"

#include <cstring>
#include <string>

namespace madd::python {

namespace {

// The front end's rows that are library options too, and their keywords
// (the fields they set in MeshOptions, TriangulateOptions, or the depth file).
struct FrontKeyword {
  const char* row;
  const char* keyword;
};
constexpr FrontKeyword front_keywords[] = {
    {"balance", "balance_by_work"},
    {"no-off-centres", "off_centres"},
    {"no-verify", "verify"},
    {"depth", "depth"},
    {"depth-up", "depth_up"},
    {"convex-hull", "convex_hull"},
    {"region-attributes", "region_attributes"},
    {"resolve-crossings", "resolve_crossings"},
};

// The named arguments of madd.mesh and their fields.
struct Alias {
  const char* keyword;
  const char* field;
};
constexpr Alias aliases[] = {{"q", "min_triangle_angle_deg"}, {"max_area", "max_triangle_area"}, {"n", "subdomains"}};

const char* alias_of(const char* field) {
  for (const Alias& a : aliases)
    if (std::strcmp(a.field, field) == 0) return a.keyword;
  return nullptr;
}

bool is_switch_off(const cli::Option& row) {
  return std::strcmp(row.name, "no-off-centres") == 0 || std::strcmp(row.name, "no-verify") == 0;
}

// A value as the CLI would have it typed: numbers as Python writes them
// (repr: the shortest text that reads back to the same double), sequences
// comma-separated, paths as paths.
std::string text_of(py::handle value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::float_>(value)) return py::repr(value).cast<std::string>();
  if (py::hasattr(value, "__fspath__")) return py::module_::import("os").attr("fspath")(value).cast<std::string>();
  if (py::isinstance<py::sequence>(value) || py::hasattr(value, "tolist")) {
    const py::object items =
        py::hasattr(value, "tolist") ? value.attr("tolist")() : py::reinterpret_borrow<py::object>(value);
    if (py::isinstance<py::sequence>(items) && !py::isinstance<py::str>(items)) {
      std::string out;
      for (const py::handle item : items) {
        if (!out.empty()) out += ',';
        out += text_of(item);
      }
      return out;
    }
    return text_of(items);
  }
  return py::str(value).cast<std::string>();
}

bool truth_of(py::handle value, const char* keyword) {
  if (py::isinstance<py::bool_>(value) || py::hasattr(value, "dtype")) return value.cast<bool>();
  throw py::type_error(std::string(keyword) + " takes True or False, got " + py::repr(value).cast<std::string>());
}

// The row of `command` that `keyword` names, else the decomposition's row
// of `also` that it names, else nullptr.
const cli::Option* row_named(const cli::CommandOptions& command, const cli::CommandOptions* also,
                             std::string_view keyword) {
  for (const Alias& a : aliases)
    if (keyword == a.keyword) keyword = a.field;
  for (const cli::CommandOptions* from : {&command, also}) {
    if (from == nullptr) continue;
    for (const cli::OptionUse& use : from->uses) {
      const cli::Option* row = use.name != nullptr ? cli::find_option(use.name) : nullptr;
      const char* k = row != nullptr ? keyword_of(*row) : nullptr;
      if (k == nullptr || keyword != k) continue;
      if (from == &command || row->scope == cli::Scope::decomposition) return row;
    }
  }
  return nullptr;
}

// A setter's problem ("max_area needs an area > 0, got '-1'"): the rule is
// what follows the keyword.
void refuse(const cli::Option& row, const char* keyword, const std::string& problem) {
  const std::string prefix = std::string(keyword) + " ";
  const std::string rule = problem.rfind(prefix, 0) == 0 ? problem.substr(prefix.size()) : problem;
  throw OptionError(row.field != nullptr ? row.field : keyword, rule, problem);
}

// How the help shows a keyword: with its alias, the value that means what
// the CLI's switch means, and the CLI's flag.
std::string spelling(const cli::Option& row, const char* keyword) {
  std::string flag = std::string("--") + row.name;
  if (std::strcmp(row.name, "balance") == 0) return "balance_by_work=False (--balance area; default True: work)";
  if (std::strcmp(row.name, "sizes-nearest") == 0)
    return "sample_interpolation='nearest' (--sizes-nearest; default 'linear')";
  if (row.arity == cli::Arity::none)
    return std::string(keyword) + (is_switch_off(row) ? "=False (" : "=True (") + flag + ")";
  std::string out;
  if (const char* alias = alias_of(keyword)) out += std::string(alias) + ", ";
  return out + keyword + " (" + flag + " " + (row.value != nullptr ? row.value : "") + ")";
}

}  // namespace

const char* keyword_of(const cli::Option& row) {
  for (const FrontKeyword& f : front_keywords)
    if (std::strcmp(f.row, row.name) == 0) return f.keyword;
  if (row.scope == cli::Scope::front_end || row.scope == cli::Scope::svg || row.field == nullptr) return nullptr;
  return row.field;
}

void apply_keyword(cli::CommandLine& line, const Keywords& keywords, const char* name, py::handle value) {
  const cli::Option* row = row_named(keywords.command, keywords.also, name);
  if (row == nullptr)
    throw py::type_error(std::string(keywords.function) + "() got an unexpected keyword argument '" + name + "'");
  std::string text;
  const char* argument = nullptr;
  if (std::strcmp(row->name, "balance") == 0) {
    text = truth_of(value, name) ? "work" : "area";
    argument = text.c_str();
  } else if (std::strcmp(row->name, "sizes-nearest") == 0) {
    text = text_of(value);
    if (text == "linear") return;
    if (text != "nearest") refuse(*row, name, std::string(name) + " takes 'linear' or 'nearest', got '" + text + "'");
  } else if (row->arity == cli::Arity::none) {
    if (truth_of(value, name) == is_switch_off(*row)) return;  // the default: nothing to set
  } else {
    text = text_of(value);
    argument = text.c_str();
  }
  if (const std::string problem = row->set(line, argument, name); !problem.empty()) refuse(*row, name, problem);
  line.typed[row->name] = {name, text};
}

void apply_keywords(cli::CommandLine& line, const Keywords& keywords, const py::dict& values) {
  for (const auto& [key, value] : values) apply_keyword(line, keywords, key.cast<std::string>().c_str(), value);
}

OptionError in_python_words(const OptionError& error, const cli::CommandLine& line,
                            const cli::CommandOptions& command) {
  for (const cli::OptionUse& use : command.uses) {
    const cli::Option* row = use.name != nullptr ? cli::find_option(use.name) : nullptr;
    if (row == nullptr || row->field == nullptr || error.option() != row->field) continue;
    const auto typed = line.typed.find(row->name);
    if (typed == line.typed.end()) break;
    std::string message = typed->second.flag;
    if (message != error.option()) message += " (" + error.option() + ")";
    message += " " + error.requirement();
    const bool value_is_field = row->value != nullptr && std::string_view(row->value) != "FILE";
    if (value_is_field && !typed->second.value.empty()) message += ", got " + typed->second.value;
    return OptionError(error.option(), error.requirement(), message);
  }
  return error;
}

void check_keywords(const cli::CommandLine& line, const cli::CommandOptions& command, bool sizes_given,
                    bool depth_given) {
  try {
    check_options(line.mesh.decomposition);
    MeshOptions mesh = line.mesh;
    // What a check needs of samples and depths is that they are there (a size bound to grade).
    if (sizes_given) mesh.size.triangle_area_samples = {{{0, 0}, 1.0}};
    if (depth_given) {
      mesh.size.depth = [](double, double) { return 1.0; };
      mesh.size.depth_gradient = [](double, double) { return Point{}; };
    }
    check_options(mesh);
  } catch (const OptionError& e) {
    throw in_python_words(e, line, command);
  }
}

std::string keywords_help(const cli::CommandOptions& command, const cli::CommandOptions* also) {
  std::string out;
  std::string heading;
  auto add = [&](const cli::CommandOptions& from, bool skip_known) {
    for (const cli::OptionUse& use : from.uses) {
      if (use.name == nullptr) {
        heading = use.help;
        continue;
      }
      const cli::Option* row = cli::find_option(use.name);
      const char* keyword = row != nullptr && use.help != nullptr ? keyword_of(*row) : nullptr;
      if (keyword == nullptr) continue;
      if (skip_known && row_named(command, nullptr, keyword) != nullptr) continue;
      if (skip_known && row->scope != cli::Scope::decomposition) continue;
      if (!heading.empty()) {
        out += "\n" + heading + "\n";
        heading.clear();
      }
      out += "    " + spelling(*row, keyword) + "\n";
      std::string help = "        ";
      for (const char* c = use.help; *c != '\0'; ++c)
        help += *c == '\n' ? std::string("\n        ") : std::string(1, *c);
      out += help + "\n";
    }
  };
  add(command, false);
  if (also != nullptr) {
    heading = "also the decomposition's (as `madd decompose` takes them):";
    add(*also, true);
  }
  return out;
}

}  // namespace madd::python
