// `madd partition`: our bisector on a METIS graph file, head to head with
// gpmetis -ptype=rb. Writes GRAPH.part.K exactly as gpmetis does.
#include <getopt.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "commands.hpp"
#include "madd/atomic_write.hpp"
#include "madd/bisect.hpp"
#include "madd/error.hpp"
#include "madd/graph.hpp"
#include "madd/metis_io.hpp"

namespace madd::cli {

namespace {

struct PartitionArgs {
  std::string graph;
  unsigned long k = 0;
  long ufactor = 1;  // METIS's default for -ptype=rb: 1.001
  unsigned long long seed = 1;
  bool contig = false;
};

void print_usage() {
  std::printf(
      "usage: madd partition GRAPH -k K [--ufactor U] [--seed S] [--contig]\n"
      "       madd partition GRAPH K [options]          (gpmetis-style)\n\n"
      "Partitions a METIS graph file into K parts by recursive bisection with madd's\n"
      "own multilevel bisector and writes GRAPH.part.K (one part id per line, as gpmetis).\n\n"
      "  -k, --parts K      number of parts (>= 1)\n"
      "  -u, --ufactor U    allowed imbalance (1 + U/1000) of the largest part, as gpmetis;\n"
      "                     default 1 (gpmetis's default for -ptype=rb). For K > 2 each\n"
      "                     bisection gets (1 + U/1000)^(1/ceil(log2 K)).\n"
      "  -s, --seed S       random seed (default 1); same seed, same result\n"
      "  -c, --contig       make every part connected (when the graph is)\n"
      "  -h, --help         this text\n");
}

bool parse_unsigned(const char* text, unsigned long long max, unsigned long long& out) {
  if (text == nullptr || *text == '\0' || *text == '-') return false;
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text, &end, 10);
  if (errno != 0 || *end != '\0' || v > max) return false;
  out = v;
  return true;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int run_partition(void* context) {
  const auto& args = *static_cast<const PartitionArgs*>(context);
  const auto t0 = std::chrono::steady_clock::now();
  const Graph graph = read_metis_file(args.graph);
  const double read_s = seconds_since(t0);
  const auto k = static_cast<std::uint32_t>(args.k);
  PartitionOptions options;
  const double levels = k > 1 ? std::ceil(std::log2(static_cast<double>(k))) : 1.0;
  options.imbalance_tolerance = std::pow(1.0 + static_cast<double>(args.ufactor) / 1000.0, 1.0 / levels) - 1.0;
  options.seed = args.seed;
  options.connected = args.contig;
  const auto t1 = std::chrono::steady_clock::now();
  const std::clock_t c1 = std::clock();
  const Partition p = partition(graph, k, options);
  const double part_s = seconds_since(t1);
  // CPU seconds too: gpmetis reports CPU time, which a loaded machine does not inflate.
  const double part_cpu = static_cast<double>(std::clock() - c1) / CLOCKS_PER_SEC;
  const auto t2 = std::chrono::steady_clock::now();
  std::string out;
  out.reserve(graph.vertex_count() * 3);
  for (const std::uint32_t id : p.part) {
    out += std::to_string(id);
    out += '\n';
  }
  const std::string out_path = args.graph + ".part." + std::to_string(k);
  write_file_atomically(out_path, out);  // never leaves a partial file
  const double write_s = seconds_since(t2);
  double total = 0.0, heaviest = 0.0;
  for (const double w : p.part_weights) {
    total += w;
    heaviest = std::max(heaviest, w);
  }
  const double balance = total > 0.0 ? heaviest / (total / static_cast<double>(k)) : 1.0;
  std::printf("graph: %s (%zu vertices, %zu edges), %u parts\n", args.graph.c_str(), graph.vertex_count(),
              graph.edge_count(), k);
  std::printf("cut: %.17g\nbalance: %.4f\n", p.cut, balance);
  std::printf("time: read %.3f s, partition %.3f s (cpu %.3f s), write %.3f s\n", read_s, part_s, part_cpu, write_s);
  std::printf("wrote %s\n", out_path.c_str());
  return exit_ok;
}

int run(int argc, char** argv) {
  static const option long_options[] = {{"parts", required_argument, nullptr, 'k'},
                                        {"ufactor", required_argument, nullptr, 'u'},
                                        {"seed", required_argument, nullptr, 's'},
                                        {"contig", no_argument, nullptr, 'c'},
                                        {"help", no_argument, nullptr, 'h'},
                                        {nullptr, 0, nullptr, 0}};
  PartitionArgs args;
  unsigned long long value = 0;
  optind = 0;
  int opt = 0;
  while ((opt = getopt_long(argc, argv, "k:u:s:ch", long_options, nullptr)) != -1) {
    switch (opt) {
    case 'k':
      if (!parse_unsigned(optarg, 1u << 30, value) || value == 0) return usage_error("partition", "bad -k value");
      args.k = static_cast<unsigned long>(value);
      break;
    case 'u':
      if (!parse_unsigned(optarg, 1000000, value)) return usage_error("partition", "bad --ufactor value");
      args.ufactor = static_cast<long>(value);
      break;
    case 's':
      if (!parse_unsigned(optarg, ~0ull, value)) return usage_error("partition", "bad --seed value");
      args.seed = value;
      break;
    case 'c': args.contig = true; break;
    case 'h': print_usage(); return exit_ok;
    default: return usage_error("partition", "unknown option");
    }
  }
  const int positional = argc - optind;
  if (positional < 1 || positional > 2) return usage_error("partition", "expected GRAPH [K]");
  args.graph = argv[optind];
  if (positional == 2) {
    if (!parse_unsigned(argv[optind + 1], 1u << 30, value) || value == 0)
      return usage_error("partition", "bad part count '" + std::string(argv[optind + 1]) + "'");
    if (args.k != 0 && args.k != value) return usage_error("partition", "-k and the positional K disagree");
    args.k = static_cast<unsigned long>(value);
  }
  if (args.k == 0) return usage_error("partition", "missing the number of parts (-k K or GRAPH K)");
  return run_guarded("partition", run_partition, &args);
}

const CommandRegistration registration({"partition", "partition a METIS graph file (gpmetis-compatible output)", run});

} // namespace

} // namespace madd::cli
