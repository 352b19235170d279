// Output 2 on disk: one .poly per subdomain, staged so that a failure never
// leaves a partial set of files (docs/formats.md).
#include <algorithm>
#include <filesystem>
#include <system_error>
#include <unistd.h>

#include "madd/atomic_write.hpp"
#include "madd/error.hpp"
#include "madd/output.hpp"

namespace madd {

namespace fs = std::filesystem;

namespace {

// "<stem>-<digits>.poly": a file an earlier run of write_split may have made.
bool is_split_name(const std::string& name, std::string_view stem) {
  const std::string prefix = std::string(stem) + "-";
  if (name.size() <= prefix.size() + 5 || name.compare(0, prefix.size(), prefix) != 0) return false;
  if (name.compare(name.size() - 5, 5, ".poly") != 0) return false;
  for (std::size_t i = prefix.size(); i + 5 < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

fs::path staging_path(const fs::path& dir) {
  fs::path parent = dir.parent_path();
  if (parent.empty()) parent = ".";
  const std::string base = dir.filename().string();
  for (int attempt = 0;; ++attempt) {
    fs::path candidate = parent / ("." + base + ".madd-tmp-" + std::to_string(::getpid()) + "-" + std::to_string(attempt));
    if (!fs::exists(candidate)) return candidate;
  }
}

// Moves the staged files into an existing `dir`, then removes stale split files.
void publish_into(const fs::path& staging, const fs::path& dir, std::string_view stem,
                  const std::vector<std::string>& names) {
  for (const std::string& name : names) fs::rename(staging / name, dir / name);
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (is_split_name(name, stem) && std::find(names.begin(), names.end(), name) == names.end())
      stale.push_back(entry.path());
  }
  for (const fs::path& p : stale) fs::remove(p);
  fs::remove_all(staging);
}

} // namespace

void write_split(const Decomposition& d, const std::string& dir_name, std::string_view stem) {
  fs::path dir = fs::path(dir_name).lexically_normal();
  if (dir.filename().empty() && dir.has_parent_path()) dir = dir.parent_path();  // "parts/" names "parts"
  const auto count = static_cast<std::uint32_t>(d.subdomains.size());
  std::vector<std::string> names;
  for (std::uint32_t k = 0; k < count; ++k) names.push_back(split_file_name(stem, k, count));
  fs::path staging;
  try {
    if (fs::exists(dir) && !fs::is_directory(dir)) throw OutputError(dir_name + ": exists and is not a directory");
    if (!dir.parent_path().empty()) fs::create_directories(dir.parent_path());
    staging = staging_path(dir);
    fs::create_directory(staging);
    for (std::uint32_t k = 0; k < count; ++k)
      write_file_atomically((staging / names[k]).string(), format_subdomain_poly(d, k));
    if (fs::exists(dir))
      publish_into(staging, dir, stem, names);
    else
      fs::rename(staging, dir);
  } catch (const fs::filesystem_error& e) {
    std::error_code ignored;
    if (!staging.empty()) fs::remove_all(staging, ignored);
    throw OutputError(dir_name + ": cannot write the split files: " + e.code().message());
  } catch (...) {
    std::error_code ignored;
    if (!staging.empty()) fs::remove_all(staging, ignored);
    throw;
  }
}

} // namespace madd
