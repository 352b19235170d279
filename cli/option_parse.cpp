// Parsing a command line with the option table, the help of a command's
// options, and the library's option errors in the command's words
// (cli/option_table.hpp).
#include <getopt.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "option_table.hpp"

namespace madd::cli {

char letter_of(const OptionUse& use) {
  const Option* row = find_option(use.name);
  return row == nullptr || use.letter == Letter::none ? 0 : row->letter;
}

namespace {

// getopt_long's view of a command's options: val is the letter, or 256 + the
// index of the entry for an option without one here.
struct GetoptTables {
  std::vector<const Option*> rows;  // per entry
  std::vector<option> longs;        // per entry, then the terminator
  std::string shorts = ":";         // ':' first: a missing value returns ':'

  explicit GetoptTables(const CommandOptions& command) {
    for (const OptionUse& use : command.uses) {
      if (use.name == nullptr) continue;
      const Option* row = find_option(use.name);
      const char letter = letter_of(use);
      const int val = letter != 0 ? letter : 256 + static_cast<int>(rows.size());
      const int has_arg = row->arity == Arity::none       ? no_argument
                          : row->arity == Arity::required ? required_argument
                                                          : optional_argument;
      rows.push_back(row);
      longs.push_back({row->name, has_arg, nullptr, val});
      if (letter != 0) shorts += std::string(1, letter) + (has_arg == required_argument ? ":" : "");
    }
    longs.push_back({nullptr, 0, nullptr, 0});
  }

  const Option* row_of(int val) const {
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (longs[i].val == val) return rows[i];
    return nullptr;
  }
};

// What getopt_long's '?' means: a known option given a value it takes none
// of (optopt is its val), an unknown letter, or an unknown long option.
std::string unknown_option(const GetoptTables& tables, char** argv) {
  if (const Option* row = tables.row_of(optopt); row != nullptr && optopt != 0)
    return std::string("option '--") + row->name + "' takes no value";
  if (optopt > 0 && optopt < 256) return std::string("unknown option '-") + static_cast<char>(optopt) + "'";
  return std::string("unknown option '") + argv[optind - 1] + "'";
}

bool is_declined(std::span<const char* const> declined, const char* name) {
  return std::any_of(declined.begin(), declined.end(), [&](const char* d) { return std::string_view(d) == name; });
}

}  // namespace

std::string parse_command_line(const CommandOptions& command, int argc, char** argv, CommandLine& line,
                               std::span<const char* const> declined) {
  GetoptTables tables(command);
  optind = 0;  // glibc: 0 restarts the scan (a fresh argv per command)
  opterr = 0;
  for (;;) {
    int index = -1;
    const int c = getopt_long(argc, argv, tables.shorts.c_str(), tables.longs.data(), &index);
    if (c == -1) break;
    if (c == ':') return std::string("option '") + argv[optind - 1] + "' needs a value";
    if (c == '?') return unknown_option(tables, argv);
    const Option* row = tables.row_of(c);
    const std::string flag = index >= 0 ? std::string("--") + row->name : std::string("-") + static_cast<char>(c);
    if (is_declined(declined, row->name)) return "option '" + flag + "' is not available here (see --help)";
    if (const std::string problem = row->set(line, optarg, flag); !problem.empty()) return problem;
    line.typed[row->name] = {flag, optarg != nullptr ? optarg : ""};
    if (line.help) return {};
  }
  for (int i = optind; i < argc; ++i) line.operands.emplace_back(argv[i]);
  return {};
}

std::string options_help(const CommandOptions& command) {
  const auto column = static_cast<std::size_t>(command.column);
  std::string out;
  for (const OptionUse& use : command.uses) {
    if (use.name == nullptr) {
      out += use.help;
      out += '\n';
      continue;
    }
    if (use.help == nullptr) continue;
    const Option& row = *find_option(use.name);
    const char letter = use.letter == Letter::usual ? row.letter : 0;  // a deprecated letter only in the text
    std::string left = letter != 0 ? std::string("  -") + letter + ", --" : std::string("      --");
    left += row.name;
    const std::string value = use.value != nullptr ? use.value : row.value != nullptr ? row.value : "";
    if (row.arity == Arity::required) left += " " + value;
    if (row.arity == Arity::optional) left += "[=" + value + "]";
    left.resize(std::max(left.size() + 2, column), ' ');
    out += left;
    for (const char* c = use.help; *c != '\0'; ++c) {
      out += *c;
      if (*c == '\n') out.append(column, ' ');
    }
    out += '\n';
  }
  return out;
}

namespace {

// The row of the command that sets `field` of `scope`, or nullptr.
const Option* row_setting(const std::string& field, Scope scope, const CommandOptions& command) {
  for (const OptionUse& use : command.uses) {
    const Option* row = use.name != nullptr ? find_option(use.name) : nullptr;
    if (row != nullptr && row->scope == scope && row->field != nullptr && field == row->field) return row;
  }
  return nullptr;
}

bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// `text` with every whole word that is a field of `scope` replaced by the long flag setting it.
std::string in_cli_words(const std::string& text, Scope scope, const CommandOptions& command) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t j = i;
    while (j < text.size() && is_identifier_char(text[j])) ++j;
    if (j == i) {
      out.push_back(text[i++]);
      continue;
    }
    const std::string word = text.substr(i, j - i);
    const Option* row = row_setting(word, scope, command);
    out += row != nullptr ? std::string("--") + row->name : word;
    i = j;
  }
  return out;
}

}  // namespace

std::string cli_message(const OptionError& error, Scope scope, const CommandOptions& command, const CommandLine& line,
                        bool with_value) {
  const Option* row = row_setting(error.option(), scope, command);
  if (row == nullptr) return error.option() + " " + in_cli_words(error.requirement(), scope, command);
  const auto typed = line.typed.find(row->name);
  const bool was_typed = typed != line.typed.end();
  std::string message = (was_typed ? typed->second.flag : std::string("--") + row->name) + " " +
                        in_cli_words(error.requirement(), scope, command);
  // The value typed, unless it only names the file the field was read from.
  const bool value_is_field = row->value != nullptr && std::string_view(row->value) != "FILE";
  if (with_value && was_typed && value_is_field) message += ", got '" + typed->second.value + "'";
  return message;
}

std::string cli_message(const OptionError& error, const CommandOptions& command, const CommandLine& line) {
  for (const Scope scope : {Scope::decomposition, Scope::mesh_size, Scope::svg, Scope::coast})
    if (row_setting(error.option(), scope, command) != nullptr) return cli_message(error, scope, command, line, false);
  return cli_message(error, Scope::decomposition, command, line, false);
}

}  // namespace madd::cli
