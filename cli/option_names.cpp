#include "option_names.hpp"

#include <cctype>

namespace madd::cli {

namespace {
// Every field OptionError::option() can name, with the flag that sets it.
struct CliName {
  const char* field;
  const char* flag;
};
constexpr CliName cli_names[] = {
    {"subdomains", "--subdomains"},          {"separator_angle_deg", "--min-angle"},
    {"boundary_refinement", "--refine"},                  {"min_split_quality", "--imbalance"},
    {"threads", "--threads"},                {"seed", "--seed"},
    {"smoothing_iterations", "--smoothing"}, {"repair_balance_above", "--rebalance"}, {"adaptive_boundary_refinement", "--adaptive-refine"}, {"gradation", "--gradation"},
    {"interpolation", "--interpolation"},    {"weight_function", "--weight-fn"},
    {"subdomain_area_function", "--area-fn"},          {"weight_samples", "--weights"},
    {"subdomain_area_samples", "--areas"},         {"subdomain_area_ratio", "--area-bound"},
    {"time_limit_seconds", "--time-limit"},  {"max_memory_bytes", "--max-memory"},
    {"mark_angles_below_deg", "--svg-mark-angles"},
};

} // namespace

const char* cli_name_of(const std::string& field) {
  for (const CliName& n : cli_names)
    if (field == n.field) return n.flag;
  return nullptr;
}

namespace {
bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

} // namespace

std::string in_cli_words(const std::string& text) {
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
    const char* flag = cli_name_of(word);
    out += flag != nullptr ? flag : word;
    i = j;
  }
  return out;
}

std::string cli_message(const OptionError& e) {
  const char* flag = cli_name_of(e.option());
  return std::string(flag != nullptr ? flag : e.option().c_str()) + " " + in_cli_words(e.requirement());
}

} // namespace madd::cli
