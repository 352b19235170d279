#pragma once
// Scratch files for tests: a fresh directory under the system temp dir,
// removed at scope exit, and a file read whole.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <system_error>

namespace madd::test {

struct TempDir {
  std::filesystem::path path;
  // The directory is named after `tag` and the process, so parallel test
  // processes and tests of one process never share one.
  explicit TempDir(const std::string& tag)
      : path(std::filesystem::temp_directory_path() / ("madd-test-" + tag + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  // The names of the entries of `dir`.
  std::set<std::string> names(const std::filesystem::path& dir) const {
    std::set<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(dir)) out.insert(e.path().filename().string());
    return out;
  }
};

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace madd::test
