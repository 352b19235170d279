// madd-mpi: `mpirun -np P madd-mpi mesh DOMAIN.poly -n N [options] -o OUT`
// (docs/mpi.md). A thin front end: every rank decomposes the domain itself
// (deterministic, so all get the same decomposition), meshes its share of
// the subdomains on its own threads (madd::mesh_share), and writes its part
// with global ids; the ranks meet only to agree on the separator pieces split
// between rounds, on the per-subdomain counts that number the vertices, on
// whether every part was written, and for the final figures. The union of
// the parts is `madd mesh`'s mesh for the same options, for any P.
//
// Failure is all or nothing, as in the single-process tool: an error every
// rank sees alike (bad input, bad options) makes every rank exit with its
// code; an error one rank meets while meshing (a limit, a bug) aborts the
// job (MPI_Abort) before anything is written; a part that cannot be written
// makes every rank remove what it staged.
#include <mpi.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <future>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "../commands.hpp"
#include "../huge_pages.hpp"
#include "../input_domain.hpp"
#include "../interrupts.hpp"
#include "../model_files.hpp"
#include "../seconds.hpp"
#include "../mesh_arguments.hpp"
#include "funnel.hpp"
#include "gather_parts.hpp"
#include "madd/atomic_write.hpp"
#include "madd/error.hpp"
#include "madd/mesh_metrics.hpp"
#include "madd/mesh_output.hpp"
#include "madd/mesh_part_output.hpp"
#include "madd/mesh_share.hpp"
#include "madd/poly_io.hpp"

namespace madd::mpi {
namespace {

using cli::ExitCode;
using cli::seconds_since;

constexpr const char* help_intro = "usage: mpirun -np P madd-mpi mesh [options] INPUT.poly|INPUT.geojson|INPUT.shp\n\n"
                                   "madd mesh on P processes: every rank decomposes the domain, meshes its share of\n"
                                   "the subdomains (balanced by expected triangles) on its own threads with no\n"
                                   "communication, and writes its part with global ids. The union of the parts is\n"
                                   "the mesh `madd mesh` makes with the same options, for any P.\n\n";

constexpr const char* help_outputs =
    "outputs, for every rank R:\n"
    "  PREFIX-R.node        \"id x y global owner marker\": global = the vertex's id in\n"
    "                       madd mesh's PREFIX.node, owner = the lowest rank that has it\n"
    "  PREFIX-R.ele         \"id a b c subdomain global\", local vertex ids\n"
    "  PREFIX-R.vtu         with --vtu, and PREFIX.pvtu that opens all of them in ParaView\n"
    "and on rank 0, of the whole mesh (the parts gathered there): --fort14, --gr3, --2dm\n\n"
    "exit codes: as madd's (0 ok, 2 usage, 3 bad input, 4 no decomposition, 5 output\n"
    "not written, 6 limit, 70 internal error); nothing is written unless all is.\n";

// `text` broken into lines of at most 80 characters, at spaces.
std::string wrapped(const std::string& text) {
  std::string out, line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > 80) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return out + line + "\n";
}

// The help: madd mesh's options, from its list in the option table, named
// with those madd-mpi does not take.
std::string help_text() {
  std::string taken, declined;
  const auto whole_mesh_only = cli::whole_mesh_file_options();
  for (const cli::OptionUse& use : cli::mesh_options().uses) {
    if (use.name == nullptr || std::string_view(use.name) == "help") continue;
    const char letter = cli::letter_of(use);
    const std::string flag = letter != 0 ? std::string("-") + letter : std::string("--") + use.name;
    const bool whole = std::find_if(whole_mesh_only.begin(), whole_mesh_only.end(), [&](const char* name) {
                         return std::string_view(name) == use.name;
                       }) != whole_mesh_only.end();
    std::string& list = whole ? declined : taken;
    list += (list.empty() ? "" : ", ") + flag;
  }
  return help_intro +
         wrapped("Options are madd mesh's, with the same meanings (see madd mesh --help): " + taken +
                 "; -n is required, -j is the thread count of each rank. Not here: " + declined + ".") +
         "\n" + help_outputs;
}

struct World {
  int rank = 0, size = 1;
  bool operator==(const World&) const = default;
};

// A whole number in [0, int's largest], all of `text`; nothing otherwise.
std::optional<int> whole_number(const char* text) {
  if (text == nullptr || *text == '\0') return std::nullopt;
  int value = 0;
  const char* end = text + std::strlen(text);
  const auto [at, error] = std::from_chars(text, end, value);
  if (error != std::errc() || at != end || value < 0) return std::nullopt;
  return value;
}

// The rank and rank count the launcher put in this process's environment
// (Open MPI's mpirun; MPICH's and Intel MPI's Hydra; MVAPICH2), read before
// MPI starts; nothing when it put none (a run without a launcher, or another
// launcher). A guess, checked against MPI's own once it has started (run()).
std::optional<World> launcher_world() {
  static constexpr std::pair<const char*, const char*> names[] = {{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"},
                                                                  {"PMI_RANK", "PMI_SIZE"},
                                                                  {"MV2_COMM_WORLD_RANK", "MV2_COMM_WORLD_SIZE"}};
  for (const auto& [rank_name, size_name] : names) {
    const std::optional<int> rank = whole_number(std::getenv(rank_name)), size = whole_number(std::getenv(size_name));
    if (rank && size && *rank < *size) return World{*rank, *size};
  }
  return std::nullopt;
}

// SIGINT/SIGTERM (mpirun forwards them): nothing partial may stay on disk.
volatile std::sig_atomic_t writing = 0;

void on_interrupt(int signal_number) {
  if (interrupt_output_writes() || writing != 0) return;  // let the write unwind and remove its staging
  ::_exit(128 + signal_number);
}

using cli::Failure;

// Runs body(); the error a rank met, as the single-process tool would say it.
template <typename Body>
Failure attempt(const Body& body) {
  try {
    body();
    return {};
  } catch (...) {
    return cli::current_failure();
  }
}

// A step every rank takes alike: when it fails anywhere, the lowest failing
// rank says why (the others would mostly say the same) and everyone returns
// the same code.
int agree(const World& world, const Failure& mine) {
  const int failing = mine.code == cli::exit_ok ? world.size : world.rank;
  int first = world.size;
  MPI_Allreduce(&failing, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (first == world.size) return cli::exit_ok;
  int code = mine.code;
  MPI_Bcast(&code, 1, MPI_INT, first, MPI_COMM_WORLD);
  if (world.rank == first) std::fprintf(stderr, "madd-mpi mesh: %s\n", mine.message.c_str());
  return code;
}

// A step only this rank takes (meshing): the others cannot be asked to stop
// at a collective they may never reach, so the job is aborted. Nothing has
// been written yet.
void abort_on(const World& world, const Failure& mine) {
  if (mine.code == cli::exit_ok) return;
  std::fprintf(stderr, "madd-mpi mesh: rank %d: %s (no output written)\n", world.rank, mine.message.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, mine.code);
}

ShareExchange mpi_exchange() {
  ShareExchange x;
  x.union_of = [](const std::vector<std::uint32_t>& mine) {
    int size = 0;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const int count = static_cast<int>(mine.size());
    std::vector<int> counts(static_cast<std::size_t>(size)), starts(static_cast<std::size_t>(size), 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    for (std::size_t r = 1; r < counts.size(); ++r) starts[r] = starts[r - 1] + counts[r - 1];
    std::vector<std::uint32_t> all(static_cast<std::size_t>(starts.back() + counts.back()));
    MPI_Allgatherv(mine.data(), count, MPI_UINT32_T, all.data(), counts.data(), starts.data(), MPI_UINT32_T,
                   MPI_COMM_WORLD);
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
  };
  x.sum_of = [](const std::vector<std::uint64_t>& mine) {
    std::vector<std::uint64_t> sum(mine.size());
    MPI_Allreduce(mine.data(), sum.data(), static_cast<int>(mine.size()), MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    return sum;
  };
  return x;
}

// mpi_exchange()'s agreements asked for by the helper thread and made by
// the main thread (funnel.hpp).
ShareExchange funneled_exchange(Funnel& funnel) {
  const ShareExchange direct = mpi_exchange();
  ShareExchange x;
  x.union_of = [&funnel, direct](const std::vector<std::uint32_t>& mine) {
    std::vector<std::uint32_t> all;
    funnel.call([&] { all = direct.union_of(mine); });
    return all;
  };
  x.sum_of = [&funnel, direct](const std::vector<std::uint64_t>& mine) {
    std::vector<std::uint64_t> sum;
    funnel.call([&] { sum = direct.sum_of(mine); });
    return sum;
  };
  return x;
}

double phase_seconds(const MeshReport& report, const char* name) {
  double s = 0;
  for (const PhaseTime& p : report.phases)
    if (p.name == name) s += p.seconds;
  return s;
}

// The global figures, on rank 0: the mesh's (its parts' combined) and every
// rank's times.
struct Figures {
  MeshMetrics mesh;
  std::vector<double> decompose_seconds, mesh_seconds, format_seconds, peak_megabytes;
  // Per subdomain: the work estimate (every rank computes all of it, the
  // same) and the triangles its owner made.
  std::vector<double> predicted_triangles, subdomain_triangles;
};

// Per subdomain, the triangles of the whole mesh: each rank's part holds
// its own subdomains' ranges (the others empty), so the sums are the counts.
std::vector<double> subdomain_triangles(const MeshPart& part) {
  const std::vector<std::uint32_t>& first = part.mesh.subdomain_first_triangle;
  std::vector<std::uint64_t> mine(first.empty() ? 0 : first.size() - 1), all(mine.size());
  for (std::size_t k = 0; k < mine.size(); ++k) mine[k] = first[k + 1] - first[k];
  MPI_Reduce(mine.data(), all.data(), static_cast<int>(mine.size()), MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
  return {all.begin(), all.end()};
}

// This process's peak resident memory.
double peak_megabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

// The figures of the whole mesh from every rank's part: counts add up, the
// smallest angle and the largest subdomain are the extremes; the median does
// not combine and is left out.
MeshMetrics combine_figures(const MeshPart& part, const MeshSizeOptions& size) {
  const MeshMetrics mine = mesh_metrics(part.mesh, size);
  MeshMetrics all = mine;
  all.triangles = part.total_triangles;
  all.vertices = part.total_points;
  all.median_smallest_angle_deg = std::numeric_limits<double>::quiet_NaN();
  MPI_Reduce(&mine.smallest_angle_deg, &all.smallest_angle_deg, 1, MPI_DOUBLE, MPI_MIN, 0, MPI_COMM_WORLD);
  MPI_Reduce(&mine.largest_subdomain_triangles, &all.largest_subdomain_triangles, 1, MPI_UINT64_T, MPI_MAX, 0,
             MPI_COMM_WORLD);
  const MeshShortfall& why = mine.shortfall;
  std::vector<std::uint64_t> counts = {mine.below_bound, why.input_angle, why.separator, why.precision, why.limit};
  counts.insert(counts.end(), mine.smallest_angle_histogram.begin(), mine.smallest_angle_histogram.end());
  std::vector<std::uint64_t> sums(counts.size());
  MPI_Reduce(counts.data(), sums.data(), static_cast<int>(counts.size()), MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
  all.below_bound = sums[0];
  all.shortfall = {sums[1], sums[2], sums[3], sums[4]};
  std::copy(sums.begin() + 5, sums.end(), all.smallest_angle_histogram.begin());
  return all;
}

Figures gather_figures(const World& world, const MeshPart& part, const MeshOptions& options, const MeshReport& report,
                       double decompose_s, double format_s) {
  Figures f;
  f.mesh = combine_figures(part, options.size);
  f.predicted_triangles = report.expected_triangles;
  f.subdomain_triangles = subdomain_triangles(part);
  // Meshing: refinement with each subdomain's check (made on its thread) and the numbering.
  const double times[4] = {decompose_s, phase_seconds(report, "refine") + phase_seconds(report, "assemble"), format_s,
                           peak_megabytes()};
  std::vector<double> all(4 * static_cast<std::size_t>(world.size));
  MPI_Gather(times, 4, MPI_DOUBLE, all.data(), 4, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  for (int r = 0; r < world.size; ++r) {
    f.decompose_seconds.push_back(all[4 * r]);
    f.mesh_seconds.push_back(all[4 * r + 1]);
    f.format_seconds.push_back(all[4 * r + 2]);
    f.peak_megabytes.push_back(all[4 * r + 3]);
  }
  return f;
}

// Slowest rank over the mean (1 = perfectly balanced).
double imbalance(const std::vector<double>& seconds) {
  double sum = 0, most = 0;
  for (const double s : seconds) {
    sum += s;
    most = std::max(most, s);
  }
  return sum > 0 ? most * static_cast<double>(seconds.size()) / sum : 1.0;
}

std::string list(const std::vector<double>& values) {
  std::string out;
  char buf[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s%.6g", i ? ", " : "", values[i]);
    out += buf;
  }
  return out;
}

// The mesh report of `madd mesh`, with every rank's figures as the run's.
std::string report_json(const World& world, const Figures& f, bool early_start, double seconds) {
  const std::vector<RunFigure> run = {
      {"ranks", static_cast<double>(world.size)},
      {"early_start", early_start ? 1.0 : 0.0},
      {"rank_imbalance", imbalance(f.mesh_seconds)},
      {"decompose_seconds", f.decompose_seconds},
      {"mesh_seconds", f.mesh_seconds},
      {"format_seconds", f.format_seconds},
      {"peak_resident_megabytes", f.peak_megabytes},
      {"predicted_triangles", std::accumulate(f.predicted_triangles.begin(), f.predicted_triangles.end(), 0.0)},
      {"subdomain_predicted_triangles", f.predicted_triangles},
      {"subdomain_triangles", f.subdomain_triangles},
      {"seconds_before_writing", seconds}};
  return format_mesh_report_json(f.mesh, run);
}

// Writes this rank's files (and rank 0's report file) all or nothing across
// ranks; returns exit_ok or, on every rank alike, exit_io.
int write_everywhere(const World& world, OutputSet& outputs, Failure staged) {
  const auto all_staged = [](bool staged_here) {
    int mine = staged_here ? 1 : 0, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
    return all == 1;
  };
  Failure written = staged;
  if (staged.code == cli::exit_ok) {
    writing = 1;
    written = attempt([&] { outputs.write(all_staged); });  // calls all_staged exactly once
    writing = 0;
  } else {
    all_staged(false);  // every rank must take part in the agreement
  }
  // Only the ranks that failed themselves say why; all exit alike.
  int failed = written.code != cli::exit_ok ? 1 : 0, any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
  if (!any) return cli::exit_ok;
  if (failed && written.message.find("another process") == std::string::npos)
    std::fprintf(stderr, "madd-mpi mesh: rank %d: %s\n", world.rank, written.message.c_str());
  return cli::exit_io;
}

// Rank 0's summary: one line of global figures, then the meshing time of
// every rank while they fit on a line, else their spread.
void print_summary(const World& world, const cli::MeshArgs& args, const Figures& f, double seconds) {
  std::FILE* out = args.line.report && args.line.report_file.empty() ? stderr : stdout;
  std::fprintf(out,
               "%s: %d ranks, %u subdomains, %llu triangles, %llu vertices, smallest angle %.2f deg (%llu below "
               "%.4g), %.2f s -> %s-*.{node,ele}%s\n",
               args.input.c_str(), world.size, f.mesh.subdomains, static_cast<unsigned long long>(f.mesh.triangles),
               static_cast<unsigned long long>(f.mesh.vertices), f.mesh.smallest_angle_deg,
               static_cast<unsigned long long>(f.mesh.below_bound), f.mesh.min_angle_bound_deg, seconds,
               args.prefix.c_str(), args.line.formats.vtu ? " .pvtu" : "");
  std::vector<double> sorted = f.mesh_seconds;
  std::sort(sorted.begin(), sorted.end());
  if (world.size <= 16)
    std::fprintf(out, "  meshing seconds per rank: %s; load imbalance (slowest / mean) %.3f\n",
                 list(f.mesh_seconds).c_str(), imbalance(f.mesh_seconds));
  else
    std::fprintf(out, "  meshing seconds per rank: fastest %.3g, median %.3g, slowest %.3g; load imbalance %.3f\n",
                 sorted.front(), sorted[sorted.size() / 2], sorted.back(), imbalance(f.mesh_seconds));
}

// What every rank reads and decomposes alike, before it needs MPI.
struct Decomposed {
  Failure failure;
  MeshOptions options;
  Pslg domain;
  Projection projection;
  std::optional<DepthField> depth;
  Decomposition decomposition;
  double seconds = 0.0;  // since the program started
};

Decomposed read_and_decompose(const cli::MeshArgs& args, std::chrono::steady_clock::time_point start) {
  Decomposed out;
  out.failure = attempt([&] {
    out.options = cli::with_background_files(args.line);
    CoastDomain input = cli::read_input_domain(args.input, args.line, nullptr);
    cli::default_coast_markers(out.options.size, args.input, input, args.line);
    out.projection = input.projection;
    out.depth = cli::read_depth(args.line);
    if (out.depth) set_depth(out.options.size, *out.depth, out.projection);
    out.domain = std::move(input.domain);
    out.decomposition = decompose_for_mesh(out.domain, out.options).decomposition;
  });
  out.seconds = seconds_since(start);
  return out;
}

// This rank's share meshed on the helper thread while MPI starts (main()),
// under the launcher's rank and rank count.
struct EarlyShare {
  std::optional<World> guess;  // launcher_world(): nothing, no early start
  bool meshed = false;         // mesh_share ran to its end, or failed (failure)
  Failure failure;
  MeshPartRun run;
};

// On the helper thread: reads and decomposes, says so, then meshes the share
// early when the launcher said which it is, its agreements through `funnel`.
// Stops early (meshed false) when the main thread closes the funnel.
void start_early(const cli::MeshArgs& args, std::chrono::steady_clock::time_point start, Decomposed& ready,
                 std::promise<void>& decomposed, EarlyShare& early, Funnel& funnel) {
  try {
    ready = read_and_decompose(args, start);
  } catch (...) {  // (it reports its failures itself; the main thread must hear back whatever happens)
    ready.failure = cli::current_failure();
  }
  decomposed.set_value();
  if (ready.failure.code == cli::exit_ok && early.guess) {
    try {
      early.run =
          mesh_share(ready.decomposition, ready.domain, ready.options, static_cast<std::uint32_t>(early.guess->rank),
                     static_cast<std::uint32_t>(early.guess->size), funneled_exchange(funnel));
      early.meshed = true;
    } catch (const Funnel::Closed&) {
      early.run = {};
    } catch (...) {
      early.failure = cli::current_failure();
      early.meshed = true;
    }
  }
  funnel.finish();
}

int run(const World& world, const cli::MeshArgs& args, Decomposed& ready, EarlyShare& early, Funnel& funnel,
        std::thread& helper, std::chrono::steady_clock::time_point start) {
  // Read and decomposed by every rank alike (before MPI started, main()).
  if (const int code = agree(world, ready.failure); code != cli::exit_ok) {
    funnel.close();
    helper.join();
    return code;
  }
  // The shares meshed early are the ones MPI gives only when every rank's
  // launcher guessed right: then the main thread makes their agreements,
  // else they stop at their first and every rank meshes its share now.
  int right = early.guess && *early.guess == world ? 1 : 0, all_right = 0;
  MPI_Allreduce(&right, &all_right, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
  if (all_right == 1) funnel.serve();
  else funnel.close();
  helper.join();
  const MeshOptions options = std::move(ready.options);
  const Pslg domain = std::move(ready.domain);
  const Projection projection = ready.projection;
  const std::optional<DepthField> depth = std::move(ready.depth);
  const Decomposition decomposition = std::move(ready.decomposition);
  const double decompose_s = ready.seconds;
  // Mesh this rank's share (unless done early).
  MeshReport report;
  MeshPart part;
  if (early.meshed) {
    abort_on(world, early.failure);
    part = std::move(early.run.part);
    report = std::move(early.run.report);
  } else {
    abort_on(world, attempt([&] {
               MeshPartRun run = mesh_share(decomposition, domain, options, static_cast<std::uint32_t>(world.rank),
                                            static_cast<std::uint32_t>(world.size), mpi_exchange());
               part = std::move(run.part);
               report = std::move(run.report);
             }));
  }
  // Format this rank's files (the report too, on rank 0), gather the
  // figures, then write every part or none.
  const auto format_start = std::chrono::steady_clock::now();
  OutputSet outputs;
  MeshPartFormats formats;
  formats.vtu = args.line.formats.vtu;
  formats.first_index = args.line.formats.first_index;
  Failure staged = attempt([&] { add_mesh_part(outputs, part, args.prefix, formats, options.decomposition.threads); });
  // The coastal model files are of the whole mesh: rank 0 joins the parts and writes them.
  Mesh whole;
  cli::ModelFiles model_files;
  if (!args.line.fort14_file.empty() || !args.line.gr3_file.empty() || !args.line.sms_file.empty()) {
    std::vector<MeshPart> parts = gather_parts(part, world.rank, world.size);
    if (world.rank == 0 && staged.code == cli::exit_ok)
      staged = attempt([&] {
        whole = join_parts(parts);
        parts.clear();
        cli::add_model_files(outputs, model_files, whole, args.line, args.prefix, projection, depth,
                             options.decomposition.threads);
      });
  }
  const Figures f = gather_figures(world, part, options, report, decompose_s, seconds_since(format_start));
  const std::string json =
      world.rank == 0 && args.line.report ? report_json(world, f, early.meshed, seconds_since(start)) : "";
  if (staged.code == cli::exit_ok && !json.empty() && !args.line.report_file.empty())
    staged = attempt([&] { outputs.add_file(args.line.report_file, json); });
  if (const int written = write_everywhere(world, outputs, staged); written != cli::exit_ok) return written;
  if (world.rank != 0) return cli::exit_ok;
  if (!json.empty() && args.line.report_file.empty()) std::fputs(json.c_str(), stdout);
  if (!args.line.quiet) print_summary(world, args, f, seconds_since(start));
  return cli::exit_ok;
}

// The command line, read before MPI starts: a usage error or the help is
// said by rank 0 once MPI has started; otherwise the arguments of a run.
struct CommandLine {
  enum class Outcome { run, help, usage } outcome = Outcome::run;
  std::string said;  // the help or the usage error, as printed
  cli::MeshArgs args;
};

CommandLine read_command_line(int argc, char** argv) {
  CommandLine out;
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    out.outcome = argc < 2 ? CommandLine::Outcome::usage : CommandLine::Outcome::help;
    out.said = help_text();
    return out;
  }
  if (std::strcmp(argv[1], "mesh") != 0) {
    out.outcome = CommandLine::Outcome::usage;
    out.said = std::string("madd-mpi: unknown command '") + argv[1] + "' (the one command is 'mesh')\n";
    return out;
  }
  const std::string problem = cli::parse_mesh_arguments(argc - 1, argv + 1, out.args, true, false);
  if (problem.empty() && out.args.line.help) {
    out.outcome = CommandLine::Outcome::help;
    out.said = help_text();
  } else if (!problem.empty()) {
    out.outcome = CommandLine::Outcome::usage;
    out.said = "madd-mpi mesh: " + problem + "\n(try 'madd-mpi mesh --help')\n";
  }
  return out;
}

// The help or a usage error, on rank 0.
int say(const World& world, const CommandLine& line) {
  const bool help = line.outcome == CommandLine::Outcome::help;
  if (world.rank == 0) std::fputs(line.said.c_str(), help ? stdout : stderr);
  return help ? cli::exit_ok : cli::exit_usage;
}

}  // namespace
}  // namespace madd::mpi

int main(int argc, char** argv) {
  madd::cli::restart_with_huge_pages(argv);
  using namespace madd::mpi;
  const auto start = std::chrono::steady_clock::now();
  const CommandLine line = read_command_line(argc, argv);
  // Reading, decomposing and meshing this rank's share need no MPI until the
  // first agreement between rounds, and MPI_Init_thread mostly waits on the
  // launcher (0.4 s of wall time for 0.06 s of CPU with Open MPI 4.1 here;
  // docs/mpi.md, "Start-up"): a helper thread starts them meanwhile, under
  // the rank the launcher named (checked once MPI has started, run()). Only
  // this thread calls MPI.
  Decomposed ready;
  EarlyShare early;
  early.guess = launcher_world();
  Funnel funnel;
  std::promise<void> decomposed;
  std::thread helper;
  if (line.outcome == CommandLine::Outcome::run)
    helper = std::thread([&] { start_early(line.args, start, ready, decomposed, early, funnel); });
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  World world;
  MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world.size);
  madd::cli::on_interrupts(on_interrupt);
  int code = 0;
  if (line.outcome == CommandLine::Outcome::run) {
    decomposed.get_future().wait();
    code = run(world, line.args, ready, early, funnel, helper, start);
  } else {
    code = say(world, line);
  }
  MPI_Finalize();
  return code;
}
