// `madd partition`: our bisector on a METIS graph file, head to head with
// gpmetis -ptype=rb. Writes GRAPH.part.K exactly as gpmetis does.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "command_line.hpp"
#include "commands.hpp"
#include "option_table.hpp"
#include "option_values.hpp"
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
  CommandLine line;  // -k, --ufactor, line.partition (--seed, --contig, --niter), --nooutput, --quiet
};

constexpr const char* partition_intro =
    "usage: madd partition GRAPH -k K [options]\n"
    "       madd partition [options] GRAPH K          (gpmetis-style)\n\n"
    "Partitions a METIS graph file into K parts by recursive bisection with madd's\n"
    "own multilevel bisector and writes GRAPH.part.K (one part id per line, as gpmetis).\n\n";

constexpr const char* partition_gpmetis =
    "\ngpmetis's spellings are accepted with one dash and '=' (or a space): -ufactor=U,\n"
    "-seed=S, -contig, -niter=N, -nooutput, -help, and the values that name what madd\n"
    "does anyway: -ptype=rb, -objtype=cut, -ctype=shem, -iptype=grow, -no2hop. Other\n"
    "values (-ptype=kway...) and -minconn, -tpwgts, -ubvec, -ncuts, -dbglvl are refused.\n";

std::string usage() {
  const std::string options = options_help(options_of("partition"));
  const std::string_view niter = "{niter}";  // the library's default, not a copy of it
  const std::size_t at = options.find(niter);
  std::string text = partition_intro;
  text.append(options, 0, at);
  text += std::to_string(PartitionOptions{}.refinement_passes);
  text.append(options, at + niter.size());
  text += partition_gpmetis;
  return text;
}

// gpmetis's options (METIS 5.1 gpmetis -help): the `supported` ones are
// madd's long options of the same name (the table's rows check the values of
// -ptype and the like); the others are refused by name, saying why.
struct GpmetisOption {
  const char* name;
  bool supported;
  const char* why;  // for the refused ones
};
constexpr GpmetisOption gpmetis_options[] = {
    {"ufactor", true, nullptr},
    {"seed", true, nullptr},
    {"contig", true, nullptr},
    {"niter", true, nullptr},
    {"nooutput", true, nullptr},
    {"help", true, nullptr},
    {"ptype", true, nullptr},
    {"objtype", true, nullptr},
    {"ctype", true, nullptr},
    {"iptype", true, nullptr},
    {"no2hop", true, nullptr},
    {"minconn", false, "it applies to -ptype=kway, which madd does not do"},
    {"tpwgts", false, "madd's parts all have the same target weight"},
    {"ubvec", false, "madd partitions single-constraint graphs only"},
    {"ncuts", false, "madd computes one partition (run it with other --seed values)"},
    {"dbglvl", false, "madd has no debug levels"},
};

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

int run_partition(void* context) {
  const auto& args = *static_cast<const PartitionArgs*>(context);
  const auto t0 = std::chrono::steady_clock::now();
  const Graph graph = read_metis_file(args.graph);
  const double read_s = seconds_since(t0);
  const std::uint32_t k = args.line.parts;
  PartitionOptions options = args.line.partition;
  const double levels = k > 1 ? std::ceil(std::log2(static_cast<double>(k))) : 1.0;
  options.balance_tolerance = std::pow(1.0 + static_cast<double>(args.line.ufactor) / 1000.0, 1.0 / levels) - 1.0;
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
  if (args.line.write_output) write_file_atomically(out_path, out);  // never leaves a partial file
  const double write_s = seconds_since(t2);
  if (args.line.quiet) return exit_ok;
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
  if (args.line.write_output) std::printf("wrote %s\n", out_path.c_str());
  return exit_ok;
}

int run(int argc, char** argv) {
  PartitionArgs args;
  CommandLine& line = args.line;
  std::vector<std::string> translated;
  if (const std::string problem = translate_gpmetis_options(argc, argv, translated); !problem.empty())
    return usage_error("partition", problem);
  if (const auto done = read_command_line(options_of("partition"), argc, argv, line, usage())) return *done;
  if (line.operands.empty() || line.operands.size() > 2) return usage_error("partition", "expected GRAPH [K]");
  args.graph = line.operands[0];
  if (line.operands.size() == 2) {
    unsigned long long value = 0;
    if (!parse_count(line.operands[1].c_str(), 1u << 30, value) || value == 0)
      return usage_error("partition", "bad part count '" + line.operands[1] + "'");
    if (line.parts != 0 && line.parts != value) return usage_error("partition", "-k and the positional K disagree");
    line.parts = static_cast<std::uint32_t>(value);
  }
  if (line.parts == 0) return usage_error("partition", "missing the number of parts (-k K or GRAPH K)");
  return run_guarded("partition", run_partition, &args);
}

const CommandRegistration registration({"partition", "partition a METIS graph file (gpmetis-compatible output)", run});

}  // namespace

}  // namespace madd::cli
