// Malloc's heaps on transparent huge pages, with slack (cli/huge_pages.hpp):
// when the programs start themselves again with glibc.malloc.hugetlb=1 and
// glibc.malloc.top_pad, and that a mesh is the same byte for byte either way.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli/huge_pages.hpp"

using madd::cli::tunables_for_huge_pages;

namespace {
constexpr const char* advised = "always [madvise] never\n";

// What is added besides the huge pages: the heap's slack and the mmap threshold.
const std::string slack = std::string("glibc.malloc.top_pad=") + madd::cli::heap_slack +
                          ":glibc.malloc.mmap_threshold=" + madd::cli::mmap_threshold;
const std::string both = "glibc.malloc.hugetlb=1:" + slack;
}  // namespace

TEST_CASE("huge pages: the tunables are added where the kernel takes advice and nobody chose otherwise") {
  CHECK(tunables_for_huge_pages(nullptr, nullptr, nullptr, advised) == both);
  CHECK(tunables_for_huge_pages("", nullptr, nullptr, advised) == both);
  // The user's own tunables are kept, in front.
  CHECK(tunables_for_huge_pages("glibc.malloc.arena_max=2", nullptr, nullptr, advised) ==
        "glibc.malloc.arena_max=2:" + both);
  // Any opt-out value but "0" leaves it on; preloads other than valgrind's too.
  CHECK(tunables_for_huge_pages(nullptr, "1", "/usr/lib/libfoo.so", advised) == both);
  // Each one the user did not name: the slack with the user's huge pages, and the other way.
  CHECK(tunables_for_huge_pages("glibc.malloc.hugetlb=0", nullptr, nullptr, advised) ==
        "glibc.malloc.hugetlb=0:" + slack);
  CHECK(tunables_for_huge_pages("glibc.malloc.top_pad=0", nullptr, nullptr, advised) ==
        std::string("glibc.malloc.top_pad=0:glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=") +
            madd::cli::mmap_threshold);
  CHECK(tunables_for_huge_pages("glibc.malloc.mmap_threshold=1048576", nullptr, nullptr, advised) ==
        std::string("glibc.malloc.mmap_threshold=1048576:glibc.malloc.hugetlb=1:glibc.malloc.top_pad=") +
            madd::cli::heap_slack);
  // The kernel gives huge pages to all (always), to none (never), or says
  // nothing: the heap's slack still pays.
  CHECK(tunables_for_huge_pages(nullptr, nullptr, nullptr, "[always] madvise never\n") == slack);
  CHECK(tunables_for_huge_pages(nullptr, nullptr, nullptr, "always madvise [never]\n") == slack);
  CHECK(tunables_for_huge_pages(nullptr, nullptr, nullptr, nullptr) == slack);
  CHECK(tunables_for_huge_pages(nullptr, nullptr, nullptr, "") == slack);
}

TEST_CASE("huge pages: nothing to do, so no second start") {
  // Both there already: the user's choice (on or off), or this very restart.
  CHECK_FALSE(tunables_for_huge_pages(both.c_str(), nullptr, nullptr, advised));
  CHECK_FALSE(tunables_for_huge_pages("glibc.malloc.hugetlb=0:glibc.malloc.top_pad=0:glibc.malloc.mmap_threshold=0",
                                      nullptr, nullptr, advised));
  CHECK_FALSE(tunables_for_huge_pages(("glibc.malloc.arena_max=2:" + both).c_str(), nullptr, nullptr, advised));
  // The slack there, and no huge pages to be had.
  CHECK_FALSE(tunables_for_huge_pages(slack.c_str(), nullptr, nullptr, "[always] madvise never\n"));
  CHECK_FALSE(tunables_for_huge_pages(slack.c_str(), nullptr, nullptr, nullptr));
  // Asked not to.
  CHECK_FALSE(tunables_for_huge_pages(nullptr, "0", nullptr, advised));
  // Under valgrind an exec would run the program outside the tool.
  CHECK_FALSE(tunables_for_huge_pages(
      nullptr, nullptr, "/usr/libexec/valgrind/vgpreload_core-amd64-linux.so:/usr/libexec/x.so", advised));
}

#ifdef MADD_CLI_PATH

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("huge pages: madd mesh writes the same files with and without them, and is started once more only") {
  const fs::path dir = fs::temp_directory_path() / ("madd-huge-pages-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string mesh = "'" MADD_CLI_PATH "' mesh '" MADD_DATA_DIR "/archipelago.poly' -n 8 -q 30 -a 0.002 -j 2";
  // GLIBC_TUNABLES unset: the program may start itself again (where the
  // kernel takes advice); MADD_HUGE_PAGES=0: it may not.
  const std::string on = "cd '" + dir.string() + "' && env -u GLIBC_TUNABLES -u MADD_HUGE_PAGES " + mesh + " -o on";
  const std::string off = "cd '" + dir.string() + "' && env MADD_HUGE_PAGES=0 " + mesh + " -o off";
  REQUIRE(std::system(on.c_str()) == 0);
  REQUIRE(std::system(off.c_str()) == 0);
  for (const char* ext : {".node", ".ele"}) {
    const std::string a = slurp(dir / (std::string("on") + ext)), b = slurp(dir / (std::string("off") + ext));
    CHECK(!a.empty());
    CHECK(a == b);
  }
  // A failing run fails the same way after the restart (its exit code and
  // message reach the caller, once).
  const std::string bad = "cd '" + dir.string() +
                          "' && env -u GLIBC_TUNABLES -u MADD_HUGE_PAGES '" MADD_CLI_PATH
                          "' mesh missing.poly -n 2 2> err.txt";
  CHECK(WEXITSTATUS(std::system(bad.c_str())) == 3);
  const std::string err = slurp(dir / "err.txt");
  CHECK(err.find("missing.poly") != std::string::npos);
  CHECK(err.find("missing.poly", err.find("missing.poly") + 1) == std::string::npos);
  fs::remove_all(dir);
}

#endif
