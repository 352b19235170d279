// `madd check FILE.poly`: read and validate a domain, print a summary.
#include <getopt.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "commands.hpp"
#include "madd/poly_io.hpp"
#include "madd/pslg.hpp"

namespace madd::cli {
namespace {

constexpr const char* check_help =
    "usage: madd check [options] FILE.poly\n\n"
    "Reads and validates a domain (Triangle .poly, or .node) and prints a summary:\n"
    "vertices, segments, holes, regions, area, bounding box and shortest segment.\n\n"
    "options:\n"
    "  -q, --quiet   print nothing on success; only the exit code tells\n"
    "  -h, --help    this text\n\n"
    "exit codes: 0 valid, 2 usage error, 3 bad input (one line: path:line:column: message)\n";

struct CheckArgs {
  std::string path;
  bool quiet = false;
};

void print_summary(const std::string& path, const Pslg& pslg) {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (const Point& p : pslg.points) {
    xmin = std::min(xmin, p.x);
    xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y);
    ymax = std::max(ymax, p.y);
  }
  double shortest = std::numeric_limits<double>::infinity();
  std::size_t shortest_id = 0;
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    const double len = distance(pslg.points[pslg.segments[s].a], pslg.points[pslg.segments[s].b]);
    if (len < shortest) {
      shortest = len;
      shortest_id = s;
    }
  }
  std::printf("%s: valid domain\n", path.c_str());
  std::printf("  vertices          %zu\n", pslg.points.size());
  std::printf("  segments          %zu\n", pslg.segments.size());
  std::printf("  holes             %zu\n", pslg.holes.size());
  std::printf("  regions           %zu\n", pslg.regions.size());
  std::printf("  attributes        %u per vertex\n", pslg.attributes_per_point);
  std::printf("  area              %.17g\n", domain_area(pslg));
  std::printf("  bounding box      [%.17g, %.17g] x [%.17g, %.17g]\n", xmin, xmax, ymin, ymax);
  std::printf("  shortest segment  %.17g (segment %zu)\n", shortest, shortest_id + pslg.first_index);
}

int check_body(void* context) {
  const auto& args = *static_cast<CheckArgs*>(context);
  const Pslg pslg = read_domain(args.path);
  if (!args.quiet) print_summary(args.path, pslg);
  return exit_ok;
}

int run_check(int argc, char** argv) {
  static const option long_options[] = {
      {"quiet", no_argument, nullptr, 'q'}, {"help", no_argument, nullptr, 'h'}, {nullptr, 0, nullptr, 0}};
  CheckArgs args;
  optind = 0;
  int c;
  while ((c = getopt_long(argc, argv, "qh", long_options, nullptr)) != -1) {
    switch (c) {
    case 'q': args.quiet = true; break;
    case 'h': std::fputs(check_help, stdout); return exit_ok;
    default: return usage_error("check", "unknown option");
    }
  }
  if (optind + 1 != argc) return usage_error("check", "expected exactly one input file");
  args.path = argv[optind];
  return run_guarded("check", check_body, &args);
}

const CommandRegistration registration({"check", "validate a domain and print a summary", run_check});

} // namespace
} // namespace madd::cli
