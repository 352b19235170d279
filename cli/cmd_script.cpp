// `madd script FILE` (also `madd --script FILE`): runs a script of the
// paper's maddi commands (Sec. 6, Table II; docs/script.md). `-` reads stdin.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>

#include "command_line.hpp"
#include "commands.hpp"
#include "option_table.hpp"
#include "madd/error.hpp"
#include "madd/script.hpp"

namespace madd::cli {
namespace {

constexpr const char* script_intro =
    "usage: madd script [options] FILE      (or: madd --script FILE)\n\n"
    "Runs the commands of FILE ('-' for stdin), one per line, as the paper's maddi\n"
    "interface does. Example:\n\n"
    "  read pipe.poly\n"
    "  set f=0.35\n"
    "  dec 400\n"
    "  write pipe400.poly\n"
    "  writeSubdomains pipe400.dat\n"
    "  exit\n\n"
    "commands:\n"
    "  read FILE              read a domain (.poly or .node)\n"
    "  dec [N]                decompose it into N subdomains (default: set n=, else 2)\n"
    "  write FILE [all]       the decomposition as one .poly; with 'all', one .poly per\n"
    "                         subdomain in FILE's directory, named <FILE stem>-<k>.poly\n"
    "  writeSubdomains FILE   the paper's subdomain file\n"
    "  read_weights FILE      background density weights (.node, first attribute)\n"
    "  read_areas FILE        background required areas (.node, first attribute)\n"
    "  setWeightFunction EXPR a density weight function of x, y, r (or 'none')\n"
    "  setAreaFunction EXPR   a required area function of x, y, r (or 'none')\n"
    "  set NAME=VALUE ...     f (min angle / pi), r, a, p, i, s, ratio, n, j, seed\n"
    "  exit                   stop\n\n"
    "'#' starts a comment. Relative file names are relative to the current directory.\n"
    "Options may also follow FILE; a FILE whose name starts with '-' follows '--'.\n"
    "Every decomposition is self-checked before any file is written.\n\n"
    "options:\n";

constexpr const char* script_exit_codes =
    "\nexit codes: 0 success, 2 usage error or bad option value, 3 bad script or input (script:line:column),\n"
    "4 no valid decomposition, 5 an output could not be written, 70 internal error\n";

struct ScriptArgs {
  std::string file;
  bool quiet = false;
};

std::string read_script(const std::string& file) {
  if (file == "-") {
    std::ostringstream text;
    text << std::cin.rdbuf();
    return std::move(text).str();
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputFileError(file + ": cannot open: " + std::strerror(errno));
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

int script_body(void* context) {
  const auto& args = *static_cast<ScriptArgs*>(context);
  const std::string text = read_script(args.file);  // unreadable: InputFileError, bad input like a bad domain
  ScriptContext script;
  if (!args.quiet) script.log = [](const std::string& line) { std::printf("%s\n", line.c_str()); };
  run_script(text, args.file == "-" ? "<stdin>" : args.file, script);
  return exit_ok;
}

int run_script_command(int argc, char** argv) {
  // Options may follow the file, as for every command; '-' (stdin) is not an
  // option, and a script whose name starts with '-' follows '--'.
  const CommandOptions& options = options_of("script");
  CommandLine line;
  if (const auto done =
          read_one_operand(options, argc, argv, line, script_intro + options_help(options) + script_exit_codes,
                           "one script file (or '-' for stdin)"))
    return *done;
  ScriptArgs args{line.operands.front(), line.quiet};
  return run_guarded("script", script_body, &args);
}

const CommandRegistration registration({"script", "run a script of maddi commands (read, set, dec, write...)",
                                        run_script_command});

}  // namespace
}  // namespace madd::cli
