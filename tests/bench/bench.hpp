#pragma once
// A tiny registry so each benchmark lives in its own file:
//   static const madd::bench::Registration reg("triangulate", run_triangulate);
// `madd_bench NAME [args...]` runs one, `madd_bench` lists them.
#include <chrono>
#include <string>

namespace madd::bench {

using BenchFn = int (*)(int argc, char** argv);

struct Registration {
  Registration(const char* name, BenchFn fn);
};

// Wall-clock seconds since an arbitrary origin.
inline double now_seconds() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

// Peak resident set size of this process so far, in bytes (Linux, /proc).
long long peak_rss_bytes();

}  // namespace madd::bench
