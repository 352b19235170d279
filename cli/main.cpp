// madd's entry point: global options, then dispatch to a subcommand.
// Decomposition is the default mode: `madd [options] INPUT.poly`.
#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <new>
#include <string>

#include "commands.hpp"
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
  std::printf(
      "madd %s - Medial Axis Domain Decomposition for parallel mesh generation\n\n"
      "usage: madd [options] INPUT.poly          decompose (the default mode; see madd decompose --help)\n"
      "       madd COMMAND [options] ARGS...\n"
      "       madd --help | --version\n\n"
      "commands:\n",
      version_string());
  for (const auto& [name, command] : commands()) std::printf("  %-12s %s\n", name.c_str(), command.summary);
  std::printf(
      "\nEach command takes --help.\n\n"
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

void on_interrupt(int signal_number) {
  interrupted_by = signal_number;
  if (madd::interrupt_output_writes() || writing_outputs != 0) return;
  const char message[] = "madd: interrupted\n";
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(128 + signal_number);
}

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int exit_after(int code) { return interrupted_by != 0 ? 128 + interrupted_by : code; }
} // namespace

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

namespace {
// The exit code for a madd::Error, from its most specific type.
int exit_code_of(const Error& e) {
  if (dynamic_cast<const ParseError*>(&e) || dynamic_cast<const InvalidInputError*>(&e) ||
      dynamic_cast<const InputFileError*>(&e))
    return exit_bad_input;
  if (dynamic_cast<const DecompositionError*>(&e)) return exit_decompose_failed;
  if (dynamic_cast<const LimitError*>(&e)) return exit_limit;
  if (dynamic_cast<const InternalError*>(&e)) return exit_internal;
  return exit_io;  // OutputError, and any other failure to produce an output
}
} // namespace

int run_guarded(const char* command, int (*body)(void*), void* context) {
  try {
    return body(context);
  } catch (const Error& e) {
    const int code = exit_code_of(e);
    std::fprintf(stderr, "madd %s: %s: %s\n", command, code == exit_internal ? "internal error" : "error", e.what());
    return code;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "madd %s: error: out of memory\n", command);
    return exit_limit;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "madd %s: internal error: %s\n", command, e.what());
    return exit_internal;
  }
}

} // namespace madd::cli

int main(int argc, char** argv) {
  using namespace madd::cli;
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
  auto it = registry.find(argv[1]);
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
