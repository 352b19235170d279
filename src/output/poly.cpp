// Outputs 1 and 2 of docs/formats.md: the decomposition as Triangle .poly text.
#include <string>
#include <unordered_map>
#include <vector>

#include "madd/output.hpp"
#include "kernel/number_format.hpp"
#include "output/faces.hpp"
#include "output/subdomain_poly.hpp"

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

// The regions section of output 1 (only_subdomain == no_index) or of output 2
// (the faces of that subdomain), as docs/formats.md, "Interior segments in the
// outputs", describes: without input regions, output 1 labels every face with
// its subdomain number and output 2 writes none; with them, every face gets
// the attribute and area bound of the input region that covers it (0 and -1,
// what Triangle gives a triangle no region reaches, where none does).
void append_regions(std::string& out, const Decomposition& d, const std::vector<detail::DecompositionFace>& faces,
                    std::uint32_t only_subdomain) {
  const bool input_regions = !d.regions.empty();
  if (!input_regions && only_subdomain != no_index) return;
  std::vector<const detail::DecompositionFace*> chosen;
  for (const detail::DecompositionFace& f : faces)
    if (only_subdomain == no_index || f.subdomain == only_subdomain) chosen.push_back(&f);
  if (input_regions) {
    out += "# regions: the input region covering each part of the subdomain";
    out += only_subdomain == no_index ? "s" : "";
    out += " between interior segments (0, -1: none)\n";
  } else if (chosen.size() == d.subdomains.size()) {
    out += "# regions: one per subdomain, attribute = subdomain number, no area bound\n";
  } else {
    out += "# regions: one per part of a subdomain between its interior segments, attribute = subdomain number, no "
           "area bound\n";
  }
  append_int(out, static_cast<std::int64_t>(chosen.size()));
  out += '\n';
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const detail::DecompositionFace& f = *chosen[i];
    append_point_line(out, i + 1, f.point);
    out += ' ';
    if (!input_regions) {
      append_int(out, f.subdomain);
      out += " -1\n";
      continue;
    }
    const Region none{f.point, 0.0, -1.0};
    const Region& r = f.region == no_index ? none : d.regions[f.region];
    append_g17(out, r.attribute);
    out += ' ';
    append_g17(out, r.max_area);
    out += "  # subdomain ";
    append_int(out, f.subdomain);
    if (f.region != no_index) {
      out += ", input region ";
      append_int(out, std::int64_t{f.region} + 1);
    }
    out += '\n';
  }
}

}  // namespace

std::string format_decomposition_poly(const Decomposition& d, std::string_view header_comment) {
  std::string out;
  out.reserve(64 * (d.points.size() + d.segments.size()) + 256);
  append_comment(out, header_comment);
  out += "# madd decomposition: " + std::to_string(d.subdomains.size()) + " subdomains; separators have marker 0; ";
  out += d.regions.empty() ? "region attribute = subdomain number\n"
                           : "regions carry the input's attributes and area bounds, each line names its subdomain\n";
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
  append_regions(out, d, detail::decomposition_faces(d), no_index);
  return out;
}

std::string detail::format_subdomain_poly(const Decomposition& d, std::uint32_t k,
                                          const std::vector<DecompositionFace>& faces) {
  const Subdomain& sub = d.subdomains.at(k);
  // Local 1-based ids in order of first appearance: ring vertices (a vertex
  // shared by two rings, a hole touching the outer ring, is written once),
  // then the other ends of interior segments, then the isolated points.
  std::unordered_map<std::uint32_t, std::uint32_t> local;
  std::vector<std::uint32_t> order;
  const auto add = [&](std::uint32_t p) {
    if (local.emplace(p, static_cast<std::uint32_t>(order.size() + 1)).second) order.push_back(p);
  };
  std::size_t segment_count = sub.interior_segments.size();
  for (const auto& ring : sub.rings) {
    segment_count += ring.size();
    for (std::uint32_t p : ring) add(p);
  }
  for (const std::uint32_t s : sub.interior_segments) {
    add(d.segments[s].a);
    add(d.segments[s].b);
  }
  for (const std::uint32_t p : sub.interior_points) add(p);
  std::string out;
  out.reserve(64 * (order.size() + segment_count) + 256);
  out += "# madd subdomain " + std::to_string(k) + " of " + std::to_string(d.subdomains.size()) + ", area ";
  append_g17(out, sub.area);
  out += ", weight ";
  append_g17(out, sub.weight);
  out += "\n# separators have marker 0\n";
  if (!sub.interior_segments.empty() || !sub.interior_points.empty())
    out += "# after the rings: " + std::to_string(sub.interior_segments.size()) + " interior segments, " +
           std::to_string(sub.interior_points.size()) + " isolated points\n";
  append_int(out, static_cast<std::int64_t>(order.size()));
  out += " 2 0 0\n";
  for (std::size_t i = 0; i < order.size(); ++i) {
    append_point_line(out, i + 1, d.points[order[i]]);
    out += '\n';
  }
  append_int(out, static_cast<std::int64_t>(segment_count));
  out += " 1\n";
  std::int64_t id = 0;
  const auto append_segment = [&](std::uint32_t a, std::uint32_t b, int marker) {
    append_int(out, ++id);
    out += ' ';
    append_int(out, local[a]);
    out += ' ';
    append_int(out, local[b]);
    out += ' ';
    append_int(out, marker);
    out += '\n';
  };
  for (std::size_t r = 0; r < sub.rings.size(); ++r) {
    const auto& ring = sub.rings[r];
    for (std::size_t j = 0; j < ring.size(); ++j)
      append_segment(ring[j], ring[(j + 1) % ring.size()], d.segments[sub.ring_segments[r][j]].marker);
  }
  for (const std::uint32_t s : sub.interior_segments)
    append_segment(d.segments[s].a, d.segments[s].b, d.segments[s].marker);
  append_holes(out, sub.hole_points);
  append_regions(out, d, faces, k);
  return out;
}

std::string format_subdomain_poly(const Decomposition& d, std::uint32_t k) {
  (void)d.subdomains.at(k);  // out of range: throw before the faces are computed
  // Faces are only needed for the input's regions (none: no triangulation).
  return detail::format_subdomain_poly(
      d, k, d.regions.empty() ? std::vector<detail::DecompositionFace>{} : detail::decomposition_faces(d));
}

std::string split_file_name(std::string_view stem, std::uint32_t k, std::uint32_t count) {
  const std::string last = std::to_string(count > 0 ? count - 1 : 0);
  std::string number = std::to_string(k);
  if (number.size() < last.size()) number.insert(0, last.size() - number.size(), '0');
  return std::string(stem) + "-" + number + ".poly";
}

}  // namespace madd
