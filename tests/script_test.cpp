// The script language of include/madd/script.hpp (the paper's maddi, Sec. 6):
// the paper's example on the pipe, set parsing, every error with its line,
// the outputs read back.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "madd/error.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"
#include "madd/script.hpp"
#include "scratch_files.hpp"

namespace {

using namespace madd;
using madd::test::read_text;
using madd::test::TempDir;
namespace fs = std::filesystem;

// Runs the test body with `dir` as the current directory, restoring it after.
struct ChangeDirectory {
  fs::path saved = fs::current_path();
  explicit ChangeDirectory(const fs::path& dir) { fs::current_path(dir); }
  ~ChangeDirectory() {
    std::error_code ignored;
    fs::current_path(saved, ignored);
  }
};

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

Pslg unit_square() {
  Pslg square;
  square.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  square.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  square.has_segment_markers = true;
  return square;
}

// A context with the unit square preloaded and one thread (deterministic and light).
ScriptContext square_context() {
  ScriptContext context;
  context.domain = unit_square();
  context.domain_name = "square";
  context.options.threads = 1;
  return context;
}

// Runs `text` as "s.txt" on a fresh square context; it must throw an E,
// which `check` then examines (with its message captured).
template <class E, class Check>
void expect_script_error(const std::string& text, Check&& check) {
  CAPTURE(text);
  ScriptContext context = square_context();
  try {
    run_script(text, "s.txt", context);
    FAIL("no error");
  } catch (const E& e) {
    const std::string what = e.what();
    CAPTURE(what);
    check(e, what);
  }
}

// A bad option value: an OptionError for `field`, located at line:column, whose message contains `part`.
void check_script_option_error(const std::string& text, std::size_t line, std::size_t column, const std::string& field,
                               const std::string& part) {
  expect_script_error<OptionError>(text, [&](const OptionError& e, const std::string& what) {
    CHECK(e.option() == field);
    CHECK(what.rfind("s.txt:" + std::to_string(line) + ":" + std::to_string(column) + ": ", 0) == 0);
    CHECK(what.find(part) != std::string::npos);
  });
}

// The script's own problem: a ParseError on `line` (and `column`, when given) whose message contains `part`.
void check_script_error(const std::string& text, std::size_t line, const std::string& part, std::size_t column = 0) {
  expect_script_error<ParseError>(text, [&](const ParseError& e, const std::string& what) {
    CHECK(e.path() == "s.txt");
    CHECK(e.line() == line);
    if (column != 0) CHECK(e.column() == column);
    CHECK(what.find(part) != std::string::npos);
  });
}

}  // namespace

TEST_SUITE("script") {

TEST_CASE("the paper's example runs on the pipe (Sec. 6), relative to the current directory") {
  TempDir tmp("paper");
  fs::copy_file(fs::path(MADD_DATA_DIR) / "pipe.poly", tmp.path / "pipe.poly");
  const ChangeDirectory cd(tmp.path);
  ScriptContext context;
  context.options.threads = 1;
  std::vector<std::string> log;
  context.log = [&](const std::string& line) { log.push_back(line); };
  // The paper's script with N = 40 instead of 400, to stay fast.
  const ScriptResult result = run_script("read pipe.poly\nset f=0.35\ndec 40\nwrite pipe40.poly\n"
                                         "writeSubdomains pipe40.dat\nexit\n",
                                         "paper.txt", context);
  CHECK(result.exited);
  CHECK(result.commands == 6);
  CHECK(log.size() == 5);
  CHECK(context.options.separator_angle_deg == doctest::Approx(63.0));
  REQUIRE(context.decomposition);
  const Decomposition& d = *context.decomposition;
  CHECK(d.subdomains.size() == 40);
  const Pslg pipe = read_domain("pipe.poly");
  CHECK(verify_decomposition(d, pipe, 40).ok());
  const PolyFile written = parse_poly(read_text("pipe40.poly"), "pipe40.poly");
  CHECK(written.pslg.points == d.points);
  CHECK(written.pslg.segments.size() == d.segments.size());
  CHECK(written.pslg.regions.size() == 40);
  CHECK(written.pslg.holes == d.holes);
  const std::string table = read_text("pipe40.dat");
  CHECK(table.find(std::to_string(d.points.size()) + " 2") != std::string::npos);
  // Nothing else was left in the directory (no temporary files).
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(tmp.path)) files += entry.is_regular_file() ? 1 : 0;
  CHECK(files == 3);
}

TEST_CASE("set parses every parameter, with or without blanks around '='") {
  ScriptContext context = square_context();
  run_script("set f=0.25\nset r = 2.5\nset a =3 p= 0.5\n set i=0.8 s=2 ratio=1.5\tn=12\n"
             "set j=2 seed=9\nset smooth=3 threads=1\n",
             "s.txt", context);
  const DecomposeOptions& o = context.options;
  CHECK(o.separator_angle_deg == doctest::Approx(45.0));
  CHECK(o.boundary_refinement == 2.5);
  CHECK(o.gradation == 3.0);
  CHECK(o.interpolation == 0.5);
  CHECK(o.min_split_quality == 0.8);
  CHECK(o.subdomain_area_ratio == 1.5);
  CHECK(o.subdomains == 12);
  CHECK(o.seed == 9);
  CHECK(o.smoothing_iterations == 3);
  CHECK(o.threads == 1);
  // A line with one bad assignment changes nothing.
  CHECK_THROWS_AS(run_script("set r=7 i=2", "s.txt", context), OptionError);
  CHECK(context.options.boundary_refinement == 2.5);
}

TEST_CASE("comments, blank lines, dec without N, and exit stopping the script") {
  ScriptContext context = square_context();
  const ScriptResult result =
      run_script("# a comment\n\n   \nset n=3 # trailing comment\r\ndec\nexit\nthis is not run\n", "s.txt", context);
  CHECK(result.exited);
  CHECK(result.commands == 3);
  REQUIRE(context.decomposition);
  CHECK(context.decomposition->subdomains.size() == 3);
  CHECK(verify_decomposition(*context.decomposition, unit_square(), 3).ok());
  const ScriptResult no_exit = run_script("dec 2", "s.txt", context);
  CHECK_FALSE(no_exit.exited);
  CHECK(context.decomposition->subdomains.size() == 2);
  CHECK(context.options.subdomains == 2);  // `dec N` also sets n
}

TEST_CASE("every script error names its line and column") {
  check_script_error("\n# c\nfoo\n", 3, "unknown command 'foo'", 1);
  check_script_error("set f=0.35\nset  q=1", 2, "unknown parameter 'q'", 6);
  check_script_error("set f", 1, "expected '='", 6);
  check_script_error("set f=", 1, "missing the value", 7);
  check_script_error("set =3", 1, "missing the parameter name", 5);
  check_script_error("set", 1, "missing <parameter>=<value>", 4);
  check_script_error("write x.poly", 1, "run 'dec' first", 1);
  check_script_error("\nwriteSubdomains x.dat", 2, "run 'dec' first");
  check_script_error("dec 2 3", 1, "unexpected '3'", 7);
  check_script_error("dec 2\nwrite a.poly some", 2, "expected 'all'", 14);
  check_script_error("read", 1, "missing argument (usage: read FILE)", 5);
  check_script_error("read \"no end", 1, "unterminated quote", 6);
  check_script_error("exit now", 1, "unexpected 'now'");
  check_script_error("setWeightFunction 1+sine(x)", 1, "unknown function 'sine'", 21);
  check_script_error("setAreaFunction   (1+x", 1, "expected ')'", 23);
  check_script_error("setAreaFunction", 1, "missing the expression", 16);
  check_script_error("setWeightFunction libweights.so weight", 1, "shared libraries are not loaded", 19);
  check_script_error("setAreaFunction /opt/lib/libarea.so.1 area", 1, "expressions", 17);
}

TEST_CASE("a value out of its range is a bad option, located and named as the script spells it") {
  check_script_option_error("set f=0.5", 1, 7, "separator_angle_deg", "f (the minimum angle as a fraction of pi");
  check_script_option_error("set f=0", 1, 7, "separator_angle_deg", "strictly between 0 and 90");
  check_script_option_error("set r=1 s=1.5", 1, 11, "smoothing_iterations", "whole number");
  check_script_option_error("set i=0", 1, 7, "min_split_quality", "(0, 1]");
  check_script_option_error("\nset n=0", 2, 7, "subdomains", "at least 1");
  check_script_option_error("set j=-1", 1, 7, "threads", "whole number");
  check_script_option_error("set j=5000", 1, 7, "threads", "at most 4096");
  check_script_option_error("dec 0", 1, 5, "subdomains", "whole number >= 1");
  check_script_option_error("dec abc", 1, 5, "subdomains", "whole number >= 1");
  check_script_option_error("dec 99999999999", 1, 5, "subdomains", "whole number >= 1");
  // A combination is checked at `dec`, with the script's names.
  check_script_option_error("set p=0.5\ndec 4", 2, 5, "interpolation", "p (interpolation) only applies");
  check_script_option_error("set a=2\ndec 4", 2, 5, "gradation", "a (gradation) grades by the domain's vertex weights");
  check_script_option_error("setAreaFunction 0\ndec 8", 2, 5, "subdomain_area_function",
                            "setAreaFunction must be finite and > 0");
}

TEST_CASE("read starts a fresh domain: background weights and areas do not carry over") {
  TempDir tmp("fresh");
  const std::string domain = (tmp.path / "sq.poly").string();
  const std::string areas = (tmp.path / "a.node").string();
  std::ofstream(domain) << "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n";
  std::ofstream(areas) << "1 2 1 0\n1 0.5 0.5 0.02\n";
  ScriptContext context;
  run_script("read " + domain + "\nread_areas " + areas, "s.txt", context);
  CHECK(context.options.subdomain_area_samples.size() == 1);
  run_script("read " + domain, "s.txt", context);
  CHECK(context.options.subdomain_area_samples.empty());
  run_script("dec 5", "s.txt", context);
  CHECK(context.decomposition->subdomains.size() == 5);  // uniform again: N is the count

  run_script("read_areas " + areas + "\nread_weights none\nread_areas none", "s.txt", context);
  CHECK(context.options.subdomain_area_samples.empty());
  CHECK(context.options.weight_samples.empty());
}

TEST_CASE("dec before read is an error") {
  ScriptContext context;
  try {
    run_script("set f=0.3\ndec 4", "s.txt", context);
    FAIL("no error");
  } catch (const ParseError& e) {
    CHECK(e.line() == 2);
    CHECK(e.message().find("read FILE") != std::string::npos);
  }
}

TEST_CASE("errors of the library keep their type and gain the script line") {
  TempDir tmp("errors");
  const std::string bad = (tmp.path / "bad.poly").string();
  write_text(bad, "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n3 0\n1 1 2\n2 2 3\n3 3 x\n");
  const std::string crossing = (tmp.path / "crossing.poly").string();
  write_text(crossing, "4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n");
  ScriptContext context;
  SUBCASE("a malformed file is a ParseError at the script line, quoting the file's position") {
    try {
      run_script("# read it\nread " + bad, "s.txt", context);
      FAIL("no error");
    } catch (const ParseError& e) {
      CHECK(e.path() == "s.txt");
      CHECK(e.line() == 2);
      CHECK(e.column() == 6);
      INFO(e.message());
      CHECK(e.message().find(bad + ":9:") != std::string::npos);
    }
  }
  SUBCASE("a missing file is bad input naming the file") {
    const std::string missing = (tmp.path / "missing.poly").string();
    try {
      run_script("read " + missing, "s.txt", context);
      FAIL("no error");
    } catch (const ParseError& e) {
      CHECK(e.line() == 1);
      CHECK(e.message().find("missing.poly") != std::string::npos);
    }
  }
  SUBCASE("an invalid domain stays an InvalidInputError") {
    try {
      run_script("\n\nread " + crossing, "s.txt", context);
      FAIL("no error");
    } catch (const InvalidInputError& e) {
      CHECK(std::string(e.what()).rfind("s.txt:3: ", 0) == 0);
      CHECK(e.problem() == InputProblem::segments_intersect);
    }
  }
  SUBCASE("a decomposition error keeps its subdomain") {
    ScriptContext square = square_context();
    square.check_options = [](const DecomposeOptions&) { throw DecompositionError("cannot split", 7, 2.5, 60.0); };
    try {
      run_script("set n=2\ndec", "s.txt", square);
      FAIL("no error");
    } catch (const DecompositionError& e) {
      CHECK(std::string(e.what()) == "s.txt:2: cannot split");
      CHECK(e.subdomain() == 7);
      CHECK(e.area() == 2.5);
    }
  }
  SUBCASE("an unwritable output is an Error naming the line") {
    ScriptContext square = square_context();
    const std::string target = (tmp.path / "no-such-dir" / "x.poly").string();
    try {
      run_script("dec 2\nwrite " + target, "s.txt", square);
      FAIL("no error");
    } catch (const ParseError&) {
      FAIL("an output failure is not a parse error");
    } catch (const Error& e) {
      CHECK(std::string(e.what()).rfind("s.txt:2: ", 0) == 0);
    }
  }
}

TEST_CASE("write FILE all writes one .poly per subdomain into FILE's directory") {
  TempDir tmp("all");
  ScriptContext context = square_context();
  const fs::path parts = tmp.path / "parts";
  run_script("dec 4\nwrite \"" + (parts / "sq.poly").string() + "\" all\n", "s.txt", context);
  REQUIRE(context.decomposition);
  CHECK(context.verified);
  CHECK_FALSE(fs::exists(parts / "sq.poly"));
  double area = 0;
  for (std::uint32_t k = 0; k < 4; ++k) {
    const fs::path file = parts / ("sq-" + std::to_string(k) + ".poly");
    REQUIRE(fs::exists(file));
    const PolyFile p = parse_poly(read_text(file), file.string());
    validate(p.pslg, p.source);
    area += domain_area(p.pslg);
  }
  CHECK(area == doctest::Approx(1.0));
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(parts)) files += entry.is_regular_file() ? 1 : 0;
  CHECK(files == 4);
}

TEST_CASE("read_weights and read_areas take the first attribute of a .node file") {
  TempDir tmp("values");
  const std::string node = (tmp.path / "bg.node").string();
  write_text(node, "# background\n3 2 2 1\n1 0.1 0.1 5 9 0\n2 0.5 0.5 2.5 9 0\n3 0.9 0.2 0.25 9 1\n");
  ScriptContext context;
  run_script("read_weights " + node + "\nread_areas " + node, "s.txt", context);
  const std::vector<ValuedPoint> want{{{0.1, 0.1}, 5.0}, {{0.5, 0.5}, 2.5}, {{0.9, 0.2}, 0.25}};
  CHECK(context.options.weight_samples == want);
  CHECK(context.options.subdomain_area_samples == want);

  const std::string zero = (tmp.path / "zero.node").string();
  write_text(zero, "2 2 1 0\n1 0 0 1\n2 1 1 0\n");
  run_script("read_weights " + zero, "s.txt", context);  // a zero weight is fine
  CHECK(context.options.weight_samples.size() == 2);
  try {
    run_script("\nread_areas " + zero, "s.txt", context);  // a zero area is not
    FAIL("no error");
  } catch (const ParseError& e) {
    CHECK(e.line() == 2);
    CHECK(e.message().find(zero + ":3:") != std::string::npos);
    CHECK(e.message().find("must be > 0") != std::string::npos);
  }
  const std::string bare = (tmp.path / "bare.node").string();
  write_text(bare, "1 2 0 0\n1 0 0\n");
  CHECK_THROWS_WITH_AS(run_script("read_weights " + bare, "s.txt", context),
                       doctest::Contains("one attribute per node"), ParseError);
}

TEST_CASE("setWeightFunction and setAreaFunction compile expressions") {
  ScriptContext context;
  run_script("setWeightFunction 1e-4*(1 + r^12)   # Fig. 13\nsetAreaFunction min(1, exp(-x))", "s.txt", context);
  REQUIRE(context.options.weight_function);
  REQUIRE(context.options.subdomain_area_function);
  CHECK(context.options.weight_function(3.0, 4.0) == doctest::Approx(1e-4 * (1 + std::pow(5.0, 12))));
  CHECK(context.options.subdomain_area_function(1.0, 0.0) == doctest::Approx(std::exp(-1.0)));
  run_script("setWeightFunction none", "s.txt", context);
  CHECK_FALSE(context.options.weight_function);
  CHECK(context.options.subdomain_area_function);
}

TEST_CASE("sandbox: file commands disabled, dec bounded") {
  ScriptContext context = square_context();
  context.allow_files = false;
  context.max_subdomains = 4;
  CHECK_THROWS_WITH_AS(run_script("read x.poly", "s.txt", context), doctest::Contains("disabled"), ParseError);
  CHECK_THROWS_WITH_AS(run_script("read_weights w.node", "s.txt", context), doctest::Contains("disabled"), ParseError);
  CHECK_THROWS_WITH_AS(run_script("dec 5", "s.txt", context), doctest::Contains("limit"), ParseError);
  run_script("dec 4", "s.txt", context);
  CHECK_THROWS_WITH_AS(run_script("write x.poly", "s.txt", context), doctest::Contains("disabled"), ParseError);
  CHECK(context.verified);  // the check ran before the refusal
  CHECK_FALSE(fs::exists("x.poly"));
}

TEST_CASE("a decomposition that fails verification is never written") {
  TempDir tmp("verify");
  ScriptContext context = square_context();
  run_script("dec 2", "s.txt", context);
  REQUIRE(context.decomposition);
  context.decomposition->subdomains.pop_back();  // now it covers half the square
  context.verified = false;
  const fs::path out = tmp.path / "wrong.poly";
  CHECK_THROWS_AS(run_script("write " + out.string(), "s.txt", context), InternalError);
  CHECK_FALSE(fs::exists(out));
}

}  // TEST_SUITE("script")
