#pragma once
// How the CLI says the library's option errors: check_options names a field
// of DecomposeOptions (or SvgOptions), "separator_angle_deg"; the user typed
// "--min-angle". Front ends parse and print; the library decides (docs/cli.md).
#include <string>

#include "madd/error.hpp"

namespace madd::cli {

// The flag of a field ("--min-angle" for "separator_angle_deg"), nullptr when none.
const char* cli_name_of(const std::string& field);

// `text` with every whole-word field name replaced by its flag.
std::string in_cli_words(const std::string& text);

// "--min-angle must lie strictly between 0 and 90 degrees".
std::string cli_message(const OptionError& e);

} // namespace madd::cli
