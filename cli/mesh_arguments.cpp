// The command line of `madd mesh` and `madd-mpi mesh` (cli/mesh_arguments.hpp).
#include "mesh_arguments.hpp"

#include <getopt.h>

#include <algorithm>
#include <string>
#include <thread>

#include "option_names.hpp"
#include "option_values.hpp"
#include "madd/decomposition.hpp"
#include "madd/expression.hpp"

namespace madd::cli {

namespace {

enum LongOnly : int { opt_min_angle = 256, opt_seed, opt_size_fn, opt_sizes, opt_balance, opt_no_off_centres, opt_msh,
                      opt_vtu, opt_split_mesh, opt_report, opt_quiet, opt_time_limit, opt_max_memory, opt_neigh, opt_edge, opt_rebalance, opt_no_verify };

std::string apply_option(int c, const char* arg, MeshArgs& args) {
  double x = 0;
  unsigned long long k = 0;
  MeshOptions& o = args.options;
  switch (c) {
  case 'q':
    if (!parse_number(arg, x)) return "-q needs degrees";
    o.size.min_triangle_angle_deg = x;
    return {};
  case 'a':
    if (!parse_number(arg, x) || !(x > 0)) return "-a needs an area > 0";
    o.size.max_triangle_area = x;
    return {};
  case opt_size_fn:
    try {
      o.size.triangle_area_function = parse_expression(arg, "--size-fn").function();
    } catch (const Error& e) {
      return e.what();
    }
    return {};
  case opt_sizes: args.sizes_file = arg; return {};
  case opt_balance:
    if (std::string(arg) == "work") o.balance_by_work = true;
    else if (std::string(arg) == "area") o.balance_by_work = false;
    else return "--balance takes 'work' or 'area'";
    return {};
  case opt_no_off_centres: o.off_centres = false; return {};
  case opt_no_verify: o.verify = false; return {};
  case 'n':
    if (!parse_count(arg, 0xFFFFFFFFull, k) || k == 0) return "-n needs a whole number >= 1";
    o.decomposition.subdomains = static_cast<std::uint32_t>(k);
    args.subdomains_given = true;
    return {};
  case opt_min_angle:
    if (!parse_number(arg, x)) return "--min-angle needs degrees";
    o.decomposition.separator_angle_deg = x;
    return {};
  case 'j':
    if (!parse_count(arg, 4096, k)) return "-j needs a whole number in [0, 4096]";
    o.decomposition.threads = static_cast<unsigned>(k);
    return {};
  case opt_seed:
    if (!parse_count(arg, ~0ull, k)) return "--seed needs a whole number";
    o.decomposition.seed = k;
    return {};
  case opt_rebalance:
    if (!parse_number(arg, x)) return "--rebalance needs a number";
    o.decomposition.repair_balance_above = x;
    return {};
  case opt_time_limit:
    if (!parse_number(arg, x) || x < 0) return "--time-limit needs seconds >= 0";
    o.decomposition.time_limit_seconds = x;
    return {};
  case opt_max_memory:
    if (!parse_number(arg, x) || x < 0 || x > 1e12) return "--max-memory needs megabytes in [0, 1e12]";
    o.decomposition.max_memory_bytes = static_cast<std::size_t>(x * 1048576.0);
    return {};
  case 'o': args.prefix = arg; return {};
  case opt_msh: args.formats.msh = true; return {};
  case opt_neigh: args.formats.neigh = true; return {};
  case opt_edge: args.formats.edge = true; return {};
  case opt_vtu: args.formats.vtu = true; return {};
  case opt_split_mesh: args.split_dir = arg; return {};
  case opt_report:
    args.report = true;
    args.report_out = arg ? arg : "";
    return {};
  case opt_quiet: args.quiet = true; return {};
  default: return "unknown option";
  }
}

bool is_extra_format(int c) { return c == opt_neigh || c == opt_edge || c == opt_msh || c == opt_split_mesh; }

// Said with the CLI's names of the mesh options.
std::string option_problem(const OptionError& e) {
  const std::string field = e.option();
  const char* name = field == "min_triangle_angle_deg" ? "-q" : field == "max_triangle_area" ? "-a" : field == "triangle_area_samples" ? "--sizes" : cli_name_of(field);
  return name ? std::string(name) + " " + e.requirement() : std::string(e.what());
}

} // namespace

std::string parse_mesh_arguments(int argc, char** argv, MeshArgs& args, bool require_subdomains, bool extra_formats) {
  static const option long_options[] = {
      {"quality", required_argument, nullptr, 'q'},
      {"max-area", required_argument, nullptr, 'a'},
      {"size-fn", required_argument, nullptr, opt_size_fn},
      {"sizes", required_argument, nullptr, opt_sizes},
      {"balance", required_argument, nullptr, opt_balance},
      {"no-off-centres", no_argument, nullptr, opt_no_off_centres},
      {"no-verify", no_argument, nullptr, opt_no_verify},
      {"subdomains", required_argument, nullptr, 'n'},
      {"min-angle", required_argument, nullptr, opt_min_angle},
      {"threads", required_argument, nullptr, 'j'},
      {"seed", required_argument, nullptr, opt_seed},
      {"time-limit", required_argument, nullptr, opt_time_limit},
      {"rebalance", required_argument, nullptr, opt_rebalance},
      {"max-memory", required_argument, nullptr, opt_max_memory},
      {"output", required_argument, nullptr, 'o'},
      {"msh", no_argument, nullptr, opt_msh},
      {"neigh", no_argument, nullptr, opt_neigh},
      {"edge", no_argument, nullptr, opt_edge},
      {"vtu", no_argument, nullptr, opt_vtu},
      {"split-mesh", required_argument, nullptr, opt_split_mesh},
      {"report", optional_argument, nullptr, opt_report},
      {"quiet", no_argument, nullptr, opt_quiet},
      {"help", no_argument, nullptr, 'h'},
      {nullptr, 0, nullptr, 0}};
  optind = 0;
  opterr = 0;
  int c;
  while ((c = getopt_long(argc, argv, ":q:a:n:j:o:h", long_options, nullptr)) != -1) {
    if (c == 'h') return "help";
    if (c == '?') return std::string("unknown option '") + argv[optind - 1] + "'";
    if (c == ':') return std::string("option '") + argv[optind - 1] + "' needs a value";
    if (!extra_formats && is_extra_format(c))
      return std::string("option '") + argv[optind - 1] + "' is not available here (see --help)";
    const std::string problem = apply_option(c, optarg, args);
    if (!problem.empty()) return problem + (optarg ? std::string(", got '") + optarg + "'" : "");
  }
  if (optind + 1 != argc) return "expected exactly one input file";
  args.input = argv[optind];
  if (!args.subdomains_given) {
    if (require_subdomains) return "-n N is required (the mesh depends on N, and must not depend on the rank count)";
    const unsigned t = args.options.decomposition.threads ? args.options.decomposition.threads
                                                           : std::max(1u, std::thread::hardware_concurrency());
    args.options.decomposition.subdomains = 4 * t;
  }
  if (args.prefix.empty()) {
    args.prefix = args.input;
    if (args.prefix.size() > 5 && args.prefix.compare(args.prefix.size() - 5, 5, ".poly") == 0)
      args.prefix.resize(args.prefix.size() - 5);
  }
  try {
    check_options(args.options.decomposition);
    check_options(args.options);
  } catch (const OptionError& e) {
    return option_problem(e);
  }
  return {};
}

} // namespace madd::cli
