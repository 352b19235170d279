#pragma once
// The CLI's subcommands and exit codes. Each subcommand lives in its own
// cli/cmd_<name>.cpp and registers itself; main.cpp only dispatches.
#include <optional>
#include <string>

#include "madd/error.hpp"

namespace madd::cli {

// Exit codes, documented in `madd --help` and docs/cli.md.
enum ExitCode : int {
  exit_ok = 0,
  exit_usage = 2,             // bad command line
  exit_bad_input = 3,         // unreadable or invalid input file
  exit_decompose_failed = 4,  // no valid decomposition exists at these settings
  exit_io = 5,                // an output could not be written
  exit_limit = 6,             // --time-limit or --max-memory reached
  exit_internal = 70,         // a bug: an unexpected exception or failed self-check
};

using CommandFn = int (*)(int argc, char** argv);

struct Command {
  const char* name;
  const char* summary;  // one line for `madd --help`
  CommandFn run;        // argv[0] is the command name; getopt-style parsing inside
};

struct CommandRegistration {
  explicit CommandRegistration(Command command);
};

// The exit code of an error of this kind: the one place that decides it.
int exit_code_of(ErrorKind kind) noexcept;

// What an exception ending a command means to the user: its exit code and
// the message after "madd CMD: " ("error: ...", "internal error: ...").
struct Failure {
  int code = exit_ok;
  std::string message;
};

// The Failure of the exception being handled: madd's errors by their kind,
// std::bad_alloc as a limit (out of memory), anything else as a bug. Call it
// only inside a catch block (madd's run_guarded, madd-mpi's steps).
Failure current_failure() noexcept;

// Runs `body`, mapping madd's typed errors to exit codes and printing one
// "madd: message" line on stderr. Every subcommand wraps its work in this.
int run_guarded(const char* command, int (*body)(void*), void* context);

// Prints "madd <command>: message" on stderr and returns exit_usage.
int usage_error(const char* command, const std::string& message);

struct CommandLine;     // cli/command_line.hpp
struct CommandOptions;  // cli/option_table.hpp

// Reads the command line into `line` with the command's options. Returns the
// exit code when the command is done with it: a usage problem said (exit 2),
// or --help asked and `help` printed; nullopt when the command should run.
std::optional<int> read_command_line(const CommandOptions& options, int argc, char** argv, CommandLine& line,
                                     const std::string& help);
// The same for a command that takes one operand (its input): also a usage
// problem when there is not exactly one, "expected exactly <expected>".
std::optional<int> read_one_operand(const CommandOptions& options, int argc, char** argv, CommandLine& line,
                                    const std::string& help, const char* expected = "one input file");

const char* version_string() noexcept;

}  // namespace madd::cli
