#include "bench.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string>

namespace madd::bench {

namespace {
std::map<std::string, BenchFn>& registry() {
  static std::map<std::string, BenchFn> benches;
  return benches;
}
}  // namespace

Registration::Registration(const char* name, BenchFn fn) { registry()[name] = fn; }

long long peak_rss_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stoll(line.substr(6)) * 1024;
  }
  return -1;
}

}  // namespace madd::bench

int main(int argc, char** argv) {
  auto& benches = madd::bench::registry();
  if (argc < 2 || benches.find(argv[1]) == benches.end()) {
    std::fprintf(stderr, "usage: madd_bench NAME [args...]\nbenchmarks:\n");
    for (const auto& [name, fn] : benches) std::fprintf(stderr, "  %s\n", name.c_str());
    return argc < 2 ? 0 : 2;
  }
  return benches.at(argv[1])(argc - 1, argv + 1);
}
