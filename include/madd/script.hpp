#pragma once
// The command language of the paper's `maddi` interface (Sec. 6, Tables II
// and III): `read`, `set f=0.35`, `dec 400`, `write`, `exit`... Functions are
// given as expressions (madd/expression.hpp) instead of shared libraries.
// The language is described in docs/script.md.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "madd/decomposition.hpp"
#include "madd/pslg.hpp"

namespace madd {

// The state a script works on; it lives across run_script calls, so a caller
// can preload a domain or options, or run a script in several pieces.
struct ScriptContext {
  // false: read, read_weights, read_areas, write and writeSubdomains fail
  // with an Error instead of touching the file system (sandboxing, fuzzing).
  bool allow_files = true;
  // `dec N` with N above this fails with an Error; 0 = no limit.
  std::uint32_t max_subdomains = 0;
  // Called with the options just before each `dec`; may throw an Error to
  // refuse them (a sandbox bounding refinement or threads). Empty = accept.
  std::function<void(const DecomposeOptions&)> check_options;
  // Receives one line per command that did something ("read pipe.poly: ...").
  // Empty = silent.
  std::function<void(const std::string&)> log;

  DecomposeOptions options;              // changed by set, read_weights, setWeightFunction...
  std::optional<Pslg> domain;            // set by `read` (or preloaded by the caller)
  std::string domain_name = "<domain>";  // the file it came from, for messages
  // The result of the last `dec`; reset by `read`. `verified` caches its
  // verify_decomposition check, which every write command needs first.
  std::optional<Decomposition> decomposition;
  std::uint32_t requested_subdomains = 0;  // N of the last `dec`
  bool verified = false;
};

struct ScriptResult {
  std::size_t commands = 0;  // commands executed (comments and blank lines excluded)
  bool exited = false;       // the script ended with `exit`
  friend bool operator==(const ScriptResult&, const ScriptResult&) = default;
};

// Runs the commands of `text` in order until `exit` or the end of the text.
// Relative file names are relative to the process's current directory.
// Every error names the script and the line: the script's own problems
// (unknown command, unknown parameter, write before dec) are ParseError(name,
// line, column); a value out of its range (`set f=0`, `dec 0`) or options
// that contradict each other are OptionError, located the same way and
// naming the parameter as the script spells it; a failing command's error
// is rethrown with the same kind and type, "name:line: " before its message.
// `read` starts a fresh domain: the background weights and areas of the
// previous one are cleared (`read_weights none` / `read_areas none` clear
// them explicitly). Commands before the failing one keep their effects
// (files written stay written; none is ever partial). Before any output is
// written the decomposition must pass verify_decomposition; if it does not,
// an InternalError (a bug) is thrown and nothing is written.
ScriptResult run_script(std::string_view text, const std::string& name, ScriptContext& context);

}  // namespace madd
