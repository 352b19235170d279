// madd_bench size_field [--extent-over-hmin F] [--hmax-over-hmin M] [--distance G]
//                       [--across R] [--gradation G] [--queries Q] [--runs K]
//                       [--mesh N] [--threads T] FILE.poly...
// The size field (src/sizing/) on each domain, with hmin = extent / F
// (2000), hmax = M hmin (50) and the other terms as given (0.15, 3, 0.2;
// 0 = off): the background's size, the time to build the field (median of
// K runs), and the time of one edge_at query (median of K runs of Q queries
// at random points of the domain, in random order and then sorted along x as
// a mesher's queries come, alternating). With --mesh N: madd::mesh at N
// subdomains, -q 30, on T threads, with the field as its area function (the
// wiring the mesher will have), and the same with the raw terms evaluated
// exactly at every query (no background: the field without its safety
// bound, interpolation or gradation), to show what the background costs in
// triangles; the background's inside triangles against the mesh's.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "bench.hpp"
#include "madd/mesh.hpp"
#include "madd/poly_io.hpp"
#include "sizing/coast.hpp"
#include "sizing/raw_field.hpp"
#include "sizing/size_field.hpp"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Settings {
  double extent_over_hmin = 2000, hmax_over_hmin = 50, distance = 0.15, across = 3, gradation = 0.2;
  std::size_t queries = 1000000;
  int runs = 3, mesh_n = 0;
  unsigned threads = 2;
};

std::vector<madd::Point> random_queries(const madd::detail::SizeBackground& bg, std::size_t count) {
  std::vector<std::uint32_t> inside;
  for (std::uint32_t t = 0; t < bg.triangles.size(); ++t)
    if (bg.inside[t] != 0) inside.push_back(t);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<madd::Point> out(count);
  for (auto& p : out) {
    const auto& v = bg.triangles[inside[rng() % inside.size()]];
    double a = unit(rng), b = unit(rng);
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    const madd::Point o = bg.points[v[0]];
    p = o + a * (bg.points[v[1]] - o) + b * (bg.points[v[2]] - o);
  }
  return out;
}

double ns_per_query(const madd::detail::SizeField& field, const std::vector<madd::Point>& queries) {
  double sum = 0.0;
  const double start = madd::bench::now_seconds();
  for (const madd::Point p : queries) sum += field.edge_at(p);
  const double seconds = madd::bench::now_seconds() - start;
  if (sum == 42.0) std::printf(" ");  // keeps the loop
  return seconds * 1e9 / static_cast<double>(queries.size());
}

std::size_t mesh_with(const madd::Pslg& domain, const Settings& s, std::function<double(double, double)> area,
                      double& seconds) {
  madd::MeshOptions o;
  o.decomposition.subdomains = static_cast<std::uint32_t>(s.mesh_n);
  o.decomposition.threads = s.threads;
  o.size.min_triangle_angle_deg = 30;
  o.size.triangle_area_function = std::move(area);
  const double start = madd::bench::now_seconds();
  try {
    const madd::Mesh m = madd::mesh(domain, o);
    seconds = madd::bench::now_seconds() - start;
    return m.triangle_count();
  } catch (const std::exception& e) {
    std::printf("  mesh failed: %s\n", e.what());
    return 0;
  }
}

void run_one(const std::string& path, const Settings& s) {
  const madd::Pslg domain = madd::read_domain(path);
  double x0 = domain.points[0].x, x1 = x0, y0 = domain.points[0].y, y1 = y0;
  for (const madd::Point p : domain.points)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  madd::MeshSizeOptions size;
  size.min_edge_length = std::max(x1 - x0, y1 - y0) / s.extent_over_hmin;
  size.max_edge_length = s.hmax_over_hmin * size.min_edge_length;
  size.distance_rate = s.distance;
  size.cells_across = s.across;
  size.size_gradation = s.gradation;
  std::vector<double> build;
  madd::detail::SizeField field;
  for (int r = 0; r < s.runs; ++r) {
    field = madd::detail::SizeField(domain, size);
    build.push_back(field.report().seconds);
  }
  const auto& bg = field.background();
  const auto& rep = field.report();
  std::vector<madd::Point> shuffled = random_queries(bg, s.queries), sorted = shuffled;
  std::sort(sorted.begin(), sorted.end(), [](madd::Point a, madd::Point b) { return a.x < b.x; });
  std::vector<double> random_ns, sorted_ns;
  for (int r = 0; r < s.runs; ++r) {
    random_ns.push_back(ns_per_query(field, shuffled));
    sorted_ns.push_back(ns_per_query(field, sorted));
  }
  std::printf("%s: hmin %.4g, background %zu points (%zu quadtree), %zu triangles (%zu inside, %zu exact, %.1f pieces "
              "each); build %.3f s; "
              "edge_at %.1f ns random, %.1f ns sorted; gradation %zu pops %zu fixes %zu held%s; floored %zu\n",
              path.c_str(), size.min_edge_length, bg.points.size(), rep.steiner_points, bg.triangles.size(),
              rep.inside_triangles, rep.exact_triangles,
              static_cast<double>(rep.coast_candidates) /
                  std::max<double>(1.0, static_cast<double>(rep.exact_triangles)),
              median(build), median(random_ns), median(sorted_ns), rep.gradation_pops, rep.gradation_fixes,
              rep.gradation_held, rep.gradation_fell_back ? " (fell back)" : "", rep.floored_points);
  if (s.mesh_n <= 0) return;
  double t_field = 0, t_raw = 0;
  const std::size_t with_field = mesh_with(
      domain, s,
      [&](double x, double y) {
        return madd::detail::area_of_edge(field.edge_at({x, y}));
      },
      t_field);
  // The raw terms exactly, without the gradation (there is no exact form of it).
  madd::MeshSizeOptions raw_size = size;
  raw_size.size_gradation = 0.0;
  const madd::detail::Coast coast = madd::detail::trace_coast(domain, {});
  const madd::detail::RawField raw(coast, raw_size);
  const std::size_t with_raw = mesh_with(
      domain, s,
      [&](double x, double y) {
        return madd::detail::area_of_edge(raw.at({x, y}).edge);
      },
      t_raw);
  std::printf("  mesh -n %d -q 30: %zu triangles with the field (%.2f s; background inside %.2f%% of it), "
              "%zu with the raw terms exactly (%.2f s): field / raw %.3f\n",
              s.mesh_n, with_field, t_field,
              100.0 * static_cast<double>(rep.inside_triangles) / static_cast<double>(with_field), with_raw, t_raw,
              static_cast<double>(with_field) / static_cast<double>(with_raw));
}

int run(int argc, char** argv) {
  Settings s;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&] { return i + 1 < argc ? std::atof(argv[++i]) : 0.0; };
    if (a == "--extent-over-hmin") s.extent_over_hmin = value();
    else if (a == "--hmax-over-hmin") s.hmax_over_hmin = value();
    else if (a == "--distance") s.distance = value();
    else if (a == "--across") s.across = value();
    else if (a == "--gradation") s.gradation = value();
    else if (a == "--queries") s.queries = static_cast<std::size_t>(value());
    else if (a == "--runs") s.runs = static_cast<int>(value());
    else if (a == "--mesh") s.mesh_n = static_cast<int>(value());
    else if (a == "--threads") s.threads = static_cast<unsigned>(value());
    else files.push_back(a);
  }
  if (files.empty() || s.runs < 1 || s.queries < 1) {
    std::fprintf(stderr, "usage: madd_bench size_field [--extent-over-hmin F] [--hmax-over-hmin M] [--distance G]\n"
                         "       [--across R] [--gradation G] [--queries Q] [--runs K] [--mesh N] [--threads T] "
                         "FILE.poly...\n");
    return 2;
  }
  int status = 0;
  for (const std::string& f : files) {
    try {
      run_one(f, s);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", f.c_str(), e.what());
      status = 1;
    }
  }
  return status;
}

const madd::bench::Registration registration("size_field", run);

}  // namespace
