// Benchmark of the multilevel bisector on dual graphs of triangulations
// (Delaunay of random points, jittered structured meshes) and grid graphs.
// `madd_bench bisect [--sizes 10000,100000,1000000] [--out DIR]` prints a
// table; with --out it also writes each graph in METIS format (fmt 011,
// integer weights scaled to mean 1000, minimum 1, as peers/metis_dd.py does)
// so `gpmetis -ptype=rb -ufactor=30 FILE 2` and `madd partition FILE 2
// --ufactor 30` can be compared on the very same graph.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "bench.hpp"
#include "madd/bisect.hpp"
#include "madd/graph.hpp"
#include "madd/triangulation.hpp"

namespace {

std::uint64_t mix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
double unit(std::uint64_t& s) { return static_cast<double>(mix(s) >> 11) * 0x1.0p-53; }

// Element dual graph: vertex = triangle (weight area), edge = shared edge (weight length).
madd::Graph dual_graph(const std::vector<madd::Point>& pts, const std::vector<std::array<std::uint32_t, 3>>& tris,
                       const std::vector<std::array<std::uint32_t, 3>>& nbrs) {
  std::vector<double> area(tris.size());
  std::vector<madd::WeightedEdge> edges;
  for (std::uint32_t t = 0; t < tris.size(); ++t) {
    const auto& a = pts[tris[t][0]];
    const auto& b = pts[tris[t][1]];
    const auto& c = pts[tris[t][2]];
    area[t] = 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = nbrs[t][i];
      if (u == madd::no_index || u < t) continue;
      const auto& p = pts[tris[t][(i + 1) % 3]];
      const auto& q = pts[tris[t][(i + 2) % 3]];
      edges.push_back({t, u, std::hypot(p.x - q.x, p.y - q.y)});
    }
  }
  return madd::make_graph(std::move(area), edges);
}

madd::Graph delaunay_dual(std::size_t triangles, std::uint64_t seed) {
  std::vector<madd::Point> pts(triangles / 2 + 2);
  for (auto& p : pts) p = {unit(seed), unit(seed)};
  const madd::Triangulation tri = madd::delaunay(pts);
  return dual_graph(tri.points, tri.triangles, tri.neighbours);
}

// A rows x cols grid of jittered points, each cell split into two triangles.
madd::Graph structured_dual(std::size_t triangles, std::uint64_t seed) {
  const auto cols = static_cast<std::uint32_t>(std::sqrt(static_cast<double>(triangles) / 2.0)) + 1;
  const auto rows = static_cast<std::uint32_t>(triangles / (2 * cols)) + 1;
  std::vector<madd::Point> pts;
  for (std::uint32_t r = 0; r <= rows; ++r)
    for (std::uint32_t c = 0; c <= cols; ++c)
      pts.push_back({c + 0.3 * (unit(seed) - 0.5), r + 0.3 * (unit(seed) - 0.5)});
  std::vector<std::array<std::uint32_t, 3>> tris, nbrs;
  const auto id = [&](std::uint32_t r, std::uint32_t c) { return r * (cols + 1) + c; };
  const auto tri_id = [&](std::uint32_t r, std::uint32_t c, std::uint32_t k) { return 2 * (r * cols + c) + k; };
  for (std::uint32_t r = 0; r < rows; ++r) {
    for (std::uint32_t c = 0; c < cols; ++c) {
      const std::uint32_t none = madd::no_index;
      // Lower triangle (a b d) and upper (b c d) of cell with corners a b c d (ccw from bottom-left).
      tris.push_back({id(r, c), id(r, c + 1), id(r + 1, c)});
      nbrs.push_back({tri_id(r, c, 1), c > 0 ? tri_id(r, c - 1, 1) : none, r > 0 ? tri_id(r - 1, c, 1) : none});
      tris.push_back({id(r, c + 1), id(r + 1, c + 1), id(r + 1, c)});
      nbrs.push_back(
          {r + 1 < rows ? tri_id(r + 1, c, 0) : none, tri_id(r, c, 0), c + 1 < cols ? tri_id(r, c + 1, 0) : none});
    }
  }
  return dual_graph(pts, tris, nbrs);
}

madd::Graph grid_graph(std::size_t vertices) {
  const auto side = static_cast<std::uint32_t>(std::sqrt(static_cast<double>(vertices)));
  std::vector<madd::WeightedEdge> edges;
  for (std::uint32_t r = 0; r < side; ++r)
    for (std::uint32_t c = 0; c < side; ++c) {
      const std::uint32_t v = r * side + c;
      if (c + 1 < side) edges.push_back({v, v + 1, 1.0});
      if (r + 1 < side) edges.push_back({v, v + side, 1.0});
    }
  return madd::make_graph(std::vector<double>(std::size_t{side} * side, 1.0), edges);
}

// METIS fmt 011 with integer weights of mean 1000 (minimum 1).
void write_metis(const madd::Graph& g, const std::string& path) {
  double vsum = 0.0, esum = 0.0;
  for (const double w : g.vertex_weights) vsum += w;
  for (const double w : g.edge_weights) esum += w;
  const double vs = 1000.0 * static_cast<double>(g.vertex_count()) / vsum;
  const double es = 1000.0 * static_cast<double>(g.adjacency.size()) / esum;
  const auto scaled = [](double w, double s) { return std::max(1.0, std::nearbyint(w * s)); };
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return;
  std::fprintf(f, "%zu %zu 011\n", g.vertex_count(), g.edge_count());
  for (std::uint32_t v = 0; v < g.vertex_count(); ++v) {
    std::fprintf(f, "%.0f", scaled(g.vertex_weights[v], vs));
    for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i)
      std::fprintf(f, " %u %.0f", g.adjacency[i] + 1, scaled(g.edge_weights[i], es));
    std::fputc('\n', f);
  }
  std::fclose(f);
}

void run_one(const char* kind, std::size_t size, const madd::Graph& g, const std::string& out_dir) {
  madd::BisectOptions o;
  o.balance_tolerance = 0.03;
  const double t0 = madd::bench::now_seconds();
  const std::clock_t c0 = std::clock();
  const madd::Bisection b = madd::bisect(g, o);
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;  // gpmetis reports CPU time
  const double t = madd::bench::now_seconds() - t0;
  const bool ok = madd::verify_bisection(g, b).ok();
  const double total = b.weight[0] + b.weight[1];
  std::printf("| %-10s | %8zu | %8zu | %12.6g | %7.4f | %5s | %8.3f | %8.3f | %s |\n", kind, size, g.vertex_count(),
              b.cut, std::max(b.weight[0], b.weight[1]) / (0.5 * total),
              b.connected[0] && b.connected[1] ? "yes" : "no", t, cpu, ok ? "ok" : "FAILED");
  std::fflush(stdout);
  if (!out_dir.empty()) write_metis(g, out_dir + "/" + kind + "-" + std::to_string(size) + ".graph");
}

int run_bisect(int argc, char** argv) {
  std::vector<std::size_t> sizes = {10000, 100000, 1000000};
  std::string out_dir;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string arg = argv[i];
    if (arg == "--out") out_dir = argv[i + 1];
    if (arg == "--sizes") {
      sizes.clear();
      std::string list = argv[i + 1];
      for (std::size_t p = 0; p < list.size();) {
        const std::size_t q = std::min(list.find(',', p), list.size());
        sizes.push_back(std::stoull(list.substr(p, q - p)));
        p = q + 1;
      }
    }
  }
  std::printf("| graph      | size     | vertices | cut          | balance | conn  | wall s   | cpu s    | verify |\n");
  std::printf("|------------|----------|----------|--------------|---------|-------|----------|----------|--------|\n");
  for (const std::size_t n : sizes) {
    run_one("delaunay", n, delaunay_dual(n, 12345 + n), out_dir);
    run_one("structured", n, structured_dual(n, 777 + n), out_dir);
    run_one("grid", n, grid_graph(n), out_dir);
  }
  std::printf("peak RSS %.1f MB\n", static_cast<double>(madd::bench::peak_rss_bytes()) / 1e6);
  return 0;
}

const madd::bench::Registration registration("bisect", run_bisect);

}  // namespace
