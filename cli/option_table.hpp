#pragma once
// The one option table of madd and madd-mpi (docs/cli.md): every option once,
// with its flags, the field it sets, how its value is read and what a bad one
// is told; and which commands take it, with what help. Commands only parse
// (ranges and conflicts are the library's check_options); a message names the
// flag as the user typed it, long or short.
#include <span>
#include <string>
#include <string_view>

#include "command_line.hpp"
#include "madd/error.hpp"

namespace madd::cli {

enum class Arity { none, required, optional };

// Which of the library's option structs holds a row's field, so that an
// OptionError of its check_options (which names the field) finds the flag;
// `front_end` for what only the front end holds.
enum class Scope { front_end, decomposition, mesh_size, svg, coast };

// Reads `value` (nullptr for an option without one) into the command line;
// returns "" or the problem, said with `flag` as typed ("-j needs a whole number").
using Setter = std::string (*)(CommandLine& line, const char* value, const std::string& flag);

// One row of the table.
struct Option {
  const char* name;  // the long flag without "--": "min-angle"
  char letter;       // the short flag ('n' for -n), 0 without one; a command may not take it (Letter)
  Arity arity;
  const char* value;  // the value's name in the help ("DEG"), nullptr without a value
  Scope scope;
  const char* field;  // the field it sets, as OptionError::option() names it; nullptr if none
  Setter set;
};

// Every row, in no particular order; names are unique.
std::span<const Option> option_table();
// The row named `name`, nullptr when none is.
const Option* find_option(std::string_view name);

// How a command takes a row's letter: as the row has it, not at all (the
// letter means something else there, or nothing), or still, but only as a
// deprecated spelling its help mentions and no longer shows beside the flag.
enum class Letter { usual, none, deprecated };

// One line of a command's option list: an option of the table with this
// command's help for it (lines separated by '\n'), or, without a name, a
// line of text of the help (a heading, or "" for a blank line).
struct OptionUse {
  const char* name;
  const char* help;  // nullptr: the option has no line (the help's own text names it)
  Letter letter = Letter::usual;
  const char* value = nullptr;  // this command's name of the value, when not the row's
};

// A command's options, in the order of its help.
struct CommandOptions {
  const char* command;  // "decompose", "mesh" (madd-mpi's too), "partition", "script", "check", "triangulate"
  std::span<const OptionUse> uses;
  int column;  // where an option's help starts in the help text
};

// The options of `command`; throws std::out_of_range for a command without any.
const CommandOptions& options_of(std::string_view command);
// Every command's.
std::span<const CommandOptions> command_options();

// The letter `use` has in its command: 0 when it takes none.
char letter_of(const OptionUse& use);

// The help text of every line of the command's list:
// "  -n, --subdomains N     number of subdomains (default 2)".
std::string options_help(const CommandOptions& command);

// Parses argv (argv[0] is the command name; options and operands in any
// order, "--" ends the options) into `line`, in order, stopping at --help.
// Returns "" or the usage problem. An option named in `declined` is one the
// command knows but does not take here ("is not available here").
std::string parse_command_line(const CommandOptions& command, int argc, char** argv, CommandLine& line,
                               std::span<const char* const> declined = {});

// An OptionError of the library's check in `scope` said with the command's
// flags: the field it names as the flag that sets it (as typed, when it was),
// the fields its requirement names as their long flags; with ", got 'VALUE'"
// when `with_value` and the option was typed. A field no option of the
// command sets keeps its name.
std::string cli_message(const OptionError& error, Scope scope, const CommandOptions& command, const CommandLine& line,
                        bool with_value = true);

// The same for an OptionError thrown from inside a run (a check that needs
// the domain: an area function's values, the coast markers), where the
// check's scope is not known: the first scope in which one of the command's
// rows sets the field it names; without the value typed.
std::string cli_message(const OptionError& error, const CommandOptions& command, const CommandLine& line);

}  // namespace madd::cli
