// madd_bench sweep [--n N,N..] [--phi DEG,DEG..] [--threads J] [--repeat R]
//                  [--time-limit S] [--csv FILE] FILE.poly...
// The quality sweep of issue 13 ("never fail, and balance within 1.25, on
// every real coastline"): decompose() for every file x N x Phi0, each result
// checked with verify_decomposition, then its figures (madd/metrics.hpp).
// Prints a table per domain as the runs finish, then a summary per domain and
// overall; --csv writes one row per run with every figure, for diffing a
// sweep before and after a change (docs/performance.md, "Sweep"): the runs
// are keyed by (domain, n, phi), no field is quoted, and the two time columns
// come last so that `cut -d, -f1-23` drops them before a diff.
//
// What counts as what:
// - a run that throws (a madd::Error, e.g. DecompositionError, LimitError with
//   --time-limit, or any std::exception) is a *failure*: a measured figure,
//   listed with its message; the sweep goes on.
// - a run that returns a decomposition verify_decomposition rejects is a
//   *check failure*: a bug in madd, printed loudly with its first problems and
//   counted apart. Its figures are not computed (metrics() needs valid rings).
// - a file that cannot be read or is not a valid domain is reported on stderr
//   and skipped; the other files are still swept.
// Exit status: 0 when every file was read and every decomposition returned
// passed its check (and, with --repeat, gave the same result every time);
// failures do not change it. 1 otherwise, 2 on bad usage.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "bench.hpp"
#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"
#include "quality/decile.hpp"

namespace {

constexpr double balance_bound = 1.25;  // the target for max/mean area
const char* const usage = "usage: madd_bench sweep [--n N,N..] [--phi DEG,DEG..] [--threads J] [--repeat R]\n"
                          "                        [--time-limit S] [--csv FILE] FILE.poly...\n";

// The decades of the shortest-new-segment histogram: [1e-1, inf), [1e-2, 1e-1), ..., [0, 1e-4).
constexpr int decades = 5;
const char* const decade_names[decades] = {">=1e-1", "1e-2", "1e-3", "1e-4", "<1e-4"};

int decade_of(double shortest) {
  for (int k = 0; k < decades - 1; ++k) {
    if (shortest >= std::pow(10.0, -(k + 1))) return k;
  }
  return decades - 1;
}

enum class Status { ok, failed, check_failed };

struct Run {
  std::string domain;  // file name without directory and extension
  std::uint32_t n = 0;
  double phi = 0.0;
  Status status = Status::ok;
  std::string error;                  // failed: "kind: message", on one line
  std::vector<std::string> problems;  // check_failed: what verify_decomposition said
  bool deterministic = true;          // every repeat gave the same decomposition
  madd::Metrics m;                    // ok only
  double sep_norm = NAN;              // mean_separator_per_subdomain / sqrt(mean_area)
  double time_median = NAN;           // seconds of decompose(), median over the repeats
  double time_min = NAN;
};

double median(std::vector<double> values) {
  std::erase_if(values, [](double v) { return std::isnan(v); });
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const std::size_t h = values.size() / 2;
  return values.size() % 2 == 1 ? values[h] : 0.5 * (values[h - 1] + values[h]);
}

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

std::string stem(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  if (name.size() > 5 && name.ends_with(".poly")) name.resize(name.size() - 5);
  return name;
}

// decompose() `repeat` times (its time is the median), then the check and the figures.
Run run_one(const std::string& domain_name, const madd::Pslg& domain, const madd::DecomposeOptions& options,
            int repeat) {
  Run run;
  run.domain = domain_name;
  run.n = options.subdomains;
  run.phi = options.separator_angle_deg;
  // The time of a failed run is the time until decompose() threw; it is not repeated.
  std::vector<double> times;
  std::unique_ptr<madd::Decomposition> first;
  double start = 0.0;
  auto fail = [&](std::string error) {
    times.push_back(madd::bench::now_seconds() - start);
    run.status = Status::failed;
    run.error = one_line(std::move(error));
    if (first) run.deterministic = false;  // an earlier repeat succeeded
  };
  try {
    for (int r = 0; r < repeat; ++r) {
      start = madd::bench::now_seconds();
      madd::Decomposition d = madd::decompose(domain, options);
      times.push_back(madd::bench::now_seconds() - start);
      if (!first) {
        first = std::make_unique<madd::Decomposition>(std::move(d));
      } else if (d != *first) {
        run.deterministic = false;
      }
    }
  } catch (const madd::Error& e) {
    fail(std::string(madd::to_string(e.kind())) + ": " + e.what());
  } catch (const std::exception& e) {
    fail(std::string("exception: ") + e.what());
  }
  if (!times.empty()) {
    run.time_median = median(times);
    run.time_min = *std::min_element(times.begin(), times.end());
  }
  if (run.status == Status::failed) return run;

  const madd::Verification check =
      madd::verify_decomposition(*first, domain, madd::expected_subdomain_count(*first, options.subdomains));
  if (!check.ok()) {
    run.status = Status::check_failed;
    run.problems = check.problems;
    return run;
  }
  run.m = madd::metrics(*first);
  run.sep_norm = run.m.mean_separator_per_subdomain / std::sqrt(run.m.mean_area);
  return run;
}

// --- printing -------------------------------------------------------------

void print_run_header() {
  std::printf("  %5s %6s  %-6s %8s %8s %9s %7s %7s %9s\n", "phi", "N", "status", "max/mean", "sep/sqA", "shortest",
              "min_ang", "med_ang", "time_s");
}

void print_run(const Run& run) {
  std::printf("  %5g %6u  ", run.phi, run.n);
  switch (run.status) {
  case Status::ok:
    std::printf("%-6s %8.3f %8.3f %9.2e %7.2f %7.2f %9.4f%s%s\n", "ok", run.m.max_area_over_mean, run.sep_norm,
                run.m.shortest_new_segment_norm, run.m.angle_min, run.m.angle_median, run.time_median,
                run.m.max_area_over_mean > balance_bound ? "  > 1.25" : "",
                run.deterministic ? "" : "  NOT DETERMINISTIC");
    break;
  case Status::failed:
    std::printf("%-6s after %.4f s: %s\n", "FAILED", run.time_median, run.error.c_str());
    break;
  case Status::check_failed:
    std::printf("%-6s verify_decomposition found %zu problem(s):\n", "CHECK", run.problems.size());
    for (std::size_t k = 0; k < run.problems.size() && k < 5; ++k) {
      std::printf("           %s\n", one_line(run.problems[k]).c_str());
    }
    break;
  }
  std::fflush(stdout);
}

// The figures of a set of runs (one domain, one Phi0, or all).
struct Summary {
  int runs = 0, failed = 0, check_failed = 0, over_bound = 0;
  double worst_balance = NAN, median_balance = NAN, median_sep = NAN;
  double median_shortest = NAN, min_shortest = NAN;
  int histogram[decades] = {};
  double time_median = NAN, time_total = 0.0;
  std::vector<double> shortest;  // sorted, for the deciles

  explicit Summary(const std::vector<const Run*>& set) {
    std::vector<double> balance, sep, times;
    for (const Run* run : set) {
      ++runs;
      if (!std::isnan(run->time_median)) {
        times.push_back(run->time_median);
        time_total += run->time_median;
      }
      if (run->status == Status::failed) ++failed;
      if (run->status == Status::check_failed) ++check_failed;
      if (run->status != Status::ok) continue;
      balance.push_back(run->m.max_area_over_mean);
      if (run->m.max_area_over_mean > balance_bound) ++over_bound;
      sep.push_back(run->sep_norm);
      if (!std::isnan(run->m.shortest_new_segment_norm)) {
        shortest.push_back(run->m.shortest_new_segment_norm);
        ++histogram[decade_of(run->m.shortest_new_segment_norm)];
      }
    }
    if (!balance.empty()) worst_balance = *std::max_element(balance.begin(), balance.end());
    median_balance = median(balance);
    median_sep = median(sep);
    std::sort(shortest.begin(), shortest.end());
    median_shortest = median(shortest);
    if (!shortest.empty()) min_shortest = shortest.front();
    time_median = median(times);
  }
};

void print_summary_header() {
  std::printf("%-18s %4s %4s %5s %6s %6s %5s %7s %9s %9s", "domain", "runs", "fail", "check", "worst", "median",
              ">1.25", "sep/sqA", "short_med", "short_min");
  for (const char* name : decade_names) std::printf(" %6s", name);
  std::printf(" %8s %9s\n", "t_med_s", "t_total_s");
}

void print_summary(const std::string& label, const Summary& s) {
  std::printf("%-18s %4d %4d %5d %6.3f %6.3f %5d %7.3f %9.2e %9.2e", label.c_str(), s.runs, s.failed, s.check_failed,
              s.worst_balance, s.median_balance, s.over_bound, s.median_sep, s.median_shortest, s.min_shortest);
  for (int count : s.histogram) std::printf(" %6d", count);
  std::printf(" %8.4f %9.3f\n", s.time_median, s.time_total);
}

// --- CSV --------------------------------------------------------------------

// A message as one CSV field with no quoting: commas become semicolons and
// double quotes single ones, so that a shell script may split rows on commas.
std::string csv_field(std::string text) {
  std::replace(text.begin(), text.end(), ',', ';');
  std::replace(text.begin(), text.end(), '"', '\'');
  return one_line(std::move(text));
}

const char* status_name(Status s) { return s == Status::ok ? "ok" : s == Status::failed ? "failed" : "check_failed"; }

void write_csv_header(std::FILE* csv) {
  std::fprintf(csv, "domain,n,phi,threads,repeat,status,message,deterministic,subdomains,points,segments,"
                    "separator_segments,max_area_over_mean,min_area_over_mean,sep_per_subdomain_norm,"
                    "mean_separator_per_subdomain,mean_area,separator_length_norm,max_separator_over_area_norm,"
                    "shortest_new_segment_norm,angle_min,angle_median,boundary_angle_min,time_median_s,time_min_s\n");
}

void write_csv_row(std::FILE* csv, const Run& run, unsigned threads, int repeat) {
  std::string message = run.error;
  if (run.status == Status::check_failed) {
    message = std::to_string(run.problems.size()) + " problem(s): " + one_line(run.problems.front());
  }
  std::fprintf(csv, "%s,%u,%.17g,%u,%d,%s,%s,%d,", run.domain.c_str(), run.n, run.phi, threads, repeat,
               status_name(run.status), csv_field(message).c_str(), run.deterministic ? 1 : 0);
  const madd::Metrics& m = run.m;
  if (run.status == Status::ok) {
    std::fprintf(csv, "%u,%u,%u,%u,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,", m.subdomains,
                 m.points, m.segments, m.separator_segments, m.max_area_over_mean, m.min_area_over_mean, run.sep_norm,
                 m.mean_separator_per_subdomain, m.mean_area, m.separator_length_norm, m.max_separator_over_area_norm,
                 m.shortest_new_segment_norm, m.angle_min, m.angle_median, m.boundary_angle_min);
  } else {
    std::fprintf(csv, ",,,,,,,,,,,,,,,");
  }
  std::fprintf(csv, "%.6f,%.6f\n", run.time_median, run.time_min);
  std::fflush(csv);
}

// --- arguments --------------------------------------------------------------

// A comma-separated list of numbers; false on anything else.
bool parse_list(const char* text, std::vector<double>& out) {
  out.clear();
  const char* p = text;
  while (true) {
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p || !std::isfinite(v)) return false;
    out.push_back(v);
    if (*end == '\0') return true;
    if (*end != ',') return false;
    p = end + 1;
  }
}

bool parse_counts(const char* text, std::vector<std::uint32_t>& out) {
  std::vector<double> values;
  if (!parse_list(text, values)) return false;
  out.clear();
  for (double v : values) {
    if (v < 1 || v > 1e9 || v != std::floor(v)) return false;
    out.push_back(static_cast<std::uint32_t>(v));
  }
  return true;
}

int run(int argc, char** argv) {
  std::vector<std::uint32_t> counts = {16, 64, 100, 256, 500, 1000, 2000};
  std::vector<double> phis = {60, 70};
  madd::DecomposeOptions options;  // the defaults, but for N, Phi0 and the limits
  int repeat = 1;
  const char* csv_path = nullptr;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
    bool good = true;
    std::vector<double> numbers;
    if (arg == "--n" && value) {
      good = parse_counts(value, counts);
    } else if (arg == "--phi" && value) {
      good = parse_list(value, phis);
    } else if ((arg == "--threads" || arg == "--repeat" || arg == "--time-limit") && value) {
      good = parse_list(value, numbers) && numbers.size() == 1 && numbers[0] >= 0;
      if (good && arg != "--time-limit") good = numbers[0] == std::floor(numbers[0]) && numbers[0] <= 1e6;
      if (good && arg == "--threads") options.threads = static_cast<unsigned>(numbers[0]);
      if (good && arg == "--repeat") repeat = std::max(1, static_cast<int>(numbers[0]));
      if (good && arg == "--time-limit") options.time_limit_seconds = numbers[0];
    } else if (arg == "--csv" && value) {
      csv_path = value;
    } else if (arg.starts_with("-")) {
      std::fprintf(stderr, "sweep: unknown option or missing value: %s\n%s", arg.c_str(), usage);
      return 2;
    } else {
      files.push_back(arg);
      continue;
    }
    if (!good) {
      std::fprintf(stderr, "sweep: bad value for %s: %s\n%s", arg.c_str(), value, usage);
      return 2;
    }
    ++i;
  }
  if (files.empty()) {
    std::fprintf(stderr, "%s", usage);
    return 2;
  }
  // Refuse a bad option before reading anything, not once per run.
  for (double phi : phis) {
    madd::DecomposeOptions o = options;
    o.separator_angle_deg = phi;
    try {
      madd::check_options(o);
    } catch (const madd::Error& e) {
      std::fprintf(stderr, "sweep: bad options (with --phi %g): %s\n", phi, e.what());
      return 2;
    }
  }
  std::FILE* csv = nullptr;
  if (csv_path) {
    csv = std::fopen(csv_path, "w");
    if (!csv) {
      std::fprintf(stderr, "sweep: cannot write %s: %s\n", csv_path, std::strerror(errno));
      return 2;
    }
    write_csv_header(csv);
  }

  std::printf("sweep: %zu file(s) x N {", files.size());
  for (std::size_t k = 0; k < counts.size(); ++k) std::printf("%s%u", k ? "," : "", counts[k]);
  std::printf("} x phi {");
  for (std::size_t k = 0; k < phis.size(); ++k) std::printf("%s%g", k ? "," : "", phis[k]);
  std::printf("}, threads %u, repeat %d%s\n", options.threads, repeat,
              options.time_limit_seconds > 0 ? ", with a time limit" : "");
  std::printf("max/mean: largest subdomain area / mean; sep/sqA: mean_separator_per_subdomain / sqrt(mean area);\n"
              "shortest: shortest_new_segment_norm; time_s: decompose() wall seconds (median of the repeats)\n");

  const double sweep_start = madd::bench::now_seconds();
  std::vector<Run> runs;
  runs.reserve(files.size() * counts.size() * phis.size());
  std::vector<std::string> domains;  // read and swept, in order
  int unreadable = 0;
  for (const std::string& file : files) {
    madd::Pslg domain;
    try {
      domain = madd::read_domain(file);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sweep: skipping %s: %s\n", file.c_str(), one_line(e.what()).c_str());
      std::printf("\n== %s: NOT READ (%s)\n", file.c_str(), one_line(e.what()).c_str());
      ++unreadable;
      continue;
    }
    const std::string name = stem(file);
    domains.push_back(name);
    std::printf("\n== %s (%zu segments, %zu hole%s)\n", name.c_str(), domain.segments.size(), domain.holes.size(),
                domain.holes.size() == 1 ? "" : "s");
    print_run_header();
    for (double phi : phis) {
      for (std::uint32_t n : counts) {
        madd::DecomposeOptions o = options;
        o.subdomains = n;
        o.separator_angle_deg = phi;
        runs.push_back(run_one(name, domain, o, repeat));
        print_run(runs.back());
        if (runs.back().status == Status::check_failed) {
          std::fprintf(stderr, "sweep: CHECK FAILED: %s N=%u phi=%g: %s\n", name.c_str(), n, phi,
                       one_line(runs.back().problems.front()).c_str());
        }
        if (csv) write_csv_row(csv, runs.back(), options.threads, repeat);
      }
    }
  }
  if (csv) std::fclose(csv);

  // Summaries: per domain, per Phi0 over all domains, all.
  auto select = [&runs](auto keep) {
    std::vector<const Run*> set;
    for (const Run& r : runs) {
      if (keep(r)) set.push_back(&r);
    }
    return set;
  };
  std::printf("\n== summary (worst/median: max/mean area; >1.25: runs above; sep/sqA: median; "
              "short_*: shortest new segment, then runs per decade)\n");
  print_summary_header();
  for (const std::string& name : domains) {
    print_summary(name, Summary(select([&name](const Run& r) { return r.domain == name; })));
  }
  if (phis.size() > 1) {
    for (double phi : phis) {
      char label[32];
      std::snprintf(label, sizeof label, "all, phi %g", phi);
      print_summary(label, Summary(select([phi](const Run& r) { return r.phi == phi; })));
    }
  }
  const Summary all(select([](const Run&) { return true; }));
  print_summary("all", all);

  if (all.shortest.size() >= 2) {
    std::printf("\nshortest new segment, deciles over the %zu runs that succeeded:", all.shortest.size());
    for (int q = 1; q <= 9; ++q) std::printf(" %.2e", madd::detail::decile(all.shortest, q));
    std::printf("\n");
  }
  std::printf("\nfailures (%d):\n", all.failed);
  for (const Run& r : runs) {
    if (r.status == Status::failed)
      std::printf("  %-20s N %5u phi %g: %s\n", r.domain.c_str(), r.n, r.phi, r.error.c_str());
  }
  if (all.check_failed > 0) {
    std::printf("\nCHECK FAILURES (%d): decompositions verify_decomposition rejects, a bug in madd:\n",
                all.check_failed);
    for (const Run& r : runs) {
      if (r.status == Status::check_failed) {
        std::printf("  %-20s N %5u phi %g: %s\n", r.domain.c_str(), r.n, r.phi, one_line(r.problems.front()).c_str());
      }
    }
  }
  std::vector<const Run*> worst = select([](const Run& r) { return r.status == Status::ok; });
  std::sort(worst.begin(), worst.end(),
            [](const Run* a, const Run* b) { return a->m.max_area_over_mean > b->m.max_area_over_mean; });
  worst.resize(std::min<std::size_t>(worst.size(), 5));
  std::printf("\nworst balance:\n");
  for (const Run* r : worst) {
    std::printf("  %-20s N %5u phi %g: max/mean %.3f\n", r->domain.c_str(), r->n, r->phi, r->m.max_area_over_mean);
  }
  const int nondeterministic = static_cast<int>(select([](const Run& r) { return !r.deterministic; }).size());
  if (nondeterministic > 0)
    std::printf("\nNOT DETERMINISTIC: %d run(s) gave different results on repeat\n", nondeterministic);
  std::printf("\ndecompose() time %.2f s in all (sum of the runs' medians); sweep wall time %.2f s\n", all.time_total,
              madd::bench::now_seconds() - sweep_start);
  if (unreadable > 0) std::printf("%d file(s) not read\n", unreadable);
  return unreadable > 0 || all.check_failed > 0 || nondeterministic > 0 ? 1 : 0;
}

const madd::bench::Registration registration("sweep", run);

}  // namespace
