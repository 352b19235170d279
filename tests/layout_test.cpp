// The house rule of docs/design.md, "Source layout: one folder per stage":
// src/ has one folder per pipeline stage, listed in the design's table in
// pipeline order, and a stage includes only from the stages before it (and
// its own). This test reads the order from the table itself and every
// `#include "<stage>/..."` of src/, so a new include that runs back up the
// pipeline, or a stage folder missing from the table, fails here with the
// file and line.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path source_root = MADD_SOURCE_DIR;

// The stage folders in the order of the table in docs/design.md: rows "| `src/<name>/` | ...".
std::vector<std::string> stage_order() {
  std::ifstream in(source_root / "docs/design.md");
  const std::regex row(R"(^\| `src/([a-z_]+)/` \|)");
  std::vector<std::string> stages;
  std::string line;
  std::smatch m;
  while (std::getline(in, line))
    if (std::regex_search(line, m, row)) stages.push_back(m[1]);
  return stages;
}

std::vector<fs::path> sources_under(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".cpp" || ext == ".hpp")) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_SUITE("layout") {

TEST_CASE("docs/design.md lists every stage folder of src/ once") {
  const std::vector<std::string> stages = stage_order();
  REQUIRE(stages.size() >= 10);
  for (const auto& e : fs::directory_iterator(source_root / "src")) {
    if (!e.is_directory()) continue;
    const std::string name = e.path().filename().string();
    CAPTURE(name);
    CHECK(std::count(stages.begin(), stages.end(), name) == 1);
  }
  CHECK(stages.front() == "kernel");
}

TEST_CASE("no include of src/ runs back up the pipeline") {
  const std::vector<std::string> stages = stage_order();
  const auto rank = [&](const std::string& stage) {
    return static_cast<long>(std::find(stages.begin(), stages.end(), stage) - stages.begin());
  };
  const std::regex include(R"(^\s*#\s*include\s+"([a-z_]+)/[^"]+")");
  std::size_t includes = 0;
  for (const fs::path& file : sources_under(source_root / "src")) {
    const std::string stage = file.parent_path().filename().string();
    std::ifstream in(file);
    std::string line;
    std::smatch m;
    for (int number = 1; std::getline(in, line); ++number) {
      if (!std::regex_search(line, m, include) || m[1] == "madd") continue;
      ++includes;
      const std::string where = fs::relative(file, source_root).string() + ":" + std::to_string(number);
      CAPTURE(where);
      CAPTURE(line);
      CHECK(rank(m[1]) < static_cast<long>(stages.size()));  // a stage of the table
      CHECK(rank(m[1]) <= rank(stage));                      // the same stage or one before it
    }
  }
  CHECK(includes > 100);  // the scan saw the tree
}

}  // TEST_SUITE("layout")
