// The file and decomposition commands of the script language (paper Sec. 6,
// Table II): read, read_weights, read_areas, dec, write, writeSubdomains.
#include <filesystem>
#include <string>
#include <vector>

#include "madd/atomic_write.hpp"
#include "madd/decomposition.hpp"
#include "madd/output.hpp"
#include "madd/poly_io.hpp"
#include "script/script_detail.hpp"

namespace madd::detail {
namespace {

void say(const ScriptContext& context, const std::string& text) {
  if (context.log) context.log(text);
}

void require_files(const ScriptCommand& c, const ScriptContext& context) {
  if (!context.allow_files)
    c.fail(c.words[0].column, "'" + c.words[0].text + "' needs the file system, which is disabled here");
}

// An unreadable input file is bad input (a ParseError at the file name, CLI
// exit 3), like a malformed one; the typed errors of the reader keep their type.
template <class F>
auto read_input(const ScriptCommand& c, std::size_t column, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const ParseError& e) {
    rethrow_located(c, column, e);
  } catch (const InvalidInputError& e) {
    rethrow_located(c, column, e);
  } catch (const Error& e) {
    c.fail(column, e.what());
  }
}

// The decomposition every write command needs, checked once by the
// library's own verifier: a wrong file is never written (docs/design.md, "Verifiers at every stage").
const Decomposition& verified_decomposition(const ScriptCommand& c, ScriptContext& context) {
  if (!context.decomposition || !context.domain) c.fail(c.words[0].column, "nothing to write yet: run 'dec' first");
  const Decomposition& d = *context.decomposition;
  if (context.verified) return d;
  const auto actual = static_cast<std::uint32_t>(d.subdomains.size());
  const std::uint32_t requested = context.requested_subdomains == 0 ? actual : context.requested_subdomains;
  const Verification check = verify_decomposition(d, *context.domain, expected_subdomain_count(d, requested));
  if (!check.ok()) {
    std::string problems;
    for (const std::string& p : check.problems) problems += "\n  " + p;
    throw InternalError(c.prefix() + "the decomposition failed its self-check, nothing written:" + problems);
  }
  context.verified = true;
  return d;
}

// decompose(), its errors located at the script line; a bad option is said
// with the script's names (a, p, setAreaFunction...).
Decomposition decompose_located(const ScriptCommand& c, std::size_t column, const ScriptContext& context) {
  try {
    return decompose(*context.domain, context.options);
  } catch (const OptionError& e) {
    c.fail_option(column, e.option(), script_name_of(e.option()) + " " + e.requirement());
  } catch (const Error& e) {
    rethrow_located(c, column, e);
  }
}

std::string count_text(std::size_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

}  // namespace

void script_read(const ScriptCommand& c, ScriptContext& context) {
  c.expect_arguments(1, 1, "read FILE");
  require_files(c, context);
  const ScriptWord& file = c.words[1];
  ValidateOptions validate_options;
  validate_options.check_weights = context.options.gradation > 0;  // boundary weights grade (Sec. 5.2, case 1)
  Pslg domain = read_input(c, file.column, [&] { return read_domain(file.text, validate_options); });
  context.decomposition.reset();
  context.verified = false;
  context.requested_subdomains = 0;
  // Background weights and areas are points of the previous domain's
  // background mesh (Sec. 5.2 case 2): a new domain starts without them.
  const bool dropped = !context.options.weight_samples.empty() || !context.options.subdomain_area_samples.empty();
  context.options.weight_samples.clear();
  context.options.subdomain_area_samples.clear();
  if (dropped) say(context, "read " + file.text + ": background weights and areas of the previous domain cleared");
  say(context, "read " + file.text + ": " + count_text(domain.points.size(), "point") + ", " +
                   count_text(domain.segments.size(), "segment") + ", " + count_text(domain.holes.size(), "hole"));
  context.domain = std::move(domain);
  context.domain_name = file.text;
}

// A background mesh (Sec. 5.2, case 2) as a .node file: the first attribute
// of each node is its density weight or its required area.
void script_read_values(const ScriptCommand& c, ScriptContext& context, bool areas) {
  const char* usage = areas ? "read_areas FILE|none" : "read_weights FILE|none";
  c.expect_arguments(1, 1, usage);
  const ScriptWord& file = c.words[1];
  auto& target = areas ? context.options.subdomain_area_samples : context.options.weight_samples;
  if (file.text == "none") {  // clears the source, as setWeightFunction none does
    target.clear();
    say(context, std::string(areas ? "read_areas" : "read_weights") + " none");
    return;
  }
  require_files(c, context);
  std::vector<ValuedPoint> values = read_input(c, file.column, [&] {
    return read_background_samples(file.text, areas ? SampleValue::area : SampleValue::weight);
  });
  say(context, std::string(areas ? "read_areas " : "read_weights ") + file.text + ": " +
                   count_text(values.size(), areas ? "required area" : "weight"));
  target = std::move(values);
}

void script_dec(const ScriptCommand& c, ScriptContext& context) {
  c.expect_arguments(0, 1, "dec [N]");
  if (!context.domain) c.fail(c.words[0].column, "no domain to decompose: 'read FILE' first");
  std::uint32_t n = context.options.subdomains;
  std::size_t column = c.words[0].column;
  if (c.words.size() == 2) {
    const std::string& t = c.words[1].text;
    column = c.words[1].column;
    unsigned long long k = 0;
    const bool digits = !t.empty() && t.size() <= 10 && t.find_first_not_of("0123456789") == std::string::npos;
    if (digits) k = std::stoull(t);
    if (!digits || k == 0 || k > 0xFFFFFFFFull)
      c.fail_option(column, "subdomains",
                    "the number of subdomains must be a whole number >= 1, got '" + printable(t) + "'");
    n = static_cast<std::uint32_t>(k);
  }
  if (context.max_subdomains != 0 && n > context.max_subdomains)
    c.fail(column, "dec " + std::to_string(n) + " is above the limit of " + std::to_string(context.max_subdomains) +
                       " subdomains here");
  context.options.subdomains = n;
  if (context.check_options) located_call(c, column, [&] { context.check_options(context.options); });
  context.decomposition.reset();
  context.verified = false;
  Decomposition d = decompose_located(c, column, context);
  say(context, "dec " + std::to_string(n) + ": " + count_text(d.subdomains.size(), "subdomain") + ", " +
                   count_text(d.points.size(), "point") + ", " + count_text(d.segments.size(), "segment"));
  context.decomposition = std::move(d);
  context.requested_subdomains = n;
}

// `write FILE` is output 1; `write FILE all` writes one .poly per subdomain
// (output 2) into FILE's directory, named after FILE's stem.
void script_write(const ScriptCommand& c, ScriptContext& context) {
  c.expect_arguments(1, 2, "write FILE [all]");
  const bool all = c.words.size() == 3;
  if (all && c.words[2].text != "all")
    c.fail(c.words[2].column,
           "expected 'all' or nothing after the file name, found '" + printable(c.words[2].text) + "'");
  const ScriptWord& file = c.words[1];
  const Decomposition& d = verified_decomposition(c, context);
  if (!all) {
    const std::string text =
        format_decomposition_poly(d, "made by madd script " + c.script + " from " + context.domain_name);
    require_files(c, context);
    located_call(c, file.column, [&] { write_file_atomically(file.text, text); });
    say(context, "write " + file.text + ": " + count_text(d.subdomains.size(), "subdomain"));
    return;
  }
  require_files(c, context);
  const std::filesystem::path path(file.text);
  const std::string stem = path.stem().string();
  if (stem.empty() || stem == "." || stem == "..")
    c.fail(file.column, "'write FILE all' needs a file name to take the stem from");
  const std::string dir = path.parent_path().empty() ? std::string(".") : path.parent_path().string();
  located_call(c, file.column, [&] { write_split(d, dir, stem); });
  const auto n = static_cast<std::uint32_t>(d.subdomains.size());
  say(context, "write " + file.text + " all: " + count_text(n, "file") + " " +
                   (std::filesystem::path(dir) / split_file_name(stem, 0, n)).string() + " ...");
}

void script_write_subdomains(const ScriptCommand& c, ScriptContext& context) {
  c.expect_arguments(1, 1, "writeSubdomains FILE");
  const ScriptWord& file = c.words[1];
  const Decomposition& d = verified_decomposition(c, context);
  const std::string text = format_subdomain_file(d);
  require_files(c, context);
  located_call(c, file.column, [&] { write_file_atomically(file.text, text); });
  say(context, "writeSubdomains " + file.text + ": " + count_text(d.subdomains.size(), "subdomain"));
}

}  // namespace madd::detail
