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
#include <vector>

#include "commands.hpp"
#include "seconds.hpp"
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
  int niter = PartitionOptions{}.refinement_passes;
  bool quiet = false;
  bool write_output = true;  // -nooutput: partition and report, write nothing
};

void print_usage() {
  std::printf(
      "usage: madd partition GRAPH -k K [options]\n"
      "       madd partition [options] GRAPH K          (gpmetis-style)\n\n"
      "Partitions a METIS graph file into K parts by recursive bisection with madd's\n"
      "own multilevel bisector and writes GRAPH.part.K (one part id per line, as gpmetis).\n\n"
      "  -k, --parts K      number of parts (>= 1)\n"
      "  -u, --ufactor U    allowed imbalance (1 + U/1000) of the largest part, as gpmetis;\n"
      "                     default 1 (gpmetis's default for -ptype=rb). For K > 2 each\n"
      "                     bisection gets (1 + U/1000)^(1/ceil(log2 K)).\n"
      "  -s, --seed S       random seed (default 1); same seed, same result\n"
      "  -c, --contig       make every part connected (when the graph is)\n"
      "      --niter N      FM refinement passes per level, 0 to 1000 (default %d)\n"
      "      --nooutput     write no GRAPH.part.K, only print the figures\n"
      "  -q, --quiet        print nothing on success\n"
      "  -h, --help         this text\n\n"
      "gpmetis's spellings are accepted with one dash and '=' (or a space): -ufactor=U,\n"
      "-seed=S, -contig, -niter=N, -nooutput, -help, and the values that name what madd\n"
      "does anyway: -ptype=rb, -objtype=cut, -ctype=shem, -iptype=grow, -no2hop. Other\n"
      "values (-ptype=kway...) and -minconn, -tpwgts, -ubvec, -ncuts, -dbglvl are refused.\n",
      PartitionOptions{}.refinement_passes);
}

// gpmetis's options (METIS 5.1 gpmetis -help): `supported` ones become madd's
// long option of the same name; `only` is the one value madd takes (naming
// what it does anyway); the unsupported ones are refused by name.
struct GpmetisOption {
  const char* name;
  bool supported;
  const char* only;  // nullptr: any value (checked by the long option)
  const char* why;   // for the refused ones
};
constexpr GpmetisOption gpmetis_options[] = {
    {"ufactor", true, nullptr, nullptr},
    {"seed", true, nullptr, nullptr},
    {"contig", true, nullptr, nullptr},
    {"niter", true, nullptr, nullptr},
    {"nooutput", true, nullptr, nullptr},
    {"help", true, nullptr, nullptr},
    {"ptype", true, "rb", "madd partitions by recursive bisection only (-ptype=rb)"},
    {"objtype", true, "cut", "madd minimises the edge cut only (-objtype=cut)"},
    {"ctype", true, "shem", "madd coarsens by heavy-edge matching only (-ctype=shem)"},
    {"iptype", true, "grow", "madd's initial bisection is greedy graph growing only (-iptype=grow)"},
    {"no2hop", true, nullptr, nullptr},
    {"minconn", false, nullptr, "it applies to -ptype=kway, which madd does not do"},
    {"tpwgts", false, nullptr, "madd's parts all have the same target weight"},
    {"ubvec", false, nullptr, "madd partitions single-constraint graphs only"},
    {"ncuts", false, nullptr, "madd computes one partition (run it with other --seed values)"},
    {"dbglvl", false, nullptr, "madd has no debug levels"},
};

// The problem with value `value` of gpmetis's option `name`, which madd only
// takes with the value it names what madd does (-ptype=rb...); empty if none.
std::string gpmetis_value_problem(const std::string& name, const std::string& value) {
  for (const GpmetisOption& option : gpmetis_options)
    if (name == option.name && option.only != nullptr && value != option.only)
      return "-" + name + "=" + value + " is not supported: " + option.why;
  return {};
}

// Rewrites gpmetis's single-dash options (-ufactor=30, -ufactor 30) into
// madd's long ones (--ufactor=30), in place, before getopt sees them.
// Returns an error message for a refused one, or for an unknown -word=value.
std::string translate_gpmetis_options(int argc, char** argv, std::vector<std::string>& storage) {
  storage.reserve(static_cast<std::size_t>(argc));
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;
    if (arg.size() < 3 || arg[0] != '-' || arg[1] == '-') continue;
    const std::string name = arg.substr(1, arg.find('=') - 1);
    const GpmetisOption* known = nullptr;
    for (const GpmetisOption& option : gpmetis_options)
      if (name == option.name) known = &option;
    if (known == nullptr) {
      if (arg.find('=') != std::string::npos) return "unknown option '" + arg + "'";
      continue;  // short options (-k8, -cq...)
    }
    if (!known->supported) return "gpmetis option -" + name + " is not supported: " + known->why;
    storage.push_back("-" + arg);
    argv[i] = storage.back().data();
  }
  return {};
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
  options.refinement_passes = args.niter;
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
  if (args.write_output) write_file_atomically(out_path, out);  // never leaves a partial file
  const double write_s = seconds_since(t2);
  if (args.quiet) return exit_ok;
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
  if (args.write_output) std::printf("wrote %s\n", out_path.c_str());
  return exit_ok;
}

enum LongOnly : int { opt_niter = 256, opt_nooutput, opt_ptype, opt_objtype, opt_ctype, opt_iptype, opt_no2hop };

int run(int argc, char** argv) {
  static const option long_options[] = {{"parts", required_argument, nullptr, 'k'},
                                        {"ufactor", required_argument, nullptr, 'u'},
                                        {"seed", required_argument, nullptr, 's'},
                                        {"contig", no_argument, nullptr, 'c'},
                                        {"niter", required_argument, nullptr, opt_niter},
                                        {"nooutput", no_argument, nullptr, opt_nooutput},
                                        {"quiet", no_argument, nullptr, 'q'},
                                        {"help", no_argument, nullptr, 'h'},
                                        // gpmetis's: only the values naming what madd does
                                        {"ptype", required_argument, nullptr, opt_ptype},
                                        {"objtype", required_argument, nullptr, opt_objtype},
                                        {"ctype", required_argument, nullptr, opt_ctype},
                                        {"iptype", required_argument, nullptr, opt_iptype},
                                        {"no2hop", no_argument, nullptr, opt_no2hop},
                                        {nullptr, 0, nullptr, 0}};
  PartitionArgs args;
  unsigned long long value = 0;
  std::vector<std::string> translated;
  if (const std::string problem = translate_gpmetis_options(argc, argv, translated); !problem.empty())
    return usage_error("partition", problem);
  optind = 0;
  opterr = 0;
  int opt = 0;
  while ((opt = getopt_long(argc, argv, ":k:u:s:cqh", long_options, nullptr)) != -1) {
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
    case opt_niter:
      if (!parse_unsigned(optarg, 1000, value)) return usage_error("partition", "--niter needs a whole number in [0, 1000]");
      args.niter = static_cast<int>(value);
      break;
    case opt_nooutput: args.write_output = false; break;
    case 'q': args.quiet = true; break;
    case opt_ptype: case opt_objtype: case opt_ctype: case opt_iptype: {
      const char* name = opt == opt_ptype ? "ptype" : opt == opt_objtype ? "objtype" : opt == opt_ctype ? "ctype" : "iptype";
      if (const std::string problem = gpmetis_value_problem(name, optarg); !problem.empty())
        return usage_error("partition", problem);
      break;  // the value names what madd does
    }
    case opt_no2hop: break;  // madd never matches two hops away
    case 'h': print_usage(); return exit_ok;
    case ':': return usage_error("partition", std::string("option '") + argv[optind - 1] + "' needs a value");
    default: {
      const std::string element = optind > 0 && optind <= argc ? argv[optind - 1] : "";
      if (element.rfind("--", 0) == 0) {
        const std::string name = element.substr(2, element.find('=') - 2);
        for (const option* o = long_options; o->name != nullptr; ++o)
          if (name == o->name) return usage_error("partition", "option '" + element.substr(0, element.find('=')) + "' takes no value");
        return usage_error("partition", "unknown option '" + element + "'");
      }
      return usage_error("partition", std::string("unknown option '-") + static_cast<char>(optopt) + "'");
    }
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
