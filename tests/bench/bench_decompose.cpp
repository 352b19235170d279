// madd_bench decompose [--phi DEG] [--threads T,T..] [--verify] FILE.poly... N...
// Times decompose() per file, N and thread count (wall and process CPU
// seconds), and prints the C1/C3 figures; --verify runs verify_decomposition.
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench.hpp"
#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"

namespace {

std::vector<unsigned> parse_list(const char* text) {
  std::vector<unsigned> out;
  for (const char* p = text; *p != '\0';) {
    char* end = nullptr;
    out.push_back(static_cast<unsigned>(std::strtoul(p, &end, 10)));
    p = (*end == ',') ? end + 1 : end;
    if (end == p && *p != '\0') break;
  }
  return out;
}

// One decompose() call, timed, with its figures on one line.
void run_one(const std::string& file, const madd::Pslg& domain, unsigned n, unsigned threads, double phi, bool verify) {
  madd::DecomposeOptions options;
  options.subdomains = n;
  options.separator_angle_deg = phi;
  options.threads = threads;
  const double start = madd::bench::now_seconds();
  const std::clock_t cpu_start = std::clock();
  const madd::Decomposition d = madd::decompose(domain, options);
  const double seconds = madd::bench::now_seconds() - start;
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const madd::Metrics m = madd::metrics(d);
  std::printf("%-24s %6u %3u %9.4f %9.4f %8.2f %8.2f %8.2f %8.3f\n", file.substr(file.rfind('/') + 1).c_str(), n,
              threads, seconds, cpu, m.angle_min, m.angle_median, m.boundary_angle_median, m.max_area_over_mean);
  if (verify) {
    const madd::Verification v = madd::verify_decomposition(d, domain, n);
    for (const auto& p : v.problems) std::printf("  PROBLEM: %s\n", p.c_str());
  }
  std::fflush(stdout);
}

int run(int argc, char** argv) {
  double phi = 60.0;
  std::vector<unsigned> threads = {1};
  bool verify = false;
  std::vector<std::string> files;
  std::vector<unsigned> counts;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--phi") == 0 && i + 1 < argc) {
      phi = std::atof(argv[++i]);
    } else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
      threads = parse_list(argv[++i]);
    } else if (std::strcmp(argv[i], "--verify") == 0) {
      verify = true;
    } else if (std::strspn(argv[i], "0123456789") == std::strlen(argv[i])) {
      counts.push_back(static_cast<unsigned>(std::atoi(argv[i])));
    } else {
      files.push_back(argv[i]);
    }
  }
  if (files.empty() || counts.empty()) {
    std::fprintf(stderr, "usage: madd_bench decompose [--phi DEG] [--threads 1,2] [--verify] FILE.poly... N...\n");
    return 2;
  }
  std::printf("%-24s %6s %3s %9s %9s %8s %8s %8s %8s\n", "file", "N", "thr", "wall_s", "cpu_s", "min_ang", "med_ang",
              "bnd_med", "max/mean");
  try {
    for (const std::string& file : files) {
      const madd::Pslg domain = madd::read_domain(file);
      for (unsigned n : counts) {
        for (unsigned t : threads) run_one(file, domain, n, t, phi, verify);
      }
    }
  } catch (const madd::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}

const madd::bench::Registration reg("decompose", run);

}  // namespace
