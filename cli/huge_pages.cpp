// Starting again with malloc's heaps on transparent huge pages (huge_pages.hpp).
#include "huge_pages.hpp"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

namespace madd::cli {

namespace {
constexpr const char* huge_tunable = "glibc.malloc.hugetlb";
constexpr const char* slack_tunable = "glibc.malloc.top_pad";
constexpr const char* mmap_tunable = "glibc.malloc.mmap_threshold";
}  // namespace

std::optional<std::string> tunables_for_huge_pages(const char* tunables, const char* opt_out, const char* ld_preload,
                                                   const char* thp_enabled) {
  if (opt_out != nullptr && std::strcmp(opt_out, "0") == 0) return std::nullopt;
  if (ld_preload != nullptr && std::strstr(ld_preload, "vgpreload") != nullptr) return std::nullopt;
  const auto named = [tunables](const char* name) {
    return tunables != nullptr && std::strstr(tunables, name) != nullptr;
  };
  const bool advised = thp_enabled != nullptr && std::strstr(thp_enabled, "[madvise]") != nullptr;
  std::string added;
  if (advised && !named(huge_tunable)) added += std::string(huge_tunable) + "=1";
  if (!named(slack_tunable)) added += (added.empty() ? "" : ":") + std::string(slack_tunable) + "=" + heap_slack;
  if (!named(mmap_tunable)) added += (added.empty() ? "" : ":") + std::string(mmap_tunable) + "=" + mmap_threshold;
  if (added.empty()) return std::nullopt;
  return tunables != nullptr && *tunables != '\0' ? std::string(tunables) + ":" + added : added;
}

void restart_with_huge_pages(char** argv) {
#if defined(__linux__) && defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 35)) &&        \
    !defined(__SANITIZE_ADDRESS__)
  std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
  const std::string thp((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::optional<std::string> tunables =
      tunables_for_huge_pages(std::getenv("GLIBC_TUNABLES"), std::getenv("MADD_HUGE_PAGES"), std::getenv("LD_PRELOAD"),
                              file ? thp.c_str() : nullptr);
  if (!tunables) return;
  // The real path, not /proc/self/exe, so that argv[0] and the program's
  // own idea of where it lives stay as they were.
  char path[4096];
  const ssize_t n = ::readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) return;
  path[n] = '\0';
  const char* before = std::getenv("GLIBC_TUNABLES");
  const bool had_tunables = before != nullptr;
  const std::string old = had_tunables ? before : "";
  if (::setenv("GLIBC_TUNABLES", tunables->c_str(), 1) != 0) return;
  ::execv(path, argv);
  // The exec failed: go on with small pages, the environment as it was.
  if (had_tunables) {
    ::setenv("GLIBC_TUNABLES", old.c_str(), 1);
  } else {
    ::unsetenv("GLIBC_TUNABLES");
  }
#else
  (void)argv;
#endif
}

}  // namespace madd::cli
