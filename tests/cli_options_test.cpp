// The CLI only parses options: ranges and conflicts come from the library's
// check_options, a bad option is exit 2 naming the flag, and nothing is
// written. Runs the madd binary (skipped when the CLI is not built).
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "cli/option_table.hpp"
#include "cli_sandbox.hpp"
#include "madd/decomposition.hpp"

#ifdef MADD_CLI_PATH

namespace {

namespace fs = std::filesystem;

using madd_test::CliRun;
using madd_test::CliSandbox;

const std::string key_poly = std::string(MADD_DATA_DIR) + "/key.poly";
const std::string pipe_poly = std::string(MADD_DATA_DIR) + "/pipe.poly";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The first line of the output after "madd COMMAND: ".
std::string problem_of(const std::string& output, const std::string& command) {
  const std::string prefix = "madd " + command + ": ";
  const std::size_t at = output.find(prefix);
  if (at == std::string::npos) return {};
  const std::size_t from = at + prefix.size();
  return output.substr(from, output.find('\n', from) - from);
}

}  // namespace

TEST_SUITE("cli options") {

TEST_CASE("an option out of its range is a usage error naming the flag, and nothing is written") {
  const CliSandbox box;
  struct Bad {
    const char* arguments;
    const char* says;
  };
  const Bad cases[] = {
      {"--min-angle 0", "--min-angle must lie strictly between 0 and 90 degrees, got '0'"},
      {"--min-angle 90", "--min-angle"},
      {"-n 0", "-n must be at least 1"},  // the flag as typed, short or long
      {"--subdomains 0", "--subdomains must be at least 1"},
      {"-i 0", "-i must lie in (0, 1]"},
      {"--imbalance 1.5", "--imbalance must lie in (0, 1]"},
      {"-j 5000", "-j must be at most 4096"},
      {"--threads 5000", "--threads must be at most 4096"},
      {"--smoothing 1001", "--smoothing"},
      {"-r 0", "-r must be"},
      {"--refine 0", "--refine must be"},
      {"-a -1", "-a must be"},  // the deprecated letter still works, and is named as typed
      {"--weight-gradation -1", "--weight-gradation must be"},
      {"--gradation -1", "--gradation must be finite and >= 0, got '-1'"},  // the size field's now
      {"--time-limit -1", "--time-limit"},
      {"--svg-mark-angles 200", "--svg-mark-angles"},
      {"-p 0.5", "-p only applies to boundary weights (--weight-gradation > 0"},
      {"--interpolation 0.5", "--interpolation only applies to boundary weights"},
      {"--weight-fn 1 --weights w.node", "--weights cannot be combined with --weight-fn"},
      {"--area-fn 1 --areas a.node", "--areas cannot be combined with --area-fn"},
  };
  for (const Bad& c : cases) {
    CAPTURE(c.arguments);
    const CliRun r = box.run(key_poly + " -o out.poly " + c.arguments);
    CHECK(r.status == 2);
    CHECK_MESSAGE(contains(r.output, c.says), r.output);
    CHECK_FALSE(fs::exists(box.path("out.poly")));
  }
}

TEST_CASE("madd mesh names the flag typed: --min-angle is the separators' angle, -q and --quality the triangles'") {
  const CliSandbox box;
  const CliRun phi = box.run("mesh " + key_poly + " -n 4 -o m --min-angle 95");
  CHECK(phi.status == 2);
  CHECK_MESSAGE(problem_of(phi.output, "mesh").rfind("--min-angle must lie strictly between 0 and 90 degrees", 0) == 0,
                phi.output);
  for (const std::string flag : {"-q", "--quality"}) {
    CAPTURE(flag);
    const CliRun r = box.run("mesh " + key_poly + " -n 4 -o m " + flag + " 95");
    CHECK(r.status == 2);
    CHECK_MESSAGE(problem_of(r.output, "mesh").rfind(flag + " must lie in [0, 60) degrees", 0) == 0, r.output);
  }
  for (const std::string flag : {"-a", "--max-area"}) {  // checked while parsing: the flag as typed too
    CAPTURE(flag);
    CHECK(problem_of(box.run("mesh " + key_poly + " -n 4 -o m " + flag + " 0").output, "mesh") ==
          flag + " needs an area > 0, got '0'");
  }
  CHECK_FALSE(fs::exists(box.path("m.ele")));
}

TEST_CASE("a command of one input refuses none or two, naming what it expected, and writes nothing") {
  const CliSandbox box;
  const std::pair<std::string, std::string> commands[] = {{"check", "one input file"},
                                                          {"decompose", "one input file"},
                                                          {"triangulate", "one input file"},
                                                          {"mesh", "one input file"},
                                                          {"script", "one script file (or '-' for stdin)"}};
  for (const auto& named : commands) {
    const std::string& command = named.first;
    const std::string& expected = named.second;
    for (const std::string& operands : {std::string(), key_poly + " " + pipe_poly}) {
      CAPTURE(command);
      CAPTURE(operands);
      const CliRun r = box.run(command + " " + operands);
      CHECK(r.status == 2);
      CHECK_MESSAGE(problem_of(r.output, command) == "expected exactly " + expected, r.output);
    }
  }
  CHECK(box.run("check " + key_poly).status == 0);  // one is right
  std::size_t entries = 0;                          // nothing written but the runs' log
  for (const auto& e : fs::directory_iterator(box.path(""))) entries += e.path().filename() != "log";
  CHECK(entries == 0);
}

TEST_CASE("-j has one limit, the library's max_threads, said alike by decompose and mesh") {
  const CliSandbox box;
  const std::string above = std::to_string(madd::max_threads + 1);
  for (const std::string flag : {"-j", "--threads"}) {
    CAPTURE(flag);
    const CliRun decompose = box.run(key_poly + " -n 2 -o out.poly " + flag + " " + above);
    const CliRun mesh = box.run("mesh " + key_poly + " -n 2 -o m " + flag + " " + above);
    CHECK(decompose.status == 2);
    CHECK(mesh.status == 2);
    const std::string said = problem_of(decompose.output, "decompose");
    CHECK(said == problem_of(mesh.output, "mesh"));
    CHECK_MESSAGE(said.rfind(flag + " must be at most " + std::to_string(madd::max_threads), 0) == 0, said);
  }
  const std::string at_limit = " -j " + std::to_string(madd::max_threads);  // the limit itself is taken
  CHECK(box.run(key_poly + " -n 2 --quiet" + at_limit).status == 0);
  CHECK(box.run("mesh " + key_poly + " -n 2 --quiet -o m" + at_limit).status == 0);
  CHECK_FALSE(fs::exists(box.path("out.poly")));
}

TEST_CASE("every option decompose and mesh share is taken by both commands") {
  const CliSandbox box;
  // A value on key.poly for each shared option (a new shared option needs one here).
  std::map<std::string, std::string> value = {{"subdomains", " 3"},    {"min-angle", " 50"},  {"threads", " 2"},
                                              {"seed", " 7"},          {"rebalance", " 1.5"}, {"time-limit", " 60"},
                                              {"max-memory", " 4000"}, {"max-area", " 0.05"}, {"size-fn", " 0.05+x*x"},
                                              {"output", " o"},        {"report", "=r.json"}, {"no-verify", ""},
                                              {"quiet", ""},           {"help", ""}};
  // The size field's, with what they need: --distance-rate and --cells-across a --hmin, --gradation a bound to grade.
  value.insert({{"sizes", " s.node"},
                {"sizes-nearest", " --sizes s.node"},
                {"hmin", " 0.1"},
                {"hmax", " 0.5"},
                {"distance-rate", " 0.3 --hmin 0.1"},
                {"cells-across", " 3 --hmin 0.1"},
                {"gradation", " 0.3 --hmax 0.5"},
                {"coast-markers", " 1"}});
  // A GeoJSON input's (tests/coast_cli_test.cpp has the rest).
  value.insert({{"clip", " -70.45,43.05,-70.05,43.45"}, {"water-at", " -70.3,43.02"}, {"min-island-area", " 1e6"}});
  std::ofstream(box.path("s.node")) << "4 2 1 0\n1 -2 -2 0.05\n2 8 -2 0.05\n3 8 2 0.05\n4 -2 2 0.02\n";
  const madd::cli::CommandOptions& mesh = madd::cli::options_of("mesh");
  int shared = 0;
  for (const madd::cli::OptionUse& use : madd::cli::options_of("decompose").uses) {
    if (use.name == nullptr) continue;
    bool in_mesh = false;
    for (const madd::cli::OptionUse& m : mesh.uses)
      in_mesh = in_mesh || (m.name != nullptr && std::string(m.name) == use.name);
    if (!in_mesh) continue;
    CAPTURE(use.name);
    ++shared;
    REQUIRE(value.count(use.name) == 1);
    const std::string option = " --" + std::string(use.name) + value.at(use.name);
    // A GeoJSON input's options on a GeoJSON input.
    const bool coast = madd::cli::find_option(use.name)->scope == madd::cli::Scope::coast;
    const std::string input = coast ? std::string(MADD_DATA_DIR) + "/coast/lagoon.geojson" : key_poly;
    const CliRun decompose = box.run(input + " -n 4 --quiet" + option);
    const CliRun meshed = box.run("mesh " + input + " -n 4 --quiet -o m" + option);
    CHECK_MESSAGE(decompose.status == 0, decompose.output);
    CHECK_MESSAGE(meshed.status == 0, meshed.output);
  }
  CHECK(shared == static_cast<int>(value.size()));
}

TEST_CASE("every command's --help lists every option it takes, as the table has it") {
  const CliSandbox box;
  for (const madd::cli::CommandOptions& command : madd::cli::command_options()) {
    CAPTURE(command.command);
    const CliRun help = box.run(std::string(command.command) + " --help");
    CHECK(help.status == 0);
    for (const madd::cli::OptionUse& use : command.uses) {
      if (use.name == nullptr) continue;
      CAPTURE(use.name);
      // An option without a line of its own is named by the text, gpmetis's way (-ptype=rb).
      CHECK(contains(help.output, (use.help != nullptr ? "--" : "-") + std::string(use.name)));
      if (const char letter = madd::cli::letter_of(use); letter != 0)
        CHECK(contains(help.output, std::string("-") + letter));
    }
  }
  const std::string decompose = box.run("decompose --help").output;  // the letters mesh took over, said once
  CHECK(contains(decompose, "-q is deprecated here"));
  CHECK(contains(decompose, "-a A is deprecated here"));
  CHECK(contains(decompose, "(was --gradation, now the size field's"));  // the rename, said where it was
}

TEST_CASE("the size field's options: a bad value or combination is a usage error naming the flag, in mesh and "
          "decompose, and nothing is written") {
  const CliSandbox box;
  struct Bad {
    const char* arguments;
    const char* says;
  };
  const Bad cases[] = {
      {"--hmin -1", "--hmin must be finite and >= 0, got '-1'"},
      {"--hmax x", "--hmax needs a number, got 'x'"},
      {"--hmin 0.2 --hmax 0.1", "--hmax must be >= --hmin, got '0.1'"},
      {"--distance-rate 0.15", "--distance-rate needs --hmin > 0"},
      {"--cells-across -3", "--cells-across must be finite and >= 0, got '-3'"},
      {"--gradation 0.2", "--gradation needs a size bound to grade"},
      {"--gradation nan --hmax 1", "--gradation needs a number, got 'nan'"},
      {"--coast-markers 1,x", "--coast-markers needs whole numbers separated by commas, got '1,x'"},
      {"--coast-markers=", "--coast-markers needs whole numbers separated by commas, got ''"},
  };
  for (const Bad& c : cases) {
    CAPTURE(c.arguments);
    const CliRun decompose = box.run(key_poly + " -n 4 -o out.poly --split parts " + c.arguments);
    CHECK(decompose.status == 2);
    CHECK_MESSAGE(problem_of(decompose.output, "decompose").rfind(c.says, 0) == 0, decompose.output);
    const CliRun mesh = box.run("mesh " + key_poly + " -n 4 -o m " + c.arguments);
    CHECK(mesh.status == 2);
    CHECK_MESSAGE(problem_of(mesh.output, "mesh").rfind(c.says, 0) == 0, mesh.output);
  }
  // --gradation was decompose's grading factor: the refusal says where that went.
  const CliRun old = box.run(key_poly + " -n 4 -o out.poly --gradation 3");
  CHECK(old.status == 2);
  CHECK_MESSAGE(contains(old.output, "(grading by weights is --weight-gradation)"), old.output);
  CHECK_FALSE(fs::exists(box.path("out.poly")));
  CHECK_FALSE(fs::exists(box.path("parts")));
  CHECK_FALSE(fs::exists(box.path("m.ele")));
}

TEST_CASE("grading options that would be ignored are refused") {
  const CliSandbox box;
  // key.poly has no vertex weights: -a has nothing to grade by.
  const CliRun r = box.run(key_poly + " -n 8 --weight-gradation 3 -o out.poly");
  CHECK(r.status == 2);
  CHECK_MESSAGE(contains(r.output, "--weight-gradation grades by the domain's vertex weights"), r.output);
  CHECK_MESSAGE(contains(box.run(key_poly + " -n 8 -a 3 -o out.poly").output, "-a grades by"), r.output);
  CHECK_FALSE(fs::exists(box.path("out.poly")));
}

TEST_CASE("an area function of 0, negative or NaN is refused, like an --areas file with such a value") {
  const CliSandbox box;
  for (const char* function : {"0", "-1", "sqrt(-1)", "x-100"}) {
    CAPTURE(function);
    const CliRun r = box.run(pipe_poly + " -n 64 -o out.poly --area-fn '" + function + "'");
    CHECK(r.status == 2);
    CHECK_MESSAGE(contains(r.output, "--area-fn must be finite and > 0 everywhere in the domain"), r.output);
    CHECK_FALSE(fs::exists(box.path("out.poly")));
  }
  std::ofstream(box.path("zero.node")) << "2 2 1 0\n1 0 0 0.5\n2 1 1 0\n";
  const CliRun file = box.run(pipe_poly + " -n 64 -o out.poly --areas zero.node");
  CHECK(file.status == 3);  // a bad value in a file is bad input, located at its line
  CHECK_MESSAGE(contains(file.output, "zero.node:3:1: node 2: a required area must be > 0"), file.output);
  CHECK_FALSE(fs::exists(box.path("out.poly")));
}

TEST_CASE("reaching N in required-area mode is said in the summary and the report") {
  const CliSandbox box;
  const CliRun r = box.run(pipe_poly + " -n 10 --area-fn 0.0005 --report=r.json");
  REQUIRE_MESSAGE(r.status == 0, r.output);
  CHECK_MESSAGE(contains(r.output, "the maximum of 10 subdomains was reached with 10 still above the area bound"),
                r.output);
  std::ifstream in(box.path("r.json"));
  std::ostringstream report;
  report << in.rdbuf();
  CHECK(contains(report.str(), "\"subdomains_over_area_bound\": 10"));
  CHECK(contains(report.str(), "\"max_area_over_required\": "));

  // Reached before N: no note.
  const CliRun enough = box.run(pipe_poly + " -n 100000 --area-fn 0.05");
  REQUIRE_MESSAGE(enough.status == 0, enough.output);
  CHECK_MESSAGE(contains(enough.output, "required area: largest area / required area"), enough.output);
  CHECK_FALSE(contains(enough.output, "still above the area bound"));
}

TEST_CASE("the set of outputs is all or nothing: a failed write leaves no output of the run behind") {
  const CliSandbox box;
  const CliRun failed = box.run(key_poly + " -n 4 -o ok.poly --split parts --report=r.json --svg /nonexistent/x.svg");
  CHECK(failed.status == 5);
  CHECK_MESSAGE(contains(failed.output, "/nonexistent/x.svg"), failed.output);
  CHECK_FALSE(fs::exists(box.path("ok.poly")));
  CHECK_FALSE(fs::exists(box.path("parts")));
  CHECK_FALSE(fs::exists(box.path("r.json")));
  for (const auto& entry : fs::directory_iterator(box.path(".")))  // no temporary either
    CHECK_MESSAGE(entry.path().filename() == "log", entry.path().string());

  // Outputs of an earlier run stay as they were when a later run fails.
  REQUIRE(box.run(key_poly + " -n 4 -q -o ok.poly --split parts").status == 0);
  const auto before = fs::last_write_time(box.path("ok.poly"));
  std::ifstream first(box.path("ok.poly"));
  std::ostringstream old_text;
  old_text << first.rdbuf();
  CHECK(box.run(key_poly + " -n 6 -o ok.poly --split parts --geo /nonexistent/g.geo").status == 5);
  std::ifstream second(box.path("ok.poly"));
  std::ostringstream new_text;
  new_text << second.rdbuf();
  CHECK(new_text.str() == old_text.str());
  CHECK(fs::last_write_time(box.path("ok.poly")) == before);
  CHECK(fs::exists(box.path("parts/key-3.poly")));
  CHECK_FALSE(fs::exists(box.path("parts/key-5.poly")));

  // One path named by two outputs is a usage error before any work.
  const CliRun twice = box.run(key_poly + " -n 4 -o same.poly --geo ./same.poly");
  CHECK(twice.status == 2);
  CHECK_MESSAGE(contains(twice.output, "is named by two outputs"), twice.output);
}

}  // TEST_SUITE("cli options")

#endif
