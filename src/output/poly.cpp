// Outputs 1 and 2 of docs/formats.md: the decomposition as Triangle .poly text.
#include <string>
#include <unordered_map>
#include <vector>

#include "madd/output.hpp"
#include "kernel/number_format.hpp"

namespace madd {

namespace {

using detail::append_g17;
using detail::append_int;

void append_comment(std::string& out, std::string_view comment) {
  std::size_t start = 0;
  while (start < comment.size()) {
    std::size_t end = comment.find('\n', start);
    if (end == std::string_view::npos) end = comment.size();
    out += "# ";
    out.append(comment.substr(start, end - start));
    out += '\n';
    start = end + 1;
  }
}

void append_point_line(std::string& out, std::size_t id, Point p) {
  append_int(out, static_cast<std::int64_t>(id));
  out += ' ';
  append_g17(out, p.x);
  out += ' ';
  append_g17(out, p.y);
}

void append_holes(std::string& out, const std::vector<Point>& holes) {
  out += "# holes\n";
  append_int(out, static_cast<std::int64_t>(holes.size()));
  out += '\n';
  for (std::size_t h = 0; h < holes.size(); ++h) {
    append_point_line(out, h + 1, holes[h]);
    out += '\n';
  }
}

} // namespace

std::string format_decomposition_poly(const Decomposition& d, std::string_view header_comment) {
  std::string out;
  out.reserve(64 * (d.points.size() + d.segments.size()) + 256);
  append_comment(out, header_comment);
  out += "# madd decomposition: " + std::to_string(d.subdomains.size()) +
         " subdomains; separators have marker 0; region attribute = subdomain number\n";
  append_int(out, static_cast<std::int64_t>(d.points.size()));
  out += " 2 0 0\n";
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    append_point_line(out, p + 1, d.points[p]);
    out += '\n';
  }
  append_int(out, static_cast<std::int64_t>(d.segments.size()));
  out += " 1\n";
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const Segment& g = d.segments[s];
    append_int(out, static_cast<std::int64_t>(s + 1));
    out += ' ';
    append_int(out, std::int64_t{g.a} + 1);
    out += ' ';
    append_int(out, std::int64_t{g.b} + 1);
    out += ' ';
    append_int(out, g.marker);
    out += '\n';
  }
  append_holes(out, d.holes);
  out += "# regions: one per subdomain, attribute = subdomain number, no area bound\n";
  append_int(out, static_cast<std::int64_t>(d.subdomains.size()));
  out += '\n';
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    append_point_line(out, k + 1, d.subdomains[k].interior_point);
    out += ' ';
    append_int(out, static_cast<std::int64_t>(k));
    out += " -1\n";
  }
  return out;
}

std::string format_subdomain_poly(const Decomposition& d, std::uint32_t k) {
  const Subdomain& sub = d.subdomains.at(k);
  // Local 1-based ids in order of first appearance; a vertex shared by two
  // rings (a hole touching the outer ring) is written once.
  std::unordered_map<std::uint32_t, std::uint32_t> local;
  std::vector<std::uint32_t> order;
  std::size_t segment_count = 0;
  for (const auto& ring : sub.rings) {
    segment_count += ring.size();
    for (std::uint32_t p : ring)
      if (local.emplace(p, static_cast<std::uint32_t>(order.size() + 1)).second) order.push_back(p);
  }
  std::string out;
  out.reserve(64 * (order.size() + segment_count) + 256);
  out += "# madd subdomain " + std::to_string(k) + " of " + std::to_string(d.subdomains.size()) + ", area ";
  append_g17(out, sub.area);
  out += ", weight ";
  append_g17(out, sub.weight);
  out += "\n# separators have marker 0\n";
  append_int(out, static_cast<std::int64_t>(order.size()));
  out += " 2 0 0\n";
  for (std::size_t i = 0; i < order.size(); ++i) {
    append_point_line(out, i + 1, d.points[order[i]]);
    out += '\n';
  }
  append_int(out, static_cast<std::int64_t>(segment_count));
  out += " 1\n";
  std::int64_t id = 0;
  for (std::size_t r = 0; r < sub.rings.size(); ++r) {
    const auto& ring = sub.rings[r];
    for (std::size_t j = 0; j < ring.size(); ++j) {
      append_int(out, ++id);
      out += ' ';
      append_int(out, local[ring[j]]);
      out += ' ';
      append_int(out, local[ring[(j + 1) % ring.size()]]);
      out += ' ';
      append_int(out, d.segments[sub.ring_segments[r][j]].marker);
      out += '\n';
    }
  }
  append_holes(out, sub.hole_points);
  return out;
}

std::string split_file_name(std::string_view stem, std::uint32_t k, std::uint32_t count) {
  const std::string last = std::to_string(count > 0 ? count - 1 : 0);
  std::string number = std::to_string(k);
  if (number.size() < last.size()) number.insert(0, last.size() - number.size(), '0');
  return std::string(stem) + "-" + number + ".poly";
}

} // namespace madd
