// run_script: splits a script into lines, each line into words, and runs the
// commands of the paper's maddi interface (Sec. 6, Table II) one by one.
#include <array>
#include <optional>

#include "madd/script.hpp"
#include "script/script_detail.hpp"

namespace madd {
namespace detail {

void ScriptCommand::fail(std::size_t column, const std::string& message) const {
  throw ParseError(script, line, column, message);
}

void ScriptCommand::fail_option(std::size_t column, const std::string& option, const std::string& message) const {
  throw OptionError(option, message,
                    script + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message);
}

void ScriptCommand::expect_arguments(std::size_t min, std::size_t max, const char* usage) const {
  const std::size_t n = words.size() - 1;
  if (n < min) fail(end_column, std::string("missing argument (usage: ") + usage + ")");
  if (n > max)
    fail(words[max + 1].column, "unexpected '" + printable(words[max + 1].text) + "' (usage: " + usage + ")");
}

std::string ScriptCommand::prefix() const { return script + ":" + std::to_string(line) + ": "; }

void rethrow_located(const ScriptCommand& c, std::size_t column, const Error& error) {
  const std::string message = c.prefix() + error.what();
  // Every error keeps its kind (and its type, for callers that catch by type).
  if (dynamic_cast<const ParseError*>(&error) != nullptr) throw ParseError(c.script, c.line, column, error.what());
  if (const auto* e = dynamic_cast<const InvalidInputError*>(&error))
    throw InvalidInputError(e->problem(), message, e->ids(), e->points());
  if (const auto* e = dynamic_cast<const DecompositionError*>(&error))
    throw DecompositionError(message, e->subdomain(), e->area(), e->separator_angle_deg());
  if (const auto* e = dynamic_cast<const OptionError*>(&error))
    throw OptionError(e->option(), e->requirement(), message);
  switch (error.kind()) {
  case ErrorKind::bad_input:
    throw InputFileError(message);
  case ErrorKind::output:
    throw OutputError(message);
  case ErrorKind::limit:
    throw LimitError(message);
  case ErrorKind::internal:
    throw InternalError(message);
  default:
    throw Error(error.kind(), message);
  }
}

std::string printable(std::string_view text) {
  std::string out(text);
  for (char& ch : out)
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ch = '?';
  return out;
}

}  // namespace detail

namespace {

using detail::ScriptCommand;
using detail::ScriptWord;

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The line without its comment: '#' outside a "quoted word" starts one.
std::string_view strip_comment(std::string_view line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    if (line[i] == '#' && !quoted) return line.substr(0, i);
  }
  return line;
}

// Splits a line into words; a word in double quotes may hold blanks.
// Returns nothing for a blank line.
std::optional<ScriptCommand> split_line(std::string_view raw, std::size_t line, const std::string& script) {
  const std::string_view text = strip_comment(raw);
  ScriptCommand c;
  c.script = script;
  c.line = line;
  std::size_t end = text.size();
  while (end > 0 && is_blank(text[end - 1])) --end;
  c.end_column = end + 1;
  for (std::size_t i = 0; i < end;) {
    if (is_blank(text[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    ScriptWord w;
    w.column = i + 1;
    if (text[i] == '"') {
      j = text.find('"', i + 1);
      if (j == std::string_view::npos || j >= end) c.fail(i + 1, "unterminated quote");
      w.text = std::string(text.substr(i + 1, j - i - 1));
      ++j;
    } else {
      while (j < end && !is_blank(text[j])) ++j;
      w.text = std::string(text.substr(i, j - i));
    }
    if (c.words.size() == 1) {
      c.rest = std::string(text.substr(i, end - i));
      c.rest_column = i + 1;
    }
    c.words.push_back(std::move(w));
    i = j;
  }
  if (c.words.empty()) return std::nullopt;
  if (c.words.size() == 1) c.rest_column = c.end_column;
  return c;
}

enum class Verb : std::uint8_t {
  read,
  dec,
  write,
  read_weights,
  read_areas,
  write_subdomains,
  weight_function,
  area_function,
  set,
  exit
};

struct VerbName {
  std::string_view name;
  Verb verb;
};

constexpr std::array<VerbName, 11> verbs{{
    {"read", Verb::read},
    {"dec", Verb::dec},
    {"write", Verb::write},
    {"read_weights", Verb::read_weights},
    {"read_areas", Verb::read_areas},
    {"writeSubdomains", Verb::write_subdomains},
    {"setWeightFunction", Verb::weight_function},
    {"setAreaFunction", Verb::area_function},
    {"set", Verb::set},
    {"exit", Verb::exit},
    {"quit", Verb::exit},
}};

// Runs one command; returns true for `exit`.
bool execute(const ScriptCommand& c, ScriptContext& context) {
  const std::string& word = c.words[0].text;
  std::optional<Verb> verb;
  for (const VerbName& v : verbs)
    if (v.name == word) verb = v.verb;
  if (!verb)
    c.fail(c.words[0].column, "unknown command '" + detail::printable(word) +
                                  "' (commands: read, dec, write, read_weights, read_areas, writeSubdomains, "
                                  "setWeightFunction, setAreaFunction, set, exit)");
  switch (*verb) {
  case Verb::read:
    detail::script_read(c, context);
    break;
  case Verb::dec:
    detail::script_dec(c, context);
    break;
  case Verb::write:
    detail::script_write(c, context);
    break;
  case Verb::read_weights:
    detail::script_read_values(c, context, false);
    break;
  case Verb::read_areas:
    detail::script_read_values(c, context, true);
    break;
  case Verb::write_subdomains:
    detail::script_write_subdomains(c, context);
    break;
  case Verb::weight_function:
    detail::script_set_function(c, context, false);
    break;
  case Verb::area_function:
    detail::script_set_function(c, context, true);
    break;
  case Verb::set:
    detail::script_set(c, context);
    break;
  case Verb::exit:
    c.expect_arguments(0, 0, "exit");
    return true;
  }
  return false;
}

}  // namespace

ScriptResult run_script(std::string_view text, const std::string& name, ScriptContext& context) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 byte order mark
  ScriptResult result;
  std::size_t line = 0;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    const std::string_view raw = text.substr(0, newline);
    text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
    ++line;
    const std::optional<ScriptCommand> command = split_line(raw, line, name);
    if (!command) continue;
    ++result.commands;
    if (execute(*command, context)) {
      result.exited = true;
      break;
    }
  }
  return result;
}

}  // namespace madd
