// madd_bench mesh [-n N] [-q DEG] [-a AREA] [-j T,T..] [--runs R]
//                 [--triangle PATH] [--csv FILE] FILE.poly...
// The meshing benchmark of issue 14: madd::mesh() (the library call, the
// file read once beforehand) on each file and thread count, R times; prints
// the median wall time of the call, the triangle count, triangles per second
// and the median time of each phase of the MeshReport. With --triangle, the
// Triangle binary at PATH (a peer, run by path, never built in) meshes the
// same file with `PATH -pq<q>a<a>Q file` in a temporary directory, R times,
// in the same run; its median wall time (fork to exit, file output included)
// and triangle count (the header of file.1.ele) are printed alongside.
// Exit status: 0 when every run succeeded, 1 otherwise, 2 on bad usage.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "bench.hpp"
#include "madd/mesh.hpp"
#include "madd/poly_io.hpp"

namespace {

namespace fs = std::filesystem;

const char* const usage = "usage: madd_bench mesh [-n N] [-q DEG] [-a AREA] [-j T,T..] [--runs R]\n"
                          "                       [--triangle PATH] [--csv FILE] FILE.poly...\n";

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::vector<unsigned> parse_list(const char* s) {
  std::vector<unsigned> out;
  std::string text(s);
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const long k = std::atol(item.c_str());
    if (k <= 0) return {};
    out.push_back(static_cast<unsigned>(k));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

// The shortest decimal text that reads back as x, never in exponent form
// (Triangle's switch parser takes only digits and '.').
std::string shortest(double x) {
  for (int digits = 1; digits <= 17; ++digits) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*g", digits, x);
    if (std::strtod(b, nullptr) == x && !std::strpbrk(b, "eE")) return b;
  }
  for (int decimals = 0; decimals <= 60; ++decimals) {
    char b[128];
    std::snprintf(b, sizeof b, "%.*f", decimals, x);
    if (std::strtod(b, nullptr) == x) return b;
  }
  char b[128];
  std::snprintf(b, sizeof b, "%.60f", x);
  return b;
}

struct PeerResult {
  bool ok = false;
  double seconds = 0.0;  // median
  long long triangles = 0;
  std::string switches;
  std::string error;
};

// Runs `triangle -pq<q>a<a>Q name.poly` in a fresh temporary directory holding
// a copy of the file, `runs` times; the time of each run is from fork to exit.
PeerResult run_triangle(const std::string& binary, const std::string& poly, double q, double a, int runs) {
  PeerResult result;
  char pattern[] = "/tmp/madd_bench_mesh_XXXXXX";
  if (!mkdtemp(pattern)) {
    result.error = "mkdtemp failed";
    return result;
  }
  const fs::path dir = pattern;
  const fs::path copy = dir / "domain.poly";
  std::error_code ec;
  fs::copy_file(poly, copy, ec);
  if (ec) {
    result.error = "cannot copy " + poly + ": " + ec.message();
    fs::remove_all(dir, ec);
    return result;
  }
  const std::string switches = "-pq" + shortest(q) + (a > 0 ? "a" + shortest(a) : std::string()) + "Q";
  result.switches = switches;
  const std::string absolute = fs::absolute(binary).string();
  std::vector<double> times;
  for (int r = 0; r < runs; ++r) {
    fs::remove(dir / "domain.1.node", ec);
    fs::remove(dir / "domain.1.ele", ec);
    fs::remove(dir / "domain.1.poly", ec);
    std::fflush(stdout);
    const double t0 = madd::bench::now_seconds();
    const pid_t pid = fork();
    if (pid == 0) {
      if (chdir(dir.c_str()) != 0) _exit(127);
      execl(absolute.c_str(), absolute.c_str(), switches.c_str(), "domain.poly", static_cast<char*>(nullptr));
      _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    times.push_back(madd::bench::now_seconds() - t0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      result.error = "triangle " + switches + " failed (status " + std::to_string(status) + ")";
      fs::remove_all(dir, ec);
      return result;
    }
  }
  std::ifstream ele(dir / "domain.1.ele");
  if (!(ele >> result.triangles)) {
    result.error = "no domain.1.ele written";
  } else {
    result.ok = true;
    result.seconds = median(times);
  }
  fs::remove_all(dir, ec);
  return result;
}

struct Row {
  std::string file;
  unsigned threads = 0;
  double seconds = 0.0;
  std::size_t triangles = 0;
  std::vector<std::pair<std::string, double>> phases;  // medians, in report order
  PeerResult peer;
  bool has_peer = false;
};

int run_mesh(int argc, char** argv) {
  madd::MeshOptions options;
  options.decomposition.subdomains = 16;
  options.size.min_triangle_angle_deg = 30.0;
  std::vector<unsigned> thread_counts{1};
  int runs = 3;
  std::string triangle, csv;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "-n" && has_value) {
      const long k = std::atol(argv[++i]);
      if (k < 1) return std::fprintf(stderr, "%s", usage), 2;
      options.decomposition.subdomains = static_cast<std::uint32_t>(k);
    } else if (arg == "-q" && has_value) {
      options.size.min_triangle_angle_deg = std::atof(argv[++i]);
    } else if (arg == "-a" && has_value) {
      options.size.max_triangle_area = std::atof(argv[++i]);
    } else if (arg == "-j" && has_value) {
      thread_counts = parse_list(argv[++i]);
      if (thread_counts.empty()) return std::fprintf(stderr, "%s", usage), 2;
    } else if (arg == "--runs" && has_value) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--triangle" && has_value) {
      triangle = argv[++i];
    } else if (arg == "--csv" && has_value) {
      csv = argv[++i];
    } else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "unknown option %s\n%s", arg.c_str(), usage);
      return 2;
    } else {
      files.push_back(arg);
    }
  }
  if (files.empty()) return std::fprintf(stderr, "%s", usage), 2;

  int status = 0;
  std::vector<Row> rows;
  std::printf("mesh: N %u, q %g, a %g, %d runs (medians)\n", options.decomposition.subdomains,
              options.size.min_triangle_angle_deg, options.size.max_triangle_area, runs);
  std::printf("%-24s %3s %10s %9s %11s  %s\n", "domain", "j", "triangles", "wall s", "tris/s", "phases (s)");
  for (const std::string& file : files) {
    madd::Pslg domain;
    try {
      domain = madd::read_domain(file);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", file.c_str(), e.what());
      status = 1;
      continue;
    }
    const std::string name = fs::path(file).stem().string();
    for (const unsigned threads : thread_counts) {
      Row row;
      row.file = name;
      row.threads = threads;
      options.decomposition.threads = threads;
      std::vector<double> times;
      std::map<std::string, std::vector<double>> phase_times;
      std::vector<std::string> phase_order;
      try {
        for (int r = 0; r < runs; ++r) {
          const double t0 = madd::bench::now_seconds();
          const madd::MeshRun run = madd::mesh_with_report(domain, options);
          const madd::Mesh& m = run.mesh;
          const madd::MeshReport& report = run.report;
          times.push_back(madd::bench::now_seconds() - t0);
          row.triangles = m.triangle_count();
          for (const madd::PhaseTime& p : report.phases) {
            if (!phase_times.count(p.name)) phase_order.push_back(p.name);
            phase_times[p.name].push_back(p.seconds);
          }
        }
      } catch (const std::exception& e) {
        std::fprintf(stderr, "%s, %u threads: %s\n", file.c_str(), threads, e.what());
        status = 1;
        continue;
      }
      row.seconds = median(times);
      for (const std::string& p : phase_order) row.phases.emplace_back(p, median(phase_times[p]));
      std::string phases;
      for (const auto& [p, s] : row.phases) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s%s %.3f", phases.empty() ? "" : ", ", p.c_str(), s);
        phases += buf;
      }
      std::printf("%-24s %3u %10zu %9.3f %11.0f  %s\n", name.c_str(), threads, row.triangles, row.seconds,
                  static_cast<double>(row.triangles) / row.seconds, phases.c_str());
      std::fflush(stdout);
      rows.push_back(row);
    }
    if (!triangle.empty()) {
      const PeerResult peer =
          run_triangle(triangle, file, options.size.min_triangle_angle_deg, options.size.max_triangle_area, runs);
      if (!peer.ok) {
        std::fprintf(stderr, "%s: %s\n", file.c_str(), peer.error.c_str());
        status = 1;
      } else {
        std::printf("%-24s %3s %10lld %9.3f %11.0f  (Triangle %s)\n", name.c_str(), "T", peer.triangles, peer.seconds,
                    static_cast<double>(peer.triangles) / peer.seconds, peer.switches.c_str());
        for (Row& r : rows) {
          if (r.file == name) {
            r.peer = peer;
            r.has_peer = true;
          }
        }
      }
      std::fflush(stdout);
    }
  }

  if (!csv.empty()) {
    std::FILE* out = std::fopen(csv.c_str(), "w");
    if (!out) {
      std::fprintf(stderr, "cannot write %s\n", csv.c_str());
      return 1;
    }
    std::fprintf(out, "domain,n,q,a,threads,triangles,seconds,triangles_per_second,phases,"
                      "triangle_triangles,triangle_seconds\n");
    for (const Row& r : rows) {
      std::string phases;
      for (const auto& [p, s] : r.phases) phases += (phases.empty() ? "" : ";") + p + "=" + shortest(s);
      std::fprintf(out, "%s,%u,%g,%g,%u,%zu,%.6f,%.0f,%s,", r.file.c_str(), options.decomposition.subdomains,
                   options.size.min_triangle_angle_deg, options.size.max_triangle_area, r.threads, r.triangles,
                   r.seconds, static_cast<double>(r.triangles) / r.seconds, phases.c_str());
      if (r.has_peer) std::fprintf(out, "%lld,%.6f\n", r.peer.triangles, r.peer.seconds);
      else std::fprintf(out, ",\n");
    }
    std::fclose(out);
  }
  return status;
}

const madd::bench::Registration reg("mesh", run_mesh);

}  // namespace
