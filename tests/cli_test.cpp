// The madd binary as a new user meets it: subcommand dispatch and help,
// gpmetis spellings for `partition`, option order, point sets for
// `triangulate` and `check`, and the progress line on a terminal. Each test
// runs the CLI (MADD_CLI_PATH) in a scratch directory; skipped without it.
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "madd/geometry.hpp"

#ifdef MADD_CLI_PATH

namespace {

namespace fs = std::filesystem;

struct Scratch {
  fs::path path;
  explicit Scratch(const std::string& tag) {
    path = fs::temp_directory_path() / ("madd-cli-test-" + tag + "-" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  fs::path operator/(const std::string& name) const { return path / name; }
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

struct Result {
  int code = -1;
  std::string out, err;
};

int exit_status(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }

// Runs `madd ARGS` (ARGS is shell text) in `dir`; captures stdout and stderr.
Result run_madd(const Scratch& dir, const std::string& args) {
  const std::string command =
      "cd '" + dir.path.string() + "' && '" MADD_CLI_PATH "' " + args + " > stdout.txt 2> stderr.txt";
  Result r;
  r.code = exit_status(std::system(command.c_str()));
  r.out = slurp(dir / "stdout.txt");
  r.err = slurp(dir / "stderr.txt");
  fs::remove(dir / "stdout.txt");
  fs::remove(dir / "stderr.txt");
  return r;
}

const std::string data_dir = MADD_DATA_DIR;

// A w x h grid graph in METIS format (vertex ids 1-based).
std::string grid_graph(int w, int h) {
  std::ostringstream s;
  s << w * h << ' ' << (w - 1) * h + w * (h - 1) << '\n';
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int v = y * w + x + 1;
      if (x > 0) s << v - 1 << ' ';
      if (x + 1 < w) s << v + 1 << ' ';
      if (y > 0) s << v - w << ' ';
      if (y + 1 < h) s << v + w << ' ';
      s << '\n';
    }
  }
  return s.str();
}

std::size_t line_count(const std::string& text) {
  std::size_t n = 0;
  for (const char c : text) n += c == '\n';
  return n;
}

std::string node_file(const std::vector<madd::Point>& points) {
  std::ostringstream s;
  s.precision(17);
  s << points.size() << " 2 0 0\n";
  for (std::size_t i = 0; i < points.size(); ++i) s << i + 1 << ' ' << points[i].x << ' ' << points[i].y << '\n';
  return s.str();
}

// The unit square's corners, edge midpoints and a few inner points.
std::vector<madd::Point> square_points() {
  return {{0, 0},   {1, 0},     {1, 1},     {0, 1},     {0.5, 0},     {1, 0.5},  {0.5, 1},
          {0, 0.5}, {0.3, 0.4}, {0.7, 0.2}, {0.6, 0.8}, {0.25, 0.75}, {0.5, 0.5}};
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("cli") {

TEST_CASE("madd help and madd help COMMAND print help, like --help") {
  const Scratch dir("help");
  const Result top = run_madd(dir, "help");
  CHECK(top.code == 0);
  CHECK(top.err.empty());
  CHECK(top.out == run_madd(dir, "--help").out);
  CHECK(has(top.out, "commands:"));
  for (const char* command : {"check", "decompose", "partition", "script", "triangulate"}) {
    CAPTURE(command);
    const Result help = run_madd(dir, std::string("help ") + command);
    CHECK(help.code == 0);
    CHECK(!help.out.empty());
    CHECK(help.out == run_madd(dir, std::string(command) + " --help").out);
  }
  const Result unknown = run_madd(dir, "help nosuch");
  CHECK(unknown.code == 2);
  CHECK(has(unknown.err, "unknown command 'nosuch'"));
  CHECK(run_madd(dir, "help check extra").code == 2);
}

TEST_CASE("a mistyped command is named, with the command it resembles") {
  const Scratch dir("typo");
  const Result r = run_madd(dir, "triangulat '" + data_dir + "/key.poly'");
  CHECK(r.code == 2);
  CHECK(r.err == "madd: unknown command 'triangulat'; did you mean 'triangulate'?\n");
  CHECK(fs::is_empty(dir.path));
  CHECK(has(run_madd(dir, "partiton g 2").err, "did you mean 'partition'?"));
  CHECK(has(run_madd(dir, "chek x.poly").err, "did you mean 'check'?"));
  CHECK(has(run_madd(dir, "decompse x.poly").err, "did you mean 'decompose'?"));
  // A file of that name is an input, and so is anything ending in .poly/.node.
  fs::copy_file(data_dir + "/key.poly", dir / "chek");
  CHECK(run_madd(dir, "chek -q").code == 0);
  const Result poly = run_madd(dir, "check.poly");
  CHECK(poly.code == 3);
  CHECK(!has(poly.err, "did you mean"));
  // Far from every command: still the default mode (decompose), which reports the missing file.
  const Result far = run_madd(dir, "zzzzzz");
  CHECK(far.code == 3);
  CHECK(!has(far.err, "did you mean"));
}

TEST_CASE("partition: -q, and gpmetis's -name=value options") {
  const Scratch dir("partition");
  put(dir / "g.metis", grid_graph(12, 10));
  const Result quiet = run_madd(dir, "partition g.metis 4 -q");
  CHECK(quiet.code == 0);
  CHECK(quiet.out.empty());
  CHECK(quiet.err.empty());
  CHECK(line_count(slurp(dir / "g.metis.part.4")) == 120);
  CHECK(run_madd(dir, "partition --quiet g.metis 4").out.empty());

  // gpmetis spellings give exactly the result of the equivalent long options.
  REQUIRE(run_madd(dir, "partition g.metis 4 -q --ufactor 30 --seed 7 --contig --niter 3").code == 0);
  const std::string expected = slurp(dir / "g.metis.part.4");
  fs::remove(dir / "g.metis.part.4");
  const Result gp = run_madd(dir, "partition -ptype=rb -ufactor=30 -seed=7 -contig -niter=3 -objtype=cut "
                                  "-ctype=shem -iptype=grow -no2hop g.metis 4 -q");
  CHECK_MESSAGE(gp.code == 0, gp.err);
  CHECK(slurp(dir / "g.metis.part.4") == expected);
  fs::remove(dir / "g.metis.part.4");
  CHECK(run_madd(dir, "partition g.metis 4 -q -ufactor 30 -seed 7 -contig -niter 3").code ==
        0);  // gpmetis accepts a space too
  CHECK(slurp(dir / "g.metis.part.4") == expected);
  fs::remove(dir / "g.metis.part.4");
  // A different seed or ufactor changes the input to the bisector (not necessarily the result),
  // so check only that the values were taken: a bad value is a usage error.
  CHECK(run_madd(dir, "partition g.metis 4 -ufactor=abc").code == 2);
  CHECK(run_madd(dir, "partition g.metis 4 -niter=-1").code == 2);

  // -nooutput: partition, print, write nothing.
  const Result none = run_madd(dir, "partition g.metis 4 -nooutput");
  CHECK(none.code == 0);
  CHECK(has(none.out, "cut:"));
  CHECK(!fs::exists(dir / "g.metis.part.4"));
  CHECK(run_madd(dir, "partition -help").out == run_madd(dir, "partition --help").out);

  // gpmetis options madd cannot honour are refused by name, with nothing written.
  for (const char* refused : {"-ptype=kway", "-objtype=vol", "-ctype=rm", "-iptype=random", "-minconn", "-tpwgts=t.txt",
                              "-ubvec=1.05", "-ncuts=4", "-dbglvl=1"}) {
    CAPTURE(refused);
    const Result r = run_madd(dir, std::string("partition g.metis 4 ") + refused);
    CHECK(r.code == 2);
    CHECK(has(r.err, std::string(refused).substr(0, std::string(refused).find('='))));
    CHECK(line_count(r.err) <= 2);
    CHECK(!fs::exists(dir / "g.metis.part.4"));
  }
  const Result kway = run_madd(dir, "partition g.metis 4 --ptype=kway");
  CHECK(kway.code == 2);
  CHECK(has(kway.err, "-ptype=kway is not supported"));
  CHECK(run_madd(dir, "partition g.metis 4 -ptype kway").code == 2);
  CHECK(!fs::exists(dir / "g.metis.part.4"));
  const Result bogus = run_madd(dir, "partition g.metis 4 -bogus=1");
  CHECK(bogus.code == 2);
  CHECK(has(bogus.err, "'-bogus=1'"));
}

TEST_CASE("script takes its options after the file too") {
  const Scratch dir("script");
  put(dir / "run.madd", "read " + data_dir + "/key.poly\ndec 3\nwriteSubdomains out.txt\n");
  const Result after = run_madd(dir, "script run.madd -q");
  CHECK_MESSAGE(after.code == 0, after.err);
  CHECK(after.out.empty());
  CHECK(fs::exists(dir / "out.txt"));
  const Result before = run_madd(dir, "script -q run.madd");
  CHECK(before.code == 0);
  CHECK(before.out.empty());
  CHECK(!run_madd(dir, "script run.madd").out.empty());
  CHECK(run_madd(dir, "script run.madd -x").code == 2);
  // A script whose name starts with '-' follows '--'.
  fs::copy_file(dir / "run.madd", dir / "-odd.madd");
  CHECK(run_madd(dir, "script -q -- -odd.madd").code == 0);
}

TEST_CASE("triangulate: a .poly without segments is a point set, as a .node is") {
  const Scratch dir("points");
  const std::vector<madd::Point> pts = square_points();
  put(dir / "p.node", node_file(pts));
  put(dir / "q.poly", node_file(pts) + "0 0\n0\n");
  const Result node = run_madd(dir, "triangulate p.node");
  REQUIRE_MESSAGE(node.code == 0, node.err);
  const Result poly = run_madd(dir, "triangulate q.poly");
  REQUIRE_MESSAGE(poly.code == 0, poly.err);
  CHECK(has(poly.out, "13 vertices"));
  for (const char* ext : {".node", ".ele", ".neigh", ".edge"}) {
    CAPTURE(ext);
    CHECK(!slurp(dir / (std::string("q.1") + ext)).empty());
    CHECK(slurp(dir / (std::string("q.1") + ext)) == slurp(dir / (std::string("p.1") + ext)));
  }
  // Holes need a boundary to stop at: still refused, in one line.
  put(dir / "h.poly", node_file(pts) + "0 0\n1\n1 0.5 0.5\n");
  const Result holes = run_madd(dir, "triangulate h.poly");
  CHECK(holes.code == 3);
  CHECK(line_count(holes.err) == 1);
  CHECK(!fs::exists(dir / "h.1.ele"));
}

TEST_CASE(
    "mesh: writes every format asked for, the same for -j 1 and -j 2, and refuses bad options with nothing written") {
  const Scratch dir("mesh");
  const std::string pipe = "'" MADD_DATA_DIR "/pipe.poly'";
  const Result one = run_madd(
      dir,
      "mesh " + pipe + " -n 4 -q 30 -a 0.02 -j 1 -o one --msh --vtu --neigh --edge --split-mesh parts --report=r.json");
  REQUIRE_MESSAGE(one.code == 0, one.err);
  CHECK(has(one.out, "4 subdomains"));
  for (const char* ext : {".node", ".ele", ".neigh", ".edge", ".msh", ".vtu"}) {
    CAPTURE(ext);
    CHECK(!slurp(dir / (std::string("one") + ext)).empty());
  }
  CHECK(fs::exists(dir / "parts" / "one-0.ele"));
  CHECK(fs::exists(dir / "parts" / "one-3.node"));
  CHECK(has(slurp(dir / "r.json"), "\"share_below_bound\": 0,"));
  const Result two = run_madd(dir, "mesh " + pipe + " -n 4 -q 30 -a 0.02 -j 2 -o two --quiet --no-verify");
  REQUIRE_MESSAGE(two.code == 0, two.err);
  CHECK(two.out.empty());
  CHECK(slurp(dir / "two.ele") == slurp(dir / "one.ele"));
  CHECK(slurp(dir / "two.node") == slurp(dir / "one.node"));
  for (const char* bad : {"-q 60", "-a -1", "-a x", "--balance speed", "-n 0"}) {
    CAPTURE(bad);
    const Result r = run_madd(dir, "mesh " + pipe + " " + bad + " -o bad");
    CHECK(r.code == 2);
    CHECK(has(r.err, "madd mesh: "));
    CHECK(line_count(r.err) == 2);  // the problem, then where help is
    CHECK(!fs::exists(dir / "bad.ele"));
  }
}

TEST_CASE("check FILE.node validates and summarises a point set") {
  const Scratch dir("check-node");
  const std::vector<madd::Point> pts = square_points();
  put(dir / "p.node", node_file(pts));
  const Result r = run_madd(dir, "check p.node");
  REQUIRE_MESSAGE(r.code == 0, r.err);
  CHECK(has(r.out, "p.node: valid point set"));
  const std::regex points_line(R"(\n  points +13\n)");
  CHECK(std::regex_search(r.out, points_line));
  const std::regex hull(R"(\n  hull +8 vertices, area ([0-9.e+-]+)\n)");
  std::smatch m;
  REQUIRE_MESSAGE(std::regex_search(r.out, m, hull), r.out);
  CHECK(std::stod(m[1]) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(has(r.out, "bounding box      [0, 1] x [0, 1]"));
  const std::regex closest(R"(\n  closest pair +([0-9.e+-]+) \(vertices (\d+) and (\d+)\)\n)");
  REQUIRE_MESSAGE(std::regex_search(r.out, m, closest), r.out);
  double brute = INFINITY;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) brute = std::min(brute, madd::distance(pts[i], pts[j]));
  CHECK(std::stod(m[1]) == doctest::Approx(brute).epsilon(1e-15));
  const int a = std::stoi(m[2]) - 1, b = std::stoi(m[3]) - 1;  // 1-based ids
  CHECK(madd::distance(pts[static_cast<std::size_t>(a)], pts[static_cast<std::size_t>(b)]) == std::stod(m[1]));
  CHECK(run_madd(dir, "check -q p.node").out.empty());
  CHECK(run_madd(dir, "check p.node -q").code == 0);

  // Bad point sets: one line, exit 3.
  std::vector<madd::Point> dup = pts;
  dup.push_back(pts[4]);
  put(dir / "dup.node", node_file(dup));
  const Result d = run_madd(dir, "check dup.node");
  CHECK(d.code == 3);
  CHECK(line_count(d.err) == 1);
  CHECK(has(d.err, "vertex 5"));
  CHECK(has(d.err, "vertex 14"));
  put(dir / "line.node", node_file({{0, 0}, {1, 1}, {2, 2}, {3, 3}}));
  const Result line = run_madd(dir, "check line.node");
  CHECK(line.code == 3);
  CHECK(has(line.err, "one line"));
  // The bundled domain's .node (its vertices) is a point set too.
  CHECK(run_madd(dir, "check '" + data_dir + "/l_shape.node'").code == 0);
  // A .poly still needs to be a domain for decompose, and says what it is for check.
  put(dir / "q.poly", node_file(pts) + "0 0\n0\n");
  const Result q = run_madd(dir, "check q.poly");
  CHECK(q.code == 0);
  CHECK(has(q.out, "q.poly: valid point set"));
  CHECK(run_madd(dir, "q.poly -n 2 -q").code == 3);
}

// data/pslg/: estuary (every kind of interior constraint), crossing_lanes
// (crossings and overlaps), survey (no enclosing boundary); their counts
// follow from data/generate.py (see tests/triangulate_pslg_test.cpp).
TEST_CASE("triangulate takes any PSLG: -c keeps the hull, -r resolves crossings, nothing is written for bad input") {
  const Scratch dir("pslg");
  const std::string pslg_dir = data_dir + "/pslg/";
  const Result estuary = run_madd(dir, "triangulate -o e '" + pslg_dir + "estuary.poly'");
  REQUIRE_MESSAGE(estuary.code == 0, estuary.err);
  CHECK(has(estuary.out, "26 vertices, 40 triangles"));
  CHECK(slurp(dir / "e.ele").rfind("40 ", 0) == 0);
  const Result survey = run_madd(dir, "triangulate -o s '" + pslg_dir + "survey.poly'");
  CHECK(has(survey.out, "13 vertices, 3 triangles"));  // the closed triangle with its inner point
  const Result hull = run_madd(dir, "triangulate --convex-hull -o h '" + pslg_dir + "survey.poly'");
  REQUIRE_MESSAGE(hull.code == 0, hull.err);
  CHECK(!has(hull.out, " 3 triangles"));
  const Result crossing = run_madd(dir, "triangulate -o x '" + pslg_dir + "crossing_lanes.poly'");
  CHECK(crossing.code == 3);
  CHECK(line_count(crossing.err) == 1);
  CHECK(has(crossing.err, "crossing_lanes.poly:26:1: segment 6 (vertices 7-8) crosses segment 5"));
  CHECK(has(crossing.err, "--resolve-crossings"));
  CHECK(!fs::exists(dir / "x.ele"));
  const Result resolved = run_madd(dir, "triangulate -r -o x '" + pslg_dir + "crossing_lanes.poly'");
  REQUIRE_MESSAGE(resolved.code == 0, resolved.err);
  CHECK(has(resolved.out, "20 vertices, 34 triangles (resolved 6 crossing(s), 1 overlap(s): 4 new vertices)"));
  CHECK(slurp(dir / "x.node").rfind("20 2 0 1\n", 0) == 0);
  // -A: the region's attribute as a column of the .ele (one triangle in the estuary's loop).
  const Result regions = run_madd(dir, "triangulate -A -o a '" + pslg_dir + "estuary.poly'");
  REQUIRE_MESSAGE(regions.code == 0, regions.err);
  const std::string ele = slurp(dir / "a.ele");
  CHECK(ele.rfind("40 3 1\n", 0) == 0);
  std::size_t twos = 0;
  for (std::size_t at = ele.find(" 2\n"); at != std::string::npos; at = ele.find(" 2\n", at + 1)) ++twos;
  CHECK(twos == 1);
}

TEST_CASE("check describes a PSLG; decompose and mesh refuse it with a located error and write nothing") {
  const Scratch dir("pslg-check");
  const std::string estuary = "'" + data_dir + "/pslg/estuary.poly'";
  const Result check = run_madd(dir, "check " + estuary);
  REQUIRE_MESSAGE(check.code == 0, check.err);
  CHECK(has(check.out, "estuary.poly: valid PSLG, not a domain"));
  CHECK(has(check.out, "segments          19 (10 boundary, 9 interior, 0 outside)"));
  CHECK(has(check.out, "isolated vertices 4 (3 inside)"));
  CHECK(has(check.out, "regions           1"));
  CHECK(has(check.out, "madd decompose and madd mesh refuse it"));
  for (const char* command : {"decompose", "mesh"}) {
    CAPTURE(command);
    const Result r = run_madd(dir, std::string(command) + " " + estuary + " -n 2 -o out");
    CHECK(r.code == 3);
    CHECK(line_count(r.err) == 1);
    // The survey point in the hole, 25 (1.25, 1.75), on line 30 of the file.
    CHECK(has(r.err, "estuary.poly:30:1: vertex 25 (1.25, 1.75) is on no segment and lies outside the domain"));
    CHECK(fs::is_empty(dir.path));
  }
  // A crossing is bad input for check as well.
  const Result crossing = run_madd(dir, "check '" + data_dir + "/pslg/crossing_lanes.poly'");
  CHECK(crossing.code == 3);
  CHECK(has(crossing.err, "crosses"));
}

// Issue 26's fuzz finding: vertex 5 lies inside boundary segment 1 and ends
// no segment. `check` called it a valid domain while decompose and mesh
// failed their self-checks (exit 70); every command now takes it, and every
// piece of --split is a valid domain of its own.
TEST_CASE("check, decompose, mesh and --split take a domain with a vertex on no segment inside a boundary segment") {
  const Scratch dir("vertex-on-segment");
  const std::string file = "'" MADD_SOURCE_DIR "/fuzz/corpus/fuzz_mesh/vertex_on_boundary_segment'";
  const Result check = run_madd(dir, "check " + file);
  REQUIRE_MESSAGE(check.code == 0, check.err);
  CHECK(has(check.out, "valid domain"));
  CHECK(has(check.out, "1 vertices on segments"));
  CHECK(has(check.out, "isolated vertices 0"));
  const Result decompose = run_madd(dir, file + " -n 5 --min-angle 45 -o d.poly");
  CHECK_MESSAGE(decompose.code == 0, decompose.err);
  const Result mesh = run_madd(dir, "mesh " + file + " -n 2 -o m");
  CHECK_MESSAGE(mesh.code == 0, mesh.err);
  const Result split = run_madd(dir, file + " -n 3 --split parts");
  REQUIRE_MESSAGE(split.code == 0, split.err);
  std::size_t pieces = 0;
  for (const auto& entry : fs::directory_iterator(dir / "parts")) {
    CAPTURE(entry.path().string());
    const Result piece = run_madd(dir, "check '" + entry.path().string() + "'");
    CHECK_MESSAGE(piece.code == 0, piece.err);
    CHECK(has(piece.out, "valid domain"));
    ++pieces;
  }
  CHECK(pieces == 3);
}

// --max-area far below the segments' lengths asks the decoupling for millions
// of points a segment: the time and memory limits stop it (it ran until
// killed before), exit 6, nothing written.
TEST_CASE("decompose's pre-discretised outputs keep to the time and memory limits") {
  const Scratch dir("discretise-limits");
  const std::string file = "'" + data_dir + "/key.poly'";
  const Result timed = run_madd(dir, file + " -n 4 --max-area 1e-14 --time-limit 1 -o out.poly");
  CHECK(timed.code == 6);
  CHECK(has(timed.err, "time limit"));
  const Result memory = run_madd(dir, file + " -n 4 --max-area 1e-14 --max-memory 300 -o out.poly --split parts");
  CHECK(memory.code == 6);
  CHECK_FALSE(fs::exists(dir / "out.poly"));
  CHECK_FALSE(fs::exists(dir / "parts"));
}

TEST_CASE("the progress line counts subdomains and time on a terminal, and is cleared") {
  const Scratch dir("progress");
  if (exit_status(std::system("script -qec true /dev/null > /dev/null 2>&1")) != 0) {
    MESSAGE("skipped: no script(1) to give madd a terminal");
    return;
  }
  // script(1) runs madd on a pseudo-terminal (stdout and stderr both) and copies it to typescript.txt.
  const auto on_terminal = [&](const std::string& args) {
    const std::string command = "cd '" + dir.path.string() + "' && script -qec \"'" MADD_CLI_PATH "' " + args +
                                "\" /dev/null > typescript.txt 2>&1";
    const int code = exit_status(std::system(command.c_str()));
    return std::make_pair(code, slurp(dir / "typescript.txt"));
  };
  // Named members, not a structured binding: clang 14 cannot capture one in
  // the lambdas the _MESSAGE checks expand to.
  const auto run = on_terminal("'" + data_dir + "/pipe.poly' -n 300 -j 1 -o out.poly");
  const int code = run.first;
  const std::string& text = run.second;
  REQUIRE_MESSAGE(code == 0, text);
  const std::regex counted(R"(decomposing: (\d+)/300 subdomains, (\d+\.\d) s)");
  long last_done = 0;
  double last_time = 0.0;
  std::size_t updates = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), counted); it != std::sregex_iterator(); ++it) {
    const long done = std::stol((*it)[1]);
    const double seconds = std::stod((*it)[2]);
    CHECK(done >= last_done);
    CHECK(done <= 300);
    CHECK(seconds >= last_time);
    last_done = done;
    last_time = seconds;
    ++updates;
  }
  CHECK_MESSAGE(updates >= 1, text);
  // Cleared before the summary: the summary starts a fresh line.
  const std::size_t summary = text.find(data_dir + "/pipe.poly: 300 subdomains");
  REQUIRE_MESSAGE(summary != std::string::npos, text);
  const std::size_t cleared = text.rfind("\r\033[K", summary);
  REQUIRE(cleared != std::string::npos);
  CHECK(text.substr(cleared + 4, summary - cleared - 4).find_first_not_of("\r\n") == std::string::npos);
  // The same run off a terminal writes no progress, and the same file.
  const std::string with_progress = slurp(dir / "out.poly");
  const Result plain = run_madd(dir, "'" + data_dir + "/pipe.poly' -n 300 -j 2 -o out.poly");
  CHECK(plain.code == 0);
  CHECK(plain.err.empty());
  CHECK(slurp(dir / "out.poly") == with_progress);
  // -q: nothing at all, even on a terminal.
  const auto [quiet_code, quiet_text] = on_terminal("'" + data_dir + "/pipe.poly' -n 50 -q");
  CHECK(quiet_code == 0);
  CHECK(quiet_text.empty());
  // An error after progress was shown starts its own line.
  const auto bad = on_terminal("'" + data_dir + "/pipe.poly' -n 50 --time-limit 0.000001");
  const int bad_code = bad.first;
  const std::string& bad_text = bad.second;
  CHECK(bad_code == 6);
  const std::size_t error = bad_text.find("madd decompose: error");
  REQUIRE_MESSAGE(error != std::string::npos, bad_text);
  CHECK((error == 0 || bad_text.compare(error - 4, 4, "\r\033[K") == 0 || bad_text[error - 1] == '\n'));
}

}  // TEST_SUITE("cli")

#endif
