#pragma once
// Internals of run_script (include/madd/script.hpp): one parsed command line
// and the commands that execute it, split over script*.cpp.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "madd/error.hpp"
#include "madd/script.hpp"

namespace madd::detail {

struct ScriptWord {
  std::string text;        // without the quotes of a "quoted word"
  std::size_t column = 1;  // 1-based column of its first character
};

// One non-empty line of a script, comment removed.
struct ScriptCommand {
  std::string script;  // the script's name, for messages
  std::size_t line = 0;
  std::vector<ScriptWord> words;  // words[0] is the command
  std::string rest;               // the raw text after the command word, trimmed
  std::size_t rest_column = 1;    // column of rest's first character (end of line when empty)
  std::size_t end_column = 1;     // column just past the last character

  // Throws ParseError(script, line, column, message).
  [[noreturn]] void fail(std::size_t column, const std::string& message) const;
  // Throws OptionError(option, message) located at script:line:column (a bad option, not bad input).
  [[noreturn]] void fail_option(std::size_t column, const std::string& option, const std::string& message) const;
  // Fails unless the command has between min and max arguments (words after the command).
  void expect_arguments(std::size_t min, std::size_t max, const char* usage) const;
  // "script:line: " for wrapping errors of the library.
  std::string prefix() const;
};

// Rethrows `error` as the same madd error type with "script:line: " in front;
// a ParseError keeps its type and is located at `column` of the script line.
[[noreturn]] void rethrow_located(const ScriptCommand& command, std::size_t column, const Error& error);

// Runs f(), relocating any madd::Error it throws to the script line.
template <class F>
auto located_call(const ScriptCommand& command, std::size_t column, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const Error& e) {
    rethrow_located(command, column, e);
  }
}

// How the script names a DecomposeOptions field ("a (gradation)", "setAreaFunction").
std::string script_name_of(const std::string& field);

// Control characters shown as '?', so a message stays one readable line.
std::string printable(std::string_view text);

// The commands of Table II (commands.cpp, set.cpp).
void script_read(const ScriptCommand& c, ScriptContext& context);
void script_read_values(const ScriptCommand& c, ScriptContext& context, bool areas);
void script_dec(const ScriptCommand& c, ScriptContext& context);
void script_write(const ScriptCommand& c, ScriptContext& context);
void script_write_subdomains(const ScriptCommand& c, ScriptContext& context);
void script_set_function(const ScriptCommand& c, ScriptContext& context, bool areas);
void script_set(const ScriptCommand& c, ScriptContext& context);

}  // namespace madd::detail
