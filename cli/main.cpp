// madd's entry point: global options, then dispatch to a subcommand.
// Decomposition is the default mode: `madd [options] INPUT.poly`.
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "commands.hpp"
#include "huge_pages.hpp"
#include "interrupts.hpp"
#include "option_table.hpp"
#include "madd/atomic_write.hpp"
#include "madd/error.hpp"

namespace madd::cli {

// Set by a command while it writes its outputs (cmd_decompose.cpp): an
// interrupt then never exits at once, so that a --split staging directory
// between two files is removed too.
volatile std::sig_atomic_t writing_outputs = 0;

namespace {
std::map<std::string, Command>& commands() {
  static std::map<std::string, Command> registry;
  return registry;
}

void print_help() {
  std::printf("madd %s - Medial Axis Domain Decomposition for parallel mesh generation\n\n"
              "usage: madd [options] INPUT.poly          decompose (the default mode; see madd decompose --help)\n"
              "       madd COMMAND [options] ARGS...\n"
              "       madd help [COMMAND] | --help | --version\n\n"
              "commands:\n",
              version_string());
  for (const auto& [name, command] : commands()) std::printf("  %-12s %s\n", name.c_str(), command.summary);
  std::printf("\nEach command takes --help (or: madd help COMMAND).\n\n"
              "exit codes:\n"
              "  0   success\n"
              "  2   usage error (bad command line)\n"
              "  3   bad input (unreadable, malformed or invalid file; the message says path:line:column)\n"
              "  4   decomposition failed (no split meets the minimum angle; names the subdomain)\n"
              "  5   an output file could not be written\n"
              "  6   a resource limit was reached\n"
              "  70  internal error (a bug: please report it with the input)\n");
}
// SIGINT/SIGTERM: nothing partial may stay on disk (docs/hostile.md). When
// no output is being written, exit at once (128 + signal): the result only
// lived in memory. Otherwise let write_file_atomically remove its temporary
// file and unwind (split staging directories are removed on the way out).
volatile std::sig_atomic_t interrupted_by = 0;
// On a terminal the message first clears the line (a progress note may be on it).
volatile std::sig_atomic_t stderr_is_terminal = 0;

void on_interrupt(int signal_number) {
  interrupted_by = signal_number;
  if (madd::interrupt_output_writes() || writing_outputs != 0) return;
  const char message[] = "\r\033[Kmadd: interrupted\n";
  const std::size_t skip = stderr_is_terminal != 0 ? 0 : 4;
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, message + skip, sizeof message - 1 - skip);
  ::_exit(128 + signal_number);
}

void install_interrupt_handlers() {
  stderr_is_terminal = ::isatty(STDERR_FILENO) == 1 ? 1 : 0;
  on_interrupts(on_interrupt);
}

int exit_after(int code) { return interrupted_by != 0 ? 128 + interrupted_by : code; }

// `madd help [COMMAND]`: the top-level help, or COMMAND's own --help.
int run_help(int argc, char** argv) {
  if (argc == 2) {
    print_help();
    return exit_ok;
  }
  const auto it = commands().find(argv[2]);
  if (argc != 3 || it == commands().end()) {
    if (argc == 3) std::fprintf(stderr, "madd: unknown command '%s' (try 'madd help')\n", argv[2]);
    else std::fprintf(stderr, "madd: usage: madd help [COMMAND]\n");
    return exit_usage;
  }
  char help_flag[] = "--help";
  char* help_argv[] = {argv[2], help_flag, nullptr};
  return it->second.run(2, help_argv);
}

// Levenshtein distance, for "did you mean".
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The command `word` is probably a typo of, or nullptr: only when `word` is
// no option, no existing file, has no .poly/.node ending, and is within 2
// edits (1 for names of up to 4 letters) of a command or of `help`.
const char* mistyped_command(const std::string& word) {
  if (word.empty() || word[0] == '-') return nullptr;
  for (const char* ext : {".poly", ".node"}) {
    const std::string e = ext;
    if (word.size() >= e.size() && word.compare(word.size() - e.size(), e.size(), e) == 0) return nullptr;
  }
  if (::access(word.c_str(), F_OK) == 0) return nullptr;
  const char* best = nullptr;
  std::size_t best_distance = word.size() <= 4 ? 2 : 3;
  const auto consider = [&](const char* name) {
    const std::size_t d = edit_distance(word, name);
    if (d < best_distance) {
      best_distance = d;
      best = name;
    }
  };
  for (const auto& entry : commands()) consider(entry.second.name);
  consider("help");
  return best;
}
}  // namespace

CommandRegistration::CommandRegistration(Command command) { commands()[command.name] = command; }

const char* version_string() noexcept {
#ifdef MADD_CLI_VERSION
  return MADD_CLI_VERSION;
#else
  return "0.1.0";
#endif
}

int usage_error(const char* command, const std::string& message) {
  std::fprintf(stderr, "madd %s: %s\n(try 'madd %s --help')\n", command, message.c_str(), command);
  return exit_usage;
}

std::optional<int> read_command_line(const CommandOptions& options, int argc, char** argv, CommandLine& line,
                                     const std::string& help) {
  if (const std::string problem = parse_command_line(options, argc, argv, line); !problem.empty())
    return usage_error(options.command, problem);
  if (!line.help) return std::nullopt;
  std::fputs(help.c_str(), stdout);
  return exit_ok;
}

std::optional<int> read_one_operand(const CommandOptions& options, int argc, char** argv, CommandLine& line,
                                    const std::string& help, const char* expected) {
  if (const auto done = read_command_line(options, argc, argv, line, help)) return done;
  if (line.operands.size() != 1) return usage_error(options.command, std::string("expected exactly ") + expected);
  return std::nullopt;
}

int run_guarded(const char* command, int (*body)(void*), void* context) {
  try {
    return body(context);
  } catch (...) {
    const Failure failure = current_failure();
    std::fprintf(stderr, "madd %s: %s\n", command, failure.message.c_str());
    return failure.code;
  }
}

}  // namespace madd::cli

int main(int argc, char** argv) {
  using namespace madd::cli;
  restart_with_huge_pages(argv);
  auto& registry = commands();
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    print_help();
    return argc < 2 ? exit_usage : exit_ok;
  }
  if (std::strcmp(argv[1], "--version") == 0 || std::strcmp(argv[1], "-V") == 0) {
    std::printf("madd %s\n", version_string());
    return exit_ok;
  }
  // `madd --script FILE` is `madd script FILE` (the paper's maddi mode, docs/script.md).
  if (std::strcmp(argv[1], "--script") == 0) argv[1] = const_cast<char*>("script");
  if (std::strcmp(argv[1], "help") == 0) return run_help(argc, argv);
  auto it = registry.find(argv[1]);
  if (it == registry.end()) {
    if (const char* guess = mistyped_command(argv[1])) {
      std::fprintf(stderr, "madd: unknown command '%s'; did you mean '%s'?\n", argv[1], guess);
      return exit_usage;
    }
  }
  install_interrupt_handlers();
  if (it != registry.end()) return exit_after(it->second.run(argc - 1, argv + 1));
  // Default mode: decomposition with the whole command line as its arguments.
  auto decompose = registry.find("decompose");
  if (decompose == registry.end()) {
    std::fprintf(stderr, "madd: unknown command '%s' (try 'madd --help')\n", argv[1]);
    return exit_usage;
  }
  argv[0] = const_cast<char*>("decompose");
  return exit_after(decompose->second.run(argc, argv));
}
