// The CLI's option table (cli/option_table.hpp) on its own: every row once,
// with a setter; every command's list names rows, with a help line each and
// no letter twice; an option two commands share means the same in both; a
// deprecated letter still parses; the library's option errors name the flag
// as typed, in the scope of the check that threw.
#include <doctest/doctest.h>

#include <set>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "cli/option_table.hpp"
#include "madd/error.hpp"
#include "madd/mesh.hpp"

namespace {

using namespace madd::cli;

// Parses `words` (after the command's name) with the command's options.
std::string parse(const char* command, std::vector<std::string> words, CommandLine& line) {
  words.insert(words.begin(), command);
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  return parse_command_line(options_of(command), static_cast<int>(words.size()), argv.data(), line);
}

// What an option can have set, as text: the library's options and the front end's.
std::string fingerprint(const CommandLine& l) {
  const madd::DecomposeOptions& d = l.mesh.decomposition;
  const madd::MeshSizeOptions& s = l.mesh.size;
  std::ostringstream out;
  out << d.subdomains << ' ' << d.separator_angle_deg << ' ' << d.boundary_refinement << ' ' << d.min_split_quality
      << ' ' << d.threads << ' ' << d.seed << ' ' << d.smoothing_iterations << ' ' << d.repair_balance_above << ' '
      << d.gradation << ' ' << d.adaptive_boundary_refinement << ' ' << d.interpolation << ' '
      << bool(d.weight_function) << ' ' << bool(d.subdomain_area_function) << ' ' << d.subdomain_area_ratio << ' '
      << d.time_limit_seconds << ' ' << d.max_memory_bytes << " | " << s.min_triangle_angle_deg << ' '
      << s.max_triangle_area << ' ' << bool(s.triangle_area_function) << ' ' << l.sizes_file << ' '
      << static_cast<int>(s.sample_interpolation) << ' ' << s.min_edge_length << ' ' << s.max_edge_length << ' '
      << s.distance_rate << ' ' << s.cells_across << ' ' << s.size_gradation << ' ' << s.coast_markers.size() << ' '
      << l.mesh.balance_by_work << l.mesh.off_centres << l.mesh.verify << " | " << l.output << ' ' << l.report
      << l.report_file << ' ' << l.quiet << l.verbose << l.help << l.subdomains_given << " | "
      << l.coast.clip.has_value() << l.coast.water_at.has_value() << ' ' << l.coast.min_island_area << ' '
      << l.min_island_area_given;
  return out.str();
}

bool takes(const CommandOptions& command, const std::string& name) {
  for (const OptionUse& use : command.uses)
    if (use.name != nullptr && name == use.name) return true;
  return false;
}

}  // namespace

TEST_SUITE("option table") {

TEST_CASE("every row once, with a setter, and taken by some command") {
  std::set<std::string> names;
  for (const Option& row : option_table()) {
    CAPTURE(row.name);
    CHECK(names.insert(row.name).second);
    CHECK(static_cast<bool>(row.set));
    CHECK((row.arity == Arity::none) == (row.value == nullptr));       // a value has a name in the help
    CHECK((row.scope == Scope::front_end) == (row.field == nullptr));  // a library field says where it lives
    bool used = false;
    for (const CommandOptions& command : command_options()) used = used || takes(command, row.name);
    CHECK(used);
  }
}

TEST_CASE("every command's list names rows, each once with a help line, and no letter twice") {
  for (const CommandOptions& command : command_options()) {
    CAPTURE(command.command);
    std::set<std::string> names;
    std::set<char> letters;
    const std::string help = options_help(command);
    for (const OptionUse& use : command.uses) {
      if (use.name == nullptr) continue;
      CAPTURE(use.name);
      const Option* row = find_option(use.name);
      REQUIRE(row != nullptr);
      CHECK(names.insert(use.name).second);
      const char letter = letter_of(use);
      if (letter != 0) CHECK(letters.insert(letter).second);
      if (use.help == nullptr) continue;  // named by the help's own text (partition's gpmetis spellings)
      CHECK(std::string(use.help).size() > 0);
      CHECK(help.find("--" + std::string(use.name)) != std::string::npos);
      if (use.letter == Letter::usual && letter != 0)
        CHECK(help.find(std::string("-") + letter + ", --" + use.name) != std::string::npos);
      if (use.letter == Letter::deprecated) {  // not beside the flag, but said in its help
        CHECK(help.find(std::string("-") + letter + ", --" + use.name) == std::string::npos);
        CHECK(std::string(use.help).find(std::string("-") + letter) != std::string::npos);
        CHECK(std::string(use.help).find("deprecated") != std::string::npos);
      }
    }
    CHECK(names.count("help") == 1);
  }
}

TEST_CASE("madd mesh keeps Triangle's letters; decompose's -q and -a still parse, deprecated") {
  CommandLine mesh;
  REQUIRE(parse("mesh", {"-q", "25", "-a", "0.5", "in.poly"}, mesh).empty());
  CHECK(mesh.mesh.size.min_triangle_angle_deg == 25);
  CHECK(mesh.mesh.size.max_triangle_area == 0.5);
  CHECK_FALSE(mesh.quiet);
  CommandLine decompose;
  REQUIRE(parse("decompose", {"-q", "-a", "2", "in.poly"}, decompose).empty());
  CHECK(decompose.quiet);
  CHECK(decompose.mesh.decomposition.gradation == 2);
  CHECK(decompose.typed.at("weight-gradation").flag == "-a");
  CHECK(decompose.operands == std::vector<std::string>{"in.poly"});
}

TEST_CASE("an option decompose and mesh share sets the same thing in both") {
  const CommandOptions& decompose = options_of("decompose");
  const CommandOptions& mesh = options_of("mesh");
  int shared = 0;
  for (const OptionUse& use : decompose.uses) {
    if (use.name == nullptr || !takes(mesh, use.name)) continue;
    CAPTURE(use.name);
    ++shared;
    const Option& row = *find_option(use.name);
    std::vector<std::string> words = {"--" + std::string(use.name)};
    // A number, an expression and a file name alike; the coast's box and point take lists.
    const std::map<std::string, std::string> lists = {{"clip", "0,0,1,1"}, {"water-at", "0.5,0.5"}};
    if (row.arity == Arity::required) words.push_back(lists.count(use.name) ? lists.at(use.name) : "3");
    CommandLine a, b;
    CHECK(parse("decompose", words, a).empty());
    CHECK(parse("mesh", words, b).empty());
    CHECK(fingerprint(a) == fingerprint(b));
    CHECK(fingerprint(a) != fingerprint(CommandLine{}));  // and it did set something
  }
  CHECK(shared >= 13);  // -n, --min-angle, -j, --seed, --rebalance, --time-limit, --max-memory, --max-area, ...
}

TEST_CASE("the size field's flags set their fields, in mesh and decompose alike") {
  for (const char* command : {"mesh", "decompose"}) {
    CAPTURE(command);
    CommandLine line;
    REQUIRE(parse(command,
                  {"--hmin", "0.1", "--hmax", "2.5", "--distance-rate", "0.15", "--cells-across", "3", "--gradation",
                   "0.2", "--coast-markers", "1,-2,30", "--sizes", "s.node", "--sizes-nearest", "in.poly"},
                  line)
                .empty());
    const madd::MeshSizeOptions& s = line.mesh.size;
    CHECK(s.min_edge_length == 0.1);
    CHECK(s.max_edge_length == 2.5);
    CHECK(s.distance_rate == 0.15);
    CHECK(s.cells_across == 3);
    CHECK(s.size_gradation == 0.2);
    CHECK(s.coast_markers == std::vector<int>{1, -2, 30});
    CHECK(line.sizes_file == "s.node");
    CHECK(s.sample_interpolation == madd::MeshSizeOptions::SampleInterpolation::nearest);
    CHECK(line.mesh.decomposition.gradation == 0);  // --gradation is not the decomposition's
    CHECK_NOTHROW(madd::check_options(line.mesh));
    CommandLine plain;  // without --sizes-nearest, --sizes is read linearly
    REQUIRE(parse(command, {"--sizes", "s.node", "--coast-markers", "4", "--coast-markers", "5", "in.poly"}, plain)
                .empty());
    CHECK(plain.mesh.size.sample_interpolation == madd::MeshSizeOptions::SampleInterpolation::linear);
    CHECK(plain.mesh.size.coast_markers == std::vector<int>{5});  // the last list given, as for any option
  }
}

TEST_CASE("--gradation is the size field's; the decomposition's grading factor is --weight-gradation (or -a)") {
  for (const std::vector<std::string>& words :
       {std::vector<std::string>{"--weight-gradation", "3"}, std::vector<std::string>{"-a", "3"}}) {
    CommandLine line;
    REQUIRE(parse("decompose", words, line).empty());
    CHECK(line.mesh.decomposition.gradation == 3);
    CHECK(line.mesh.size.size_gradation == 0);
  }
  CommandLine size;
  REQUIRE(parse("decompose", {"--gradation", "0.5"}, size).empty());
  CHECK(size.mesh.size.size_gradation == 0.5);
  CHECK(size.mesh.decomposition.gradation == 0);
  CommandLine mesh;  // madd mesh grades the size field only; -a is its largest area
  CHECK(parse("mesh", {"--weight-gradation", "3"}, mesh) == "unknown option '--weight-gradation'");
  // The decomposition's errors about its factor name --weight-gradation in decompose.
  const madd::OptionError factor("gradation", "must be a finite number >= 0");
  CommandLine typed;
  REQUIRE(parse("decompose", {"--weight-gradation", "-1"}, typed).empty());
  CHECK(cli_message(factor, Scope::decomposition, options_of("decompose"), typed) ==
        "--weight-gradation must be a finite number >= 0, got '-1'");
}

TEST_CASE("a bad size field value names the flag as typed; so do the library's size checks") {
  CommandLine line;
  CHECK(parse("mesh", {"--hmin", "x"}, line) == "--hmin needs a number, got 'x'");
  CHECK(parse("decompose", {"--distance-rate", "inf"}, line) == "--distance-rate needs a number, got 'inf'");
  CHECK(parse("mesh", {"--gradation", "0.1.2"}, line) == "--gradation needs a number, got '0.1.2'");
  for (const char* list : {"", "x", "1,", ",1", "1,,2", "1.5", "1, 2", "+1", "99999999999", "1;2"}) {
    CAPTURE(list);
    CommandLine markers;
    CHECK(parse("mesh", {"--coast-markers", list}, markers) ==
          std::string("--coast-markers needs whole numbers separated by commas, got '") + list + "'");
    CHECK(parse("decompose", {"--coast-markers", list}, markers) ==
          std::string("--coast-markers needs whole numbers separated by commas, got '") + list + "'");
  }
  // The library's refusals, in the words of the command.
  const auto said = [](const char* command, std::vector<std::string> words) {
    CommandLine l;
    REQUIRE(parse(command, std::move(words), l).empty());
    try {
      madd::check_options(l.mesh);
    } catch (const madd::OptionError& e) {
      return cli_message(e, Scope::mesh_size, options_of(command), l);
    }
    return std::string();
  };
  CHECK(said("mesh", {"--hmin", "-1"}) == "--hmin must be finite and >= 0, got '-1'");
  CHECK(said("mesh", {"--hmin", "0.2", "--hmax", "0.1"}) == "--hmax must be >= --hmin, got '0.1'");
  CHECK(said("decompose", {"--cells-across", "-2"}) == "--cells-across must be finite and >= 0, got '-2'");
  const std::string rate = said("mesh", {"--distance-rate", "0.15"});
  CHECK_MESSAGE(rate.rfind("--distance-rate needs --hmin > 0", 0) == 0, rate);
  const std::string grade = said("mesh", {"--gradation", "0.2"});
  CHECK_MESSAGE(grade.rfind("--gradation needs a size bound to grade (--hmax, --distance-rate, --cells-across, "
                            "--wavelength-cells, --slope-cells, --max-area, --size-fn or --sizes)",
                            0) == 0,
                grade);
  CHECK(said("mesh", {"--gradation", "0.2", "--hmax", "1"}).empty());
  // A check made inside a run (the coast markers against the domain) finds its flag without a scope.
  const madd::OptionError markers("coast_markers", "must name boundary markers of the domain");
  CHECK(cli_message(markers, options_of("mesh"), CommandLine{}) ==
        "--coast-markers must name boundary markers of the domain");
  CHECK(cli_message(madd::OptionError("separator_angle_deg", "must be right"), options_of("decompose"), line) ==
        "--min-angle must be right");
}

TEST_CASE("a bad value names the flag as typed; the library's errors too, in the scope that threw") {
  CommandLine line;
  CHECK(parse("mesh", {"-j", "x"}, line) == "-j needs a whole number, got 'x'");
  CHECK(parse("mesh", {"--threads", "x"}, line) == "--threads needs a whole number, got 'x'");
  CHECK(parse("mesh", {"--min-angle", "95", "-q", "70", "in.poly"}, line).empty());
  const CommandOptions& mesh = options_of("mesh");
  const madd::OptionError separator_angle("separator_angle_deg", "must be right");
  const madd::OptionError triangle_angle("min_triangle_angle_deg", "must be right");
  CHECK(cli_message(separator_angle, Scope::decomposition, mesh, line) == "--min-angle must be right, got '95'");
  CHECK(cli_message(triangle_angle, Scope::mesh_size, mesh, line) == "-q must be right, got '70'");
  CHECK(cli_message(triangle_angle, Scope::mesh_size, mesh, CommandLine{}) == "--quality must be right");
  // A field of one scope is no field of the other: its name is kept.
  CHECK(cli_message(triangle_angle, Scope::decomposition, mesh, line) == "min_triangle_angle_deg must be right");
  // Fields in the requirement become long flags; a field no option sets keeps its name.
  const madd::OptionError conflict("weight_samples", "cannot be combined with weight_function");
  CHECK(cli_message(conflict, Scope::decomposition, options_of("decompose"), CommandLine{}) ==
        "--weights cannot be combined with --weight-fn");
  CHECK(cli_message(madd::OptionError("max_split_retries", "must be small"), Scope::decomposition, mesh, line) ==
        "max_split_retries must be small");
  CHECK(parse("mesh", {"--msh=1"}, line) == "option '--msh' takes no value");
  CHECK(parse("mesh", {"--nosuch"}, line) == "unknown option '--nosuch'");
  CHECK(parse("mesh", {"-n"}, line) == "option '-n' needs a value");
}

}  // TEST_SUITE("option table")
