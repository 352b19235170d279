// Triangle's files of a triangulation (cli/triangulation_files.hpp).
#include "triangulation_files.hpp"

#include <charconv>
#include <concepts>
#include <string>
#include <vector>

namespace madd::cli {

namespace {

// One output line: the values separated by spaces. Numbers go through
// std::to_chars (doubles as the shortest text that reads back to the same
// value): the files of a 10^6-point triangulation hold ~10^7 numbers, and
// printf-style formatting of them cost more than the triangulation itself.
void put(std::string& out, double value) {
  char buf[32];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, value).ptr);
}
void put(std::string& out, std::integral auto value) {
  char buf[24];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, value).ptr);
}
void line(std::string& out, auto first, auto... rest) {
  put(out, first);
  ((out += ' ', put(out, rest)), ...);
  out += '\n';
}

// Output marker of constrained edge (t, i): the segment's marker, or 1 when the
// file gave no segment markers (every segment is then a boundary).
int edge_marker(const Pslg& pslg, const Triangulation& tri, std::uint32_t t, int i) {
  const std::uint32_t s = tri.segment_of[t][i];
  if (s == no_index) return 0;
  return pslg.has_segment_markers ? pslg.segments[s].marker : 1;
}

std::vector<int> vertex_markers(const Pslg& pslg, const Triangulation& tri) {
  std::vector<int> mark(tri.points.size(), 0);
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) {
      int m = edge_marker(pslg, tri, t, i);
      if (m == 0 && tri.neighbours[t][i] == no_index) m = 1;
      for (const int k : {(i + 1) % 3, (i + 2) % 3}) {
        if (mark[tri.triangles[t][k]] == 0) mark[tri.triangles[t][k]] = m;
      }
    }
  }
  for (std::size_t v = 0; v < pslg.point_markers.size() && v < mark.size(); ++v) {
    if (pslg.point_markers[v] != 0) mark[v] = pslg.point_markers[v];
  }
  return mark;
}

}  // namespace

std::string triangulation_node_text(const Pslg& pslg, const Triangulation& tri) {
  const std::vector<int> mark = vertex_markers(pslg, tri);
  const unsigned base = pslg.first_index;
  std::string out;
  line(out, tri.points.size(), 2, pslg.attributes_per_point, 1);
  for (std::size_t v = 0; v < tri.points.size(); ++v) {
    put(out, v + base);
    for (const double x : {tri.points[v].x, tri.points[v].y}) (out += ' ', put(out, x));
    for (std::size_t k = 0; k < pslg.attributes_per_point; ++k) (out += ' ', put(out, pslg.attribute(v, k)));
    out += ' ';
    line(out, mark[v]);
  }
  return out;
}

std::string triangulation_ele_text(const Pslg& pslg, const Triangulation& tri) {
  const unsigned base = pslg.first_index;
  std::string out;
  const bool attributes = !tri.attributes.empty();
  line(out, tri.triangle_count(), 3, attributes ? 1 : 0);
  for (std::size_t t = 0; t < tri.triangle_count(); ++t) {
    const auto& c = tri.triangles[t];
    if (attributes) {
      line(out, t + base, c[0] + base, c[1] + base, c[2] + base, tri.attributes[t]);
    } else {
      line(out, t + base, c[0] + base, c[1] + base, c[2] + base);
    }
  }
  return out;
}

std::string triangulation_neigh_text(const Pslg& pslg, const Triangulation& tri) {
  const long long base = pslg.first_index;
  std::string out;
  line(out, tri.triangle_count(), 3);
  for (std::size_t t = 0; t < tri.triangle_count(); ++t) {
    long long n[3];
    for (int i = 0; i < 3; ++i) n[i] = tri.neighbours[t][i] == no_index ? -1 : tri.neighbours[t][i] + base;
    line(out, static_cast<long long>(t) + base, n[0], n[1], n[2]);
  }
  return out;
}

// Each edge once: from the triangle with the smaller index, or the only one.
std::string triangulation_edge_text(const Pslg& pslg, const Triangulation& tri) {
  const unsigned base = pslg.first_index;
  std::string body;
  std::size_t count = 0;
  const bool hull_marks = pslg.segments.empty();
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = tri.neighbours[t][i];
      if (u != no_index && u < t) continue;
      int m = edge_marker(pslg, tri, t, i);
      if (hull_marks && u == no_index) m = 1;
      ++count;
      line(body, count - 1 + base, tri.triangles[t][(i + 1) % 3] + base, tri.triangles[t][(i + 2) % 3] + base, m);
    }
  }
  std::string out;
  line(out, count, 1);
  return out + body;
}

}  // namespace madd::cli
