// The one check of the options (check_options) and the error model: every
// range refused with the field's name and ErrorKind::bad_option, the same for
// a library caller as for the front ends; conflicting grading sources refused;
// every error class carrying its kind.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "madd/bisect.hpp"
#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/mesh.hpp"
#include "madd/metrics.hpp"
#include "madd/output.hpp"

namespace {

using madd::DecomposeOptions;
using madd::OptionError;
using madd::Point;
using madd::Pslg;

Pslg square(bool with_weights = false) {
  Pslg p;
  p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  if (with_weights) {
    p.attributes_per_point = 1;
    p.attributes = {1, 2, 3, 4};
  }
  return p;
}

// The field OptionError names when `options` is checked, or "" when it passes.
std::string refused_field(const std::function<void()>& check) {
  try {
    check();
  } catch (const OptionError& e) {
    CHECK(e.kind() == madd::ErrorKind::bad_option);
    CHECK_FALSE(e.requirement().empty());
    CHECK(std::string(e.what()).find(e.option()) != std::string::npos);
    return e.option();
  }
  return {};
}

struct Case {
  const char* field;
  std::function<void(DecomposeOptions&)> set;
};

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace

TEST_SUITE("options") {

TEST_CASE("check_options refuses every field out of its range, naming the field") {
  const std::vector<Case> bad = {
      {"subdomains", [](DecomposeOptions& o) { o.subdomains = 0; }},
      {"separator_angle_deg", [](DecomposeOptions& o) { o.separator_angle_deg = 0; }},
      {"separator_angle_deg", [](DecomposeOptions& o) { o.separator_angle_deg = 90; }},
      {"separator_angle_deg", [](DecomposeOptions& o) { o.separator_angle_deg = -5; }},
      {"separator_angle_deg", [](DecomposeOptions& o) { o.separator_angle_deg = not_a_number; }},
      {"boundary_refinement", [](DecomposeOptions& o) { o.boundary_refinement = 0; }},
      {"boundary_refinement", [](DecomposeOptions& o) { o.boundary_refinement = infinity; }},
      {"min_split_quality", [](DecomposeOptions& o) { o.min_split_quality = 0; }},
      {"min_split_quality", [](DecomposeOptions& o) { o.min_split_quality = 1.0000001; }},
      {"min_split_quality", [](DecomposeOptions& o) { o.min_split_quality = not_a_number; }},
      {"threads", [](DecomposeOptions& o) { o.threads = madd::max_threads + 1; }},
      {"max_split_retries", [](DecomposeOptions& o) { o.max_split_retries = -1; }},
      {"smoothing_iterations", [](DecomposeOptions& o) { o.smoothing_iterations = -1; }},
      {"smoothing_iterations", [](DecomposeOptions& o) { o.smoothing_iterations = 1001; }},
      {"repair_balance_above", [](DecomposeOptions& o) { o.repair_balance_above = 0.99; }},
      {"adaptive_boundary_refinement", [](DecomposeOptions& o) { o.adaptive_boundary_refinement = 0.5; }},
      {"adaptive_boundary_refinement", [](DecomposeOptions& o) { o.adaptive_boundary_refinement = 65.0; }},
      {"adaptive_boundary_refinement", [](DecomposeOptions& o) { o.adaptive_boundary_refinement = not_a_number; }},
      {"repair_balance_above", [](DecomposeOptions& o) { o.repair_balance_above = -1.0; }},
      {"repair_balance_above", [](DecomposeOptions& o) { o.repair_balance_above = not_a_number; }},
      {"repair_balance_above", [](DecomposeOptions& o) { o.repair_balance_above = infinity; }},
      {"gradation", [](DecomposeOptions& o) { o.gradation = -0.5; }},
      {"gradation", [](DecomposeOptions& o) { o.gradation = not_a_number; }},
      {"interpolation", [](DecomposeOptions& o) { o.interpolation = -1; }},
      {"subdomain_area_ratio", [](DecomposeOptions& o) { o.subdomain_area_ratio = 0; }},
      {"time_limit_seconds", [](DecomposeOptions& o) { o.time_limit_seconds = -1; }},
      {"time_limit_seconds", [](DecomposeOptions& o) { o.time_limit_seconds = not_a_number; }},
      {"weight_samples",
       [](DecomposeOptions& o) {
         o.weight_samples = {{{0.5, 0.5}, -1}};
       }},
      {"weight_samples",
       [](DecomposeOptions& o) {
         o.weight_samples = {{{not_a_number, 0.5}, 1}};
       }},
      {"subdomain_area_samples",
       [](DecomposeOptions& o) {
         o.subdomain_area_samples = {{{0.5, 0.5}, 0}};
       }},
      {"subdomain_area_samples",
       [](DecomposeOptions& o) {
         o.subdomain_area_samples = {{{0.5, 0.5}, not_a_number}};
       }},
  };
  for (const Case& c : bad) {
    CAPTURE(c.field);
    DecomposeOptions o;
    c.set(o);
    CHECK(refused_field([&] { madd::check_options(o); }) == c.field);
    CHECK(refused_field([&] { madd::check_option_ranges(o); }) == c.field);
    // decompose() refuses the same options the same way, before any work.
    CHECK(refused_field([&] { (void)madd::decompose(square(), o); }) == c.field);
  }
}

TEST_CASE("values at the ends of each range are accepted") {
  const std::vector<std::function<void(DecomposeOptions&)>> good = {
      [](DecomposeOptions& o) { o.separator_angle_deg = 1e-9; },
      [](DecomposeOptions& o) { o.separator_angle_deg = 89.999; },
      [](DecomposeOptions& o) { o.min_split_quality = 1.0; },
      [](DecomposeOptions& o) { o.min_split_quality = 1e-9; },
      [](DecomposeOptions& o) { o.threads = madd::max_threads; },
      [](DecomposeOptions& o) { o.smoothing_iterations = 0; },
      [](DecomposeOptions& o) { o.smoothing_iterations = 1000; },
      [](DecomposeOptions& o) { o.repair_balance_above = 0.0; },
      [](DecomposeOptions& o) { o.repair_balance_above = 1.0; },
      [](DecomposeOptions& o) { o.adaptive_boundary_refinement = 1.0; },
      [](DecomposeOptions& o) { o.adaptive_boundary_refinement = 64.0; },
      [](DecomposeOptions& o) { o.max_split_retries = 0; },
      [](DecomposeOptions& o) { o.gradation = 0; },
      [](DecomposeOptions& o) { o.time_limit_seconds = 0; },
      [](DecomposeOptions& o) {
        o.weight_samples = {{{0.5, 0.5}, 0}};
      },
      [](DecomposeOptions& o) { o.gradation = 2, o.interpolation = 0.5; },
  };
  for (const auto& set : good) {
    DecomposeOptions o;
    set(o);
    CHECK(refused_field([&] { madd::check_options(o); }).empty());
  }
}

TEST_CASE("two sources of the same grading input are refused, not silently dropped") {
  DecomposeOptions o;
  o.weight_function = [](double, double) { return 1.0; };
  o.weight_samples = {{{0.5, 0.5}, 1.0}};
  CHECK(refused_field([&] { madd::check_options(o); }) == "weight_samples");
  // Each alone is a valid range: only the combination is wrong.
  CHECK(refused_field([&] { madd::check_option_ranges(o); }).empty());

  DecomposeOptions a;
  a.subdomain_area_function = [](double, double) { return 0.1; };
  a.subdomain_area_samples = {{{0.5, 0.5}, 0.1}};
  CHECK(refused_field([&] { madd::check_options(a); }) == "subdomain_area_samples");

  DecomposeOptions p;
  p.interpolation = 0.5;  // no boundary weights to interpolate
  CHECK(refused_field([&] { madd::check_options(p); }) == "interpolation");
  p.gradation = 1;
  p.weight_function = [](double, double) { return 1.0; };  // weights from the function: p still unused
  CHECK(refused_field([&] { madd::check_options(p); }) == "interpolation");
}

TEST_CASE("grading by boundary weights needs a domain that has them") {
  DecomposeOptions o;
  o.subdomains = 4;
  o.gradation = 3;
  CHECK(refused_field([&] { madd::check_options(o, square(false)); }) == "gradation");
  CHECK(refused_field([&] { (void)madd::decompose(square(false), o); }) == "gradation");
  CHECK(refused_field([&] { madd::check_options(o, square(true)); }).empty());
  CHECK(madd::decompose(square(true), o).subdomains.size() == 4);
}

TEST_CASE("an area function of 0, a negative value or NaN is refused like such a background area") {
  for (const double value : {0.0, -1.0, not_a_number, infinity}) {
    CAPTURE(value);
    DecomposeOptions o;
    o.subdomains = 64;
    o.subdomain_area_function = [value](double, double) { return value; };
    CHECK(refused_field([&] { (void)madd::decompose(square(), o); }) == "subdomain_area_function");
    DecomposeOptions b;
    b.subdomains = 64;
    b.subdomain_area_samples = {{{0.5, 0.5}, value}};
    CHECK(refused_field([&] { (void)madd::decompose(square(), b); }) == "subdomain_area_samples");
  }
  // Positive only in part of the domain is refused too: the value is a size everywhere.
  DecomposeOptions half;
  half.subdomains = 64;
  half.subdomain_area_function = [](double x, double) { return x < 0.5 ? 0.01 : -0.01; };
  CHECK(refused_field([&] { (void)madd::decompose(square(), half); }) == "subdomain_area_function");
}

TEST_CASE("split to a required area, N is a maximum, and the result says how far it got") {
  DecomposeOptions o;
  o.subdomains = 6;
  o.subdomain_area_function = [](double, double) { return 0.01; };  // wants about 100 subdomains
  const madd::Decomposition d = madd::decompose(square(), o);
  CHECK(d.subdomains.size() == 6);
  CHECK(d.subdomain_area_ratio == o.subdomain_area_ratio);
  CHECK(madd::expected_subdomain_count(d, 6) == 6);
  CHECK(madd::verify_decomposition(d, square(), madd::expected_subdomain_count(d, 6)).ok());
  const madd::Metrics m = madd::metrics(d);
  CHECK(m.subdomain_area_ratio == o.subdomain_area_ratio);
  double largest_ratio = 0;
  std::uint32_t over = 0;
  for (const madd::Subdomain& s : d.subdomains) {
    CHECK(s.required_area == doctest::Approx(0.01));
    largest_ratio = std::max(largest_ratio, s.area / s.required_area);
    over += s.area / s.required_area > o.subdomain_area_ratio ? 1u : 0u;
  }
  CHECK(m.max_area_over_required == doctest::Approx(largest_ratio));
  CHECK(m.subdomains_over_area_bound == over);
  CHECK(over == 6);  // every subdomain still about 16 times too large
  CHECK(madd::format_report_json(m).find("\"subdomains_over_area_bound\": 6") != std::string::npos);

  // Reached before N: fewer subdomains is the expected count, none over the bound.
  o.subdomains = 1000;
  o.subdomain_area_function = [](double, double) { return 0.2; };
  const madd::Decomposition e = madd::decompose(square(), o);
  CHECK(e.subdomains.size() < 1000);
  CHECK(madd::expected_subdomain_count(e, 1000) == e.subdomains.size());
  CHECK(madd::metrics(e).subdomains_over_area_bound == 0);
  CHECK(madd::metrics(e).max_area_over_required <= o.subdomain_area_ratio);

  // A uniform decomposition asks for exactly N, and its report has no such keys.
  DecomposeOptions u;
  u.subdomains = 3;
  const madd::Decomposition f = madd::decompose(square(), u);
  CHECK(f.subdomain_area_ratio == 0.0);
  CHECK(madd::expected_subdomain_count(f, 5) == 5);
  CHECK(madd::format_report_json(madd::metrics(f)).find("area_bound") == std::string::npos);
}

TEST_CASE("the size field's terms: negative or not finite, hmax below hmin, a rate without hmin, a gradation of "
          "nothing are refused, naming the field") {
  struct SizeCase {
    const char* field;
    std::function<void(madd::MeshSizeOptions&)> set;
  };
  const std::vector<SizeCase> bad = {
      {"min_edge_length", [](madd::MeshSizeOptions& s) { s.min_edge_length = -0.1; }},
      {"min_edge_length", [](madd::MeshSizeOptions& s) { s.min_edge_length = infinity; }},
      {"max_edge_length", [](madd::MeshSizeOptions& s) { s.max_edge_length = not_a_number; }},
      {"max_edge_length", [](madd::MeshSizeOptions& s) { s.max_edge_length = -1; }},
      {"distance_rate", [](madd::MeshSizeOptions& s) { s.min_edge_length = 0.1, s.distance_rate = -0.2; }},
      {"distance_rate", [](madd::MeshSizeOptions& s) { s.min_edge_length = 0.1, s.distance_rate = infinity; }},
      {"cells_across", [](madd::MeshSizeOptions& s) { s.cells_across = -3; }},
      {"cells_across", [](madd::MeshSizeOptions& s) { s.cells_across = not_a_number; }},
      {"size_gradation", [](madd::MeshSizeOptions& s) { s.max_edge_length = 1, s.size_gradation = -0.2; }},
      {"size_gradation", [](madd::MeshSizeOptions& s) { s.max_edge_length = 1, s.size_gradation = infinity; }},
      // hmax below hmin, both set.
      {"max_edge_length", [](madd::MeshSizeOptions& s) { s.min_edge_length = 0.2, s.max_edge_length = 0.1; }},
      // A distance rate grows from hmin: without it there is nothing to grow from.
      {"distance_rate", [](madd::MeshSizeOptions& s) { s.distance_rate = 0.15; }},
      {"distance_rate", [](madd::MeshSizeOptions& s) { s.max_edge_length = 1, s.distance_rate = 0.15; }},
      // Gradation only lowers a field: alone, or with hmin alone, it has nothing to grade.
      {"size_gradation", [](madd::MeshSizeOptions& s) { s.size_gradation = 0.2; }},
      {"size_gradation", [](madd::MeshSizeOptions& s) { s.min_edge_length = 0.1, s.size_gradation = 0.2; }},
  };
  for (const SizeCase& c : bad) {
    CAPTURE(c.field);
    madd::MeshOptions o;
    c.set(o.size);
    CHECK(refused_field([&] { madd::check_options(o); }) == c.field);
    CHECK(refused_field([&] { (void)madd::mesh(square(), o); }) == c.field);  // before any work
  }
  // The same values in the combinations that make sense pass.
  const std::vector<std::function<void(madd::MeshSizeOptions&)>> good = {
      [](madd::MeshSizeOptions& s) { s.min_edge_length = 0.1, s.max_edge_length = 0.1; },  // hmax = hmin
      [](madd::MeshSizeOptions& s) { s.min_edge_length = 0.2; },  // a floor of nothing: taken, as 0 terms are
      [](madd::MeshSizeOptions& s) { s.min_edge_length = 0.01, s.distance_rate = 0.15; },
      [](madd::MeshSizeOptions& s) { s.cells_across = 3, s.size_gradation = 0.2; },
      [](madd::MeshSizeOptions& s) { s.max_edge_length = 0.5, s.size_gradation = 0.2; },
      [](madd::MeshSizeOptions& s) { s.max_triangle_area = 0.01, s.size_gradation = 0.2; },
      [](madd::MeshSizeOptions& s) {
        s.triangle_area_function = [](double, double) { return 0.01; };
        s.size_gradation = 1;
      },
      [](madd::MeshSizeOptions& s) {
        s.triangle_area_samples = {{{0.5, 0.5}, 0.01}};
        s.size_gradation = 0.2;
      },
      [](madd::MeshSizeOptions& s) { s.min_edge_length = 0.01, s.distance_rate = 0.15, s.size_gradation = 0.2; },
      [](madd::MeshSizeOptions& s) {
        s.coast_markers = {1, -2};
        s.cells_across = 2;
      },
  };
  for (std::size_t i = 0; i < good.size(); ++i) {
    CAPTURE(i);
    madd::MeshOptions o;
    good[i](o.size);
    CHECK(refused_field([&] { madd::check_options(o); }).empty());
  }
}

TEST_CASE("bisection, partition and picture options are refused as OptionError too") {
  madd::Graph g;
  g.offsets = {0, 1, 2};
  g.adjacency = {1, 0};
  g.edge_weights = {1, 1};
  g.vertex_weights = {1, 1};
  madd::BisectOptions b;
  b.target_fraction = 1.0;
  CHECK(refused_field([&] { (void)madd::bisect(g, b); }) == "target_fraction");
  b = {};
  b.balance_tolerance = -0.1;
  CHECK(refused_field([&] { madd::check_options(b); }) == "balance_tolerance");
  CHECK(refused_field([&] { (void)madd::partition(g, 0); }) == "k");
  madd::PartitionOptions p;
  p.balance_tolerance = not_a_number;
  CHECK(refused_field([&] { (void)madd::partition(g, 2, p); }) == "balance_tolerance");
  madd::SvgOptions s;
  s.mark_angles_below_deg = 181;
  CHECK(refused_field([&] { madd::check_options(s); }) == "mark_angles_below_deg");
}

TEST_CASE("every error carries its kind") {
  CHECK(OptionError("refine", "must be > 0").kind() == madd::ErrorKind::bad_option);
  CHECK(madd::ParseError("f", 1, 2, "m").kind() == madd::ErrorKind::bad_input);
  CHECK(madd::InvalidInputError(madd::InputProblem::other, "m").kind() == madd::ErrorKind::bad_input);
  CHECK(madd::InputFileError("m").kind() == madd::ErrorKind::bad_input);
  CHECK(madd::DecompositionError("m").kind() == madd::ErrorKind::decomposition);
  CHECK(madd::OutputError("m").kind() == madd::ErrorKind::output);
  CHECK(madd::LimitError("m").kind() == madd::ErrorKind::limit);
  CHECK(madd::InternalError("m").kind() == madd::ErrorKind::internal);
  const OptionError located("refine", "must be > 0", "run.madd:3:7: r must be > 0");
  CHECK(std::string(located.what()) == "run.madd:3:7: r must be > 0");
  CHECK(located.option() == "refine");
  CHECK(located.requirement() == "must be > 0");
}

}  // TEST_SUITE("options")
