// Output 3: the paper's subdomain file (Sec. 6: "points, segments, subdomains
// defined by segments, and a set of holes for each subdomain"). The exact
// layout is documented in docs/formats.md; section 5 (interior segments and
// isolated points per subdomain) is written only when there are some.
#include <algorithm>

#include "madd/output.hpp"
#include "kernel/number_format.hpp"

namespace madd {

namespace {

using detail::append_g17;
using detail::append_int;

void append_subdomain_line(std::string& out, std::size_t k, const Subdomain& sub) {
  append_int(out, static_cast<std::int64_t>(k));
  out += ' ';
  append_g17(out, sub.area);
  out += ' ';
  append_g17(out, sub.weight);
  out += ' ';
  append_int(out, static_cast<std::int64_t>(sub.ring_segments.size()));
  for (const auto& ring : sub.ring_segments) {
    out += "  ";
    append_int(out, static_cast<std::int64_t>(ring.size()));
    for (std::uint32_t s : ring) {
      out += ' ';
      append_int(out, std::int64_t{s} + 1);
    }
  }
  out += '\n';
}

// Section 5, only when some subdomain has interior constraints, so that the
// file of a domain without any is the four sections readers already know:
// per subdomain its interior segments (ids of section 2) and its isolated
// points (ids of section 1).
void append_interior_section(std::string& out, const Decomposition& d) {
  const bool any = std::any_of(d.subdomains.begin(), d.subdomains.end(), [](const Subdomain& s) {
    return !s.interior_segments.empty() || !s.interior_points.empty();
  });
  if (!any) return;
  out += "# section 5: interior constraints per subdomain: number #segments segment ids #points point ids\n";
  append_int(out, static_cast<std::int64_t>(d.subdomains.size()));
  out += '\n';
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    const Subdomain& sub = d.subdomains[k];
    append_int(out, static_cast<std::int64_t>(k));
    for (const auto* ids : {&sub.interior_segments, &sub.interior_points}) {
      out += "  ";
      append_int(out, static_cast<std::int64_t>(ids->size()));
      for (const std::uint32_t i : *ids) {
        out += ' ';
        append_int(out, std::int64_t{i} + 1);
      }
    }
    out += '\n';
  }
}

}  // namespace

std::string format_subdomain_file(const Decomposition& d) {
  std::string out;
  out.reserve(64 * (d.points.size() + 2 * d.segments.size()) + 256);
  out += "# madd subdomain file (docs/formats.md): points, segments, subdomains, holes per subdomain\n";
  out += "# section 1: points (1-based ids)\n";
  append_int(out, static_cast<std::int64_t>(d.points.size()));
  out += " 2\n";
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    append_int(out, static_cast<std::int64_t>(p + 1));
    out += ' ';
    append_g17(out, d.points[p].x);
    out += ' ';
    append_g17(out, d.points[p].y);
    out += '\n';
  }
  out += "# section 2: segments (1-based ids): id endpoint endpoint marker (0 = separator)\n";
  append_int(out, static_cast<std::int64_t>(d.segments.size()));
  out += " 1\n";
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    append_int(out, static_cast<std::int64_t>(s + 1));
    out += ' ';
    append_int(out, std::int64_t{d.segments[s].a} + 1);
    out += ' ';
    append_int(out, std::int64_t{d.segments[s].b} + 1);
    out += ' ';
    append_int(out, d.segments[s].marker);
    out += '\n';
  }
  out += "# section 3: subdomains: number area weight #rings, then per ring: #segments segment ids in walking order\n";
  out += "# (ring 1 is the outer boundary, counter-clockwise; the others are holes, clockwise)\n";
  append_int(out, static_cast<std::int64_t>(d.subdomains.size()));
  out += '\n';
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) append_subdomain_line(out, k, d.subdomains[k]);
  out += "# section 4: hole points per subdomain: number #holes x y ... (one point inside each hole ring)\n";
  append_int(out, static_cast<std::int64_t>(d.subdomains.size()));
  out += '\n';
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    const Subdomain& sub = d.subdomains[k];
    append_int(out, static_cast<std::int64_t>(k));
    out += ' ';
    append_int(out, static_cast<std::int64_t>(sub.hole_points.size()));
    for (const Point& h : sub.hole_points) {
      out += ' ';
      append_g17(out, h.x);
      out += ' ';
      append_g17(out, h.y);
    }
    out += '\n';
  }
  append_interior_section(out, d);
  return out;
}

}  // namespace madd
