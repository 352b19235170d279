#pragma once
// Keyword arguments as the CLI's options (docs/python.md, "Options"): a
// Python keyword is the C++ options struct's field the option table's row
// sets (`min_triangle_angle_deg` for `-q`), its value is read by that row's
// own setter, its ranges are checked by the library's check_options, and
// its help is the CLI's help for that command. So madd.mesh(..., **kw)
// and `madd mesh` take the same options and mean the same mesh.
#include <pybind11/pybind11.h>

#include <string>
#include <string_view>

#include "../command_line.hpp"
#include "../option_table.hpp"

namespace madd::python {

namespace py = pybind11;

// The keyword a row is spelled as in Python, nullptr for a row Python does
// not take as a keyword (files, reports, --help; the writers are methods).
const char* keyword_of(const cli::Option& row);

// The keywords a Python function takes: those of a CLI command's rows,
// and, with `also`, the decomposition's rows of that command too (madd.mesh
// takes every DecomposeOptions field, `madd mesh` a few).
struct Keywords {
  const char* function;  // "mesh", for messages
  const cli::CommandOptions& command;
  const cli::CommandOptions* also = nullptr;
};

// Sets `line` from `values` (keyword = value) as the rows set it. A keyword
// the function does not take raises TypeError, as Python does for an
// unexpected keyword; a value its row refuses raises madd.OptionError.
// Array and callable values (samples, size functions) are the caller's to
// take out first: they never reach the table.
void apply_keywords(cli::CommandLine& line, const Keywords& keywords, const py::dict& values);

// One keyword, as apply_keywords sets it (the named arguments q, max_area, threads).
void apply_keyword(cli::CommandLine& line, const Keywords& keywords, const char* name, py::handle value);

// The library's check of the line's options (decomposition, mesh size),
// raised as madd.OptionError said with the keywords as typed.
void check_keywords(const cli::CommandLine& line, const cli::CommandOptions& command, bool sizes_given,
                    bool depth_given);

// An OptionError of the library said in Python's words: the keyword that
// sets its field, as typed, and its value.
OptionError in_python_words(const OptionError& error, const cli::CommandLine& line, const cli::CommandOptions& command);

// The keywords of `command` with the CLI's help for each, for a docstring.
std::string keywords_help(const cli::CommandOptions& command, const cli::CommandOptions* also = nullptr);

}  // namespace madd::python
