// The documentation against the tree and against the code.
//
// 1. References to files. Every file a user's clone holds that talks about
//    other files (README.md, CMakeLists.txt, docs/*.md, docs/madd.1, and every
//    .cpp/.hpp/.h/.sh/CMakeLists.txt under src/ include/ cli/ tests/ fuzz/,
//    fuzz/corpus excepted) is scanned for references, and each must name a
//    file or folder that exists. The rule:
//    - In a .md file, the target of a link or image, `[text](target)` or
//      `![alt](target)`, without its `#fragment`, must exist relative to that
//      .md file's folder (where a Markdown viewer looks). URLs (`scheme:...`)
//      and pure fragments are not checked.
//    - Anywhere, a path-like word (a run of letters, digits, `_ . / -` and the
//      placeholder characters below; trailing dots dropped) is a reference
//      when it
//        a. starts with one of the repository's own top-level folders
//           (src/ include/ cli/ tests/ fuzz/ data/ docs/), or
//        b. ends in `.md`, or
//        c. ends in `.cpp`, `.hpp` or `.h` and is a bare file name or starts
//           with `madd/` or a stage folder (`split/chord.hpp`), as includes
//           name them;
//      and it must exist relative to the referencing file's folder or to the
//      repository root (c. also relative to include/, include/madd/ and src/).
//    - Not references: words that start with `/` (absolute paths, other
//      machines); words containing `< > * $ { } \` (templates such as
//      `tests/<concept>_test.cpp`, shell variables, escaped regexes); words
//      with a one-capital-letter placeholder part (`docs/img/pipe-N.svg`);
//      paths under any other folder (`build/pipe.svg`, `parts/pipe-0.poly`,
//      `shared/...`), which are outputs of examples or not part of the clone.
//    - A .md reference followed by a quoted section name (`docs/formats.md,
//      "Bad input"`) must also find a heading in that file that starts with
//      the name.
//    A failure names file:line and the missing target. This file is not
//    scanned: its own checks name missing files on purpose.
// 2. Examples. Each figure a doc quotes from a command (subdomain counts,
//    angles, max/mean ratios, a script's output) is recomputed by running that
//    command with the CLI built from this tree (skipped when the CLI is not
//    built), and the doc must still quote the command and the figure as
//    printed; so is README's claim that every bundled domain decomposes at
//    Phi0 = 89 degrees. Change the code and the doc together.
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "scratch_files.hpp"

namespace {

namespace fs = std::filesystem;
using madd::test::TempDir;

const fs::path source_root = MADD_SOURCE_DIR;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool starts_with(const std::string& s, const std::string& head) { return s.rfind(head, 0) == 0; }

bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
         std::string_view("_./-<>*${}\\").find(c) != std::string_view::npos;
}

// A part of the word that is one capital letter alone (`pipe-N.svg`, `a/K/b`).
bool has_placeholder_letter(const std::string& w) {
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (std::isupper(static_cast<unsigned char>(w[i])) == 0) continue;
    const bool alone_before = i == 0 || std::isalnum(static_cast<unsigned char>(w[i - 1])) == 0;
    const bool alone_after = i + 1 == w.size() || std::isalnum(static_cast<unsigned char>(w[i + 1])) == 0;
    if (alone_before && alone_after) return true;
  }
  return false;
}

const std::vector<std::string> top_level_folders = {"src/", "include/", "cli/", "tests/", "fuzz/", "data/", "docs/"};
const std::vector<std::string> include_prefixes = {"madd/",      "kernel/",  "pslg/",        "triangulation/",
                                                   "graph/",     "medial/",  "subdivision/", "split/",
                                                   "decompose/", "quality/", "output/",      "script/"};

// True when `w` is a file name ending in `ext` (not the extension alone).
bool names_file_with(const std::string& w, const std::string& ext) {
  if (!ends_with(w, ext) || w.size() == ext.size()) return false;
  const char before = w[w.size() - ext.size() - 1];
  return before != '/' && before != '.';
}

// The folders (relative to the root) a word is resolved against, or none when
// the word is not a reference.
std::vector<fs::path> roots_for(const std::string& w, const fs::path& folder) {
  if (w.empty() || w[0] == '/' || w.find_first_of("<>*${}\\") != std::string::npos || has_placeholder_letter(w))
    return {};
  for (const std::string& top : top_level_folders)
    if (starts_with(w, top)) return {folder, "."};
  if (names_file_with(w, ".md")) return {folder, "."};
  if (names_file_with(w, ".cpp") || names_file_with(w, ".hpp") || names_file_with(w, ".h")) {
    const bool bare = w.find('/') == std::string::npos;
    const bool include_style = std::any_of(include_prefixes.begin(), include_prefixes.end(),
                                           [&](const std::string& p) { return starts_with(w, p); });
    if (bare || include_style) return {folder, ".", "include", "include/madd", "src"};
  }
  return {};
}

// The first of `folders` under which `target` exists, as a path, or empty.
fs::path resolve(const fs::path& root, const std::vector<fs::path>& folders, const std::string& target) {
  std::error_code ignored;
  for (const fs::path& f : folders)
    if (fs::exists(root / f / target, ignored)) return root / f / target;
  return {};
}

bool exists_under(const fs::path& root, const std::vector<fs::path>& folders, const std::string& target) {
  return !resolve(root, folders, target).empty();
}

// The section a reference names right after a .md file, as in
// `docs/formats.md, "Bad input"`: the quoted text, or empty.
std::string quoted_section_after(const std::string& line, std::size_t at) {
  while (at < line.size() && (line[at] == '`' || line[at] == ',' || line[at] == ' ')) ++at;
  if (at >= line.size() || line[at] != '"') return {};
  const std::size_t end = line.find('"', at + 1);
  return end == std::string::npos ? std::string() : line.substr(at + 1, end - at - 1);
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// True when the Markdown file has a heading that starts with `section`
// (case aside): `## Graphs (madd partition)` answers to "Graphs".
bool has_heading(const fs::path& md, const std::string& section) {
  std::ifstream in(md);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] != '#') continue;
    const std::size_t text = line.find_first_not_of("# ");
    if (text != std::string::npos && starts_with(lower(line.substr(text)), lower(section))) return true;
  }
  return false;
}

// "file:line: missing target" for every dangling reference in `text`, the
// contents of the file at `rel` (relative to `root`).
std::vector<std::string> dangling_references(const fs::path& root, const fs::path& rel, const std::string& text) {
  std::vector<std::string> found;
  const fs::path folder = rel.parent_path();
  const bool markdown = rel.extension() == ".md";
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::vector<std::string> missing;  // on this line, each target once
    const auto report = [&](const std::string& target) {
      if (std::find(missing.begin(), missing.end(), target) != missing.end()) return;
      missing.push_back(target);
      found.push_back(rel.generic_string() + ":" + std::to_string(number) + ": missing " + target);
    };
    if (markdown) {
      for (std::size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2)) {
        const std::size_t end = line.find_first_of(") \t", at + 2);
        if (end == std::string::npos) continue;
        std::string target = line.substr(at + 2, end - at - 2);
        target = target.substr(0, target.find('#'));
        const std::size_t colon = target.find(':');
        if (target.empty() || (colon != std::string::npos && target.find('/') > colon)) continue;  // URL
        if (!exists_under(root, {folder}, target)) report(target);
      }
    }
    for (std::size_t i = 0; i < line.size();) {
      if (!is_word_char(line[i])) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < line.size() && is_word_char(line[j])) ++j;
      std::string word = line.substr(i, j - i);
      i = j;
      while (!word.empty() && (word.back() == '.' || word.back() == '-')) word.pop_back();
      const std::vector<fs::path> roots = roots_for(word, folder);
      if (roots.empty()) continue;
      const fs::path target = resolve(root, roots, word);
      if (target.empty()) {
        report(word);
        continue;
      }
      const std::string section = names_file_with(word, ".md") ? quoted_section_after(line, j) : std::string();
      if (!section.empty() && !has_heading(target, section)) report(word + ", section \"" + section + "\"");
    }
  }
  return found;
}

std::vector<fs::path> scanned_files(const fs::path& root) {
  std::vector<fs::path> files = {"README.md", "CMakeLists.txt", "docs/madd.1"};
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") files.push_back(fs::relative(e.path(), root));
  for (const char* top : {"src", "include", "cli", "tests", "fuzz"}) {
    for (auto it = fs::recursive_directory_iterator(root / top); it != fs::recursive_directory_iterator(); ++it) {
      if (it->is_directory() && it->path().filename() == "corpus") {
        it.disable_recursion_pending();
        continue;
      }
      const fs::path& p = it->path();
      const std::string ext = p.extension().string();
      if (it->is_regular_file() &&
          (ext == ".cpp" || ext == ".hpp" || ext == ".h" || ext == ".sh" || p.filename() == "CMakeLists.txt"))
        files.push_back(fs::relative(p, root));
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

}  // namespace

TEST_SUITE("docs") {
TEST_CASE("the reference rule flags missing files and leaves example outputs alone") {
  const fs::path root = source_root;
  const auto count = [&](const char* rel, const char* text) { return dangling_references(root, rel, text).size(); };
  // Files a user's clone does not have, or that moved.
  CHECK(count("src/pslg/validate.cpp", "// the rules (FORMATS.md, \"Bad input\")") == 1);
  CHECK(count("include/madd/metrics.hpp", "// docs/QUALITY.md") == 1);
  CHECK(count("docs/algorithm.md", "see `src/split_round.cpp`.") == 1);
  CHECK(count("src/split/chord.cpp", "// the rule of split_chord.hpp") == 1);
  CHECK(count("docs/api.md", "[formats](FORMATS.md) ![](img/none.svg)") == 2);
  CHECK(count("src/split/split.cpp", "// see formats.md") == 1);  // from src/, it is docs/formats.md
  CHECK(count("src/pslg/validate.cpp", "// (docs/formats.md, \"No such section\")") == 1);
  CHECK(count("src/pslg/validate.cpp", "// (docs/formats.md, \"Bad input\"), `docs/quality.md` \"Phase times\"") == 0);
  // What exists, named as the file's folder, the root or the includes see it.
  CHECK(count("docs/api.md", "[formats.md](formats.md), `docs/formats.md`, ![](img/pipe-64.svg), [x](#anchor)") == 0);
  CHECK(count("src/split/split.cpp", "// chord.hpp, split/chord.hpp, madd/metrics.hpp, docs/algorithm.md.") == 0);
  CHECK(count("README.md", "`data/pipe.poly`, include/madd/, [`docs/cli.md`](docs/cli.md), https://x.org/y.md") == 0);
  // Outputs of examples, placeholders and other machines are not references.
  CHECK(count("README.md", "--svg build/pipe.svg --split parts/ parts/pipe-0.poly out.svg") == 0);
  CHECK(count("docs/algorithm.md", "--svg docs/img/pipe-N.svg, tests/<concept>_test.cpp, $dir/docs/x.md") == 0);
  CHECK(count("docs/performance.md", "shared/peers/cgal_cdt.cpp, /usr/include/doctest/doctest.h, <sys/wait.h>") == 0);
}

TEST_CASE("every file the docs and comments refer to exists") {
  const fs::path root = source_root;
  std::vector<std::string> dangling;
  const std::vector<fs::path> files = scanned_files(root);
  CHECK(files.size() > 100);
  for (const fs::path& rel : files) {
    if (rel == "tests/docs_test.cpp") continue;  // names missing files on purpose, as test data
    const std::vector<std::string> found = dangling_references(root, rel, slurp(root / rel));
    dangling.insert(dangling.end(), found.begin(), found.end());
  }
  CHECK_MESSAGE(dangling.empty(), dangling.size() << " dangling references:\n" << joined(dangling));
}
}  // TEST_SUITE("docs")

// ---------------------------------------------------------------------------
// 1b. docs/api.md lists the whole public API.

namespace {

// What a public header declares in namespace madd itself (not in
// madd::detail, not members): types, functions and constants. Declarations
// start at column 0 in these headers; continuation lines are indented.
std::vector<std::string> public_names(const std::string& text) {
  static const std::regex type_re(R"(^(?:struct|class|enum class|enum)\s+(\w+))");
  static const std::regex constant_re(R"(^inline constexpr [^=]*\s(\w+)\s*=)");
  static const std::regex function_re(R"((\w+)\()");
  std::vector<std::string> names;
  std::istringstream in(text);
  std::string line;
  int depth = 0;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find("//"));
    std::smatch m;
    const bool declaration = depth == 1 && !line.empty() && std::isalpha(static_cast<unsigned char>(line[0])) &&
                             line.rfind("namespace", 0) != 0 && line.rfind("friend", 0) != 0;
    if (declaration && (std::regex_search(line, m, type_re) || std::regex_search(line, m, constant_re) ||
                        (line.find("operator") == std::string::npos && std::regex_search(line, m, function_re))))
      names.push_back(m[1]);
    depth += static_cast<int>(std::count(line.begin(), line.end(), '{') - std::count(line.begin(), line.end(), '}'));
  }
  return names;
}

}  // namespace

TEST_SUITE("docs") {
TEST_CASE("docs/api.md names every public header and every type and function they declare") {
  const std::string api = slurp(source_root / "docs/api.md");
  const auto named = [&](const std::string& name) {
    for (std::size_t at = api.find('`' + name); at != std::string::npos; at = api.find('`' + name, at + 1)) {
      const std::size_t end = at + 1 + name.size();
      if (end < api.size() && !(std::isalnum(static_cast<unsigned char>(api[end])) || api[end] == '_')) return true;
    }
    return false;
  };
  std::vector<std::string> missing;
  std::size_t names = 0;
  for (const auto& e : fs::directory_iterator(source_root / "include/madd")) {
    const std::string header = "madd/" + e.path().filename().string();
    if (!named(header)) missing.push_back(header);
    for (const std::string& name : public_names(slurp(e.path()))) {
      ++names;
      if (!named(name)) missing.push_back(header + ": " + name);
    }
  }
  CHECK(names > 150);  // the reader found the declarations
  CHECK_MESSAGE(missing.empty(), "not in docs/api.md:\n" << joined(missing));
}
}  // TEST_SUITE("docs")

// ---------------------------------------------------------------------------
// 2. The figures the docs quote, recomputed with the CLI built from this tree.

namespace {

// Runs of blanks and line ends become one blank, so that a quote may wrap.
std::string squeezed(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool blank = c == ' ' || c == '\n' || c == '\t' || c == '\r';
    if (!blank) out += c;
    else if (!out.empty() && out.back() != ' ') out += ' ';
  }
  return out;
}

bool doc_quotes(const std::string& doc, const std::string& text) {
  return squeezed(slurp(source_root / doc)).find(squeezed(text)) != std::string::npos;
}

// The numbers of `text` in order, as written ("65.2", "1.07", "64").
std::vector<std::string> numbers_in(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < text.size();) {
    if (std::isdigit(static_cast<unsigned char>(text[i])) == 0) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) != 0) ++j;
    if (j + 1 < text.size() && text[j] == '.' && std::isdigit(static_cast<unsigned char>(text[j + 1])) != 0) {
      ++j;
      while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) != 0) ++j;
    }
    out.push_back(text.substr(i, j - i));
    i = j;
  }
  return out;
}

// `value` printed with as many decimals as `as_written` has.
std::string rounded_like(double value, const std::string& as_written) {
  const std::size_t dot = as_written.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(as_written.size() - dot - 1);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

// A number of the JSON report by key (NaN when missing or null).
double report_value(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return std::nan("");
  const char* start = json.c_str() + at + key.size() + 4;
  char* end = nullptr;
  const double v = std::strtod(start, &end);
  return end == start ? std::nan("") : v;
}

#ifdef MADD_CLI_PATH
// Runs the CLI with `arguments` (shell syntax) in `dir`; its standard output
// goes to `log`, its standard error to `log` + ".err".
int run_cli(const fs::path& dir, const std::string& arguments, const fs::path& log) {
  const std::string command = "cd '" + dir.string() + "' && '" + MADD_CLI_PATH + "' " + arguments + " > '" +
                              log.string() + "' 2> '" + log.string() + ".err'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A command quoted in a doc, minus its --svg output (nothing is written into
// the source tree), plus a report into `report`.
std::string arguments_of(const std::string& quoted, const fs::path& report) {
  std::istringstream words(quoted);
  std::string word, out;
  words >> word;  // "madd"
  while (words >> word) {
    if (word == "--svg") {
      words >> word;
      continue;
    }
    out += word + " ";
  }
  return out + "-q --report='" + report.string() + "'";
}
#endif

// A decomposition a doc shows: the command it quotes and the sentence with the
// figures; keys[k] is the report key of the k-th number of the sentence ("" =
// not a figure of the run).
struct QuotedRun {
  const char* doc;
  const char* command;
  const char* figures;
  std::vector<std::string> keys;
};

const std::vector<QuotedRun> quoted_runs = {
    {"README.md",
     "madd data/pipe.poly -n 64 --svg pipe.svg",
     "minimum new angle 65.2°, median 93.0°, largest area / mean 1.07",
     {"angle_min", "angle_median", "max_area_over_mean"}},
    {"docs/algorithm.md",
     "madd data/key.poly -n 200 --min-angle 70 --svg docs/img/key-200-phi70.svg",
     "minimum new angle 70.2°, median 94.3°, largest area / mean 1.16",
     {"angle_min", "angle_median", "max_area_over_mean"}},
    {"docs/grading.md",
     "madd docs/img/grading-key-weights.poly -n 64 --weight-gradation 3 -p 0.5 --svg docs/img/grading-boundary.svg",
     "— area max/mean 2.45, weight max/mean 1.84, min angle 63.3°",
     {"max_area_over_mean", "max_weight_over_mean", "angle_min"}},
    {"docs/grading.md",
     "madd data/pipe.poly -n 64 --weights docs/img/grading-pipe-weights.node --weight-gradation 20 --svg "
     "docs/img/grading-background-weights.svg",
     "— area max/mean 2.51, weight max/mean 1.09, min angle 61.2°",
     {"max_area_over_mean", "max_weight_over_mean", "angle_min"}},
    {"docs/grading.md",
     "madd data/pipe.poly -n 1000 --areas docs/img/grading-pipe-areas.node --svg docs/img/grading-background-areas.svg",
     "— stops at 64 subdomains (every ratio ≤ 1), min angle 61.0°",
     {"subdomains", "", "angle_min"}},
    {"docs/grading.md",
     "madd data/key.poly -n 100 --weight-fn x+2.5 --svg docs/img/grading-weight-fn.svg",
     "— area max/mean 2.04, weight max/mean 1.20, min angle 60.1°",
     {"max_area_over_mean", "max_weight_over_mean", "angle_min"}},
    {"docs/grading.md",
     "madd data/key.poly -n 1000 --area-fn \"0.01+0.01*(x+2)^2\" --svg docs/img/grading-area-fn.svg",
     "— stops at 532 subdomains (every ratio ≤ 1), min angle 60.1°",
     {"subdomains", "", "angle_min"}},
};

// A script a doc shows, verbatim, with what `madd script` prints for it.
struct QuotedScript {
  const char* doc;
  const char* script;
  const char* output;
  std::vector<std::string> inputs;  // bundled domains it reads, from data/
};

const std::vector<QuotedScript> quoted_scripts = {
    {"docs/script.md",
     "read pipe.poly\nset f=0.35\ndec 400\nwrite pipe400.poly\nwriteSubdomains pipe400.dat\nexit\n",
     "read pipe.poly: 576 points, 576 segments, 9 holes\nset f=0.35\n"
     "dec 400: 400 subdomains, 1223 points, 1631 segments\nwrite pipe400.poly: 400 subdomains\n"
     "writeSubdomains pipe400.dat: 400 subdomains\n",
     {"pipe.poly"}},
    {"docs/script.md",
     "read key.poly\n"
     "setWeightFunction x + 2.5           # Fig. 13, left: linear in x (x runs from -2 to 8 on the key)\n"
     "dec 1250\n",
     "read key.poly: 56 points, 56 segments, 1 hole\nsetWeightFunction x + 2.5\n"
     "dec 1250: 1250 subdomains, 2473 points, 3723 segments\n",
     {"key.poly"}},
    {"docs/script.md",
     "read pipe.poly\n"
     "setAreaFunction 1e-9*(1 + r^12)     # Fig. 13, right: grows as rho^12, rho the distance to the bore's centre\n"
     "dec 2000\n",
     "read pipe.poly: 576 points, 576 segments, 9 holes\nsetAreaFunction 1e-9*(1 + r^12)\n"
     "dec 2000: 1197 subdomains, 2697 points, 3902 segments\n",
     {"pipe.poly"}},
};

}  // namespace

TEST_SUITE("docs") {
TEST_CASE("the figures the docs quote are what the code gives") {
  for (const QuotedRun& q : quoted_runs) {
    const std::string doc = q.doc, command = q.command;
    CAPTURE(doc);
    CAPTURE(command);
    CHECK_MESSAGE(doc_quotes(q.doc, q.command), "the doc no longer quotes the command");
    CHECK_MESSAGE(doc_quotes(q.doc, q.figures), "the doc no longer quotes: " << std::string(q.figures));
    REQUIRE(numbers_in(q.figures).size() == q.keys.size());
  }
  for (const QuotedScript& q : quoted_scripts) {
    const std::string script = q.script;
    CAPTURE(script);
    CHECK_MESSAGE(slurp(source_root / q.doc).find(q.script) != std::string::npos, "the doc no longer shows the script");
    CHECK_MESSAGE(slurp(source_root / q.doc).find(q.output) != std::string::npos, "the doc no longer shows the output");
  }
#ifndef MADD_CLI_PATH
  MESSAGE("skipped running the examples: the madd CLI is not built");
#else
  const TempDir dir("figures");
  const fs::path report = dir.path / "report.json";
  const fs::path log = dir.path / "log";
  for (const QuotedRun& q : quoted_runs) {
    const std::string command = q.command;
    CAPTURE(command);
    fs::remove(report);
    REQUIRE_MESSAGE(run_cli(source_root, arguments_of(q.command, report), log) == 0, slurp(log.string() + ".err"));
    const std::string json = slurp(report);
    const std::vector<std::string> written = numbers_in(q.figures);
    for (std::size_t k = 0; k < q.keys.size(); ++k) {
      if (q.keys[k].empty()) continue;
      CAPTURE(q.keys[k]);
      CHECK(rounded_like(report_value(json, q.keys[k]), written[k]) == written[k]);
    }
  }
  for (const QuotedScript& q : quoted_scripts) {
    const std::string script = q.script;
    CAPTURE(script);
    for (const std::string& input : q.inputs)
      fs::copy_file(source_root / "data" / input, dir.path / input, fs::copy_options::overwrite_existing);
    std::ofstream(dir.path / "script.txt") << q.script;
    REQUIRE_MESSAGE(run_cli(dir.path, "script script.txt", log) == 0, slurp(log.string() + ".err"));
    CHECK(slurp(log) == q.output);
  }
#endif
}

TEST_CASE("README: every bundled domain decomposes at a minimum angle of 89 degrees") {
  CHECK(doc_quotes("README.md", "any Φ0 below 90° may be asked for, and every bundled domain decomposes even at 89°"));
#ifndef MADD_CLI_PATH
  MESSAGE("skipped: the madd CLI is not built");
#else
  const TempDir dir("phi89");
  const fs::path report = dir.path / "report.json";
  const fs::path log = dir.path / "log";
  std::vector<fs::path> domains;
  for (const auto& e : fs::directory_iterator(source_root / "data"))
    if (e.path().extension() == ".poly") domains.push_back(e.path());
  std::sort(domains.begin(), domains.end());
  CHECK(domains.size() >= 7);
  for (const fs::path& domain : domains) {
    for (const int n : {7, 256}) {
      CAPTURE(domain);
      CAPTURE(n);
      std::string arguments = "'";
      arguments += domain.string();
      arguments += "' -n " + std::to_string(n) + " --min-angle 89 --quiet --report='";
      arguments += report.string();
      arguments += "'";
      REQUIRE_MESSAGE(run_cli(dir.path, arguments, log) == 0, slurp(log.string() + ".err"));
      const std::string json = slurp(report);
      CHECK(report_value(json, "subdomains") == n);
      CHECK(report_value(json, "angle_min") >= 89.0);
    }
  }
#endif
}
}  // TEST_SUITE("docs")
