#pragma once
// Running the madd binary in a scratch directory of its own, for the tests
// that check the CLI from the outside (MADD_CLI_PATH, set when it is built).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#ifdef MADD_CLI_PATH

namespace madd_test {

struct CliRun {
  int status = -1;
  std::string output;  // stdout and stderr together
};

class CliSandbox {
public:
  explicit CliSandbox(const std::string& name = "madd-cli-options")
      : dir_(std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(dir_);
  }
  ~CliSandbox() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  CliSandbox(const CliSandbox&) = delete;
  CliSandbox& operator=(const CliSandbox&) = delete;
  std::filesystem::path path(const std::string& name) const { return dir_ / name; }

  CliRun run(const std::string& arguments) const {
    const std::filesystem::path log = dir_ / "log";
    const std::string command = std::string("cd '") + dir_.string() + "' && '" + MADD_CLI_PATH + "' " + arguments +
                                " > '" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(log);
    std::ostringstream text;
    text << in.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
  }

private:
  std::filesystem::path dir_;
};

}  // namespace madd_test

#endif
