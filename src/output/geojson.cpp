// The GeoJSON view of a decomposition (include/madd/output_formats.hpp).
// RFC 7946 Sec. 3.1.6: a Polygon is an array of closed linear rings, the
// exterior counter-clockwise and holes clockwise, which is exactly the order
// and orientation of Subdomain::rings; only the closing position is added.
#include <charconv>
#include <cstdint>
#include <string>

#include "madd/output_formats.hpp"
#include "kernel/number_format.hpp"

namespace madd {
namespace {

void append_position(std::string& out, Point p) {
  out += '[';
  detail::append_shortest(out, p.x);
  out += ',';
  detail::append_shortest(out, p.y);
  out += ']';
}

void append_polygon(std::string& out, const Decomposition& d, const Subdomain& s) {
  out += "\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[";
  for (std::size_t r = 0; r < s.rings.size(); ++r) {
    if (r > 0) out += ',';
    out += '[';
    for (const std::uint32_t v : s.rings[r]) {
      append_position(out, d.points[v]);
      out += ',';
    }
    append_position(out, d.points[s.rings[r].front()]);  // closes the ring
    out += ']';
  }
  out += "]}";
}

// The interior constraints after the polygons, so feature k is still
// subdomain k: one LineString per interior piece (its id in output 1, its
// marker, its subdomain), one Point per isolated point (its id in output 1).
void append_interior_features(std::string& out, const Decomposition& d) {
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    const Subdomain& s = d.subdomains[k];
    for (const std::uint32_t j : s.interior_segments) {
      out += ",\n{\"type\":\"Feature\",\"properties\":{\"subdomain\":";
      detail::append_int(out, static_cast<std::int64_t>(k));
      out += ",\"segment\":";
      detail::append_int(out, std::int64_t{j} + 1);
      out += ",\"marker\":";
      detail::append_int(out, d.segments[j].marker);
      out += "},\"geometry\":{\"type\":\"LineString\",\"coordinates\":[";
      append_position(out, d.points[d.segments[j].a]);
      out += ',';
      append_position(out, d.points[d.segments[j].b]);
      out += "]}}";
    }
    for (const std::uint32_t p : s.interior_points) {
      out += ",\n{\"type\":\"Feature\",\"properties\":{\"subdomain\":";
      detail::append_int(out, static_cast<std::int64_t>(k));
      out += ",\"point\":";
      detail::append_int(out, std::int64_t{p} + 1);
      out += "},\"geometry\":{\"type\":\"Point\",\"coordinates\":";
      append_position(out, d.points[p]);
      out += "}}";
    }
  }
}

}  // namespace

std::string format_geojson(const Decomposition& decomposition) {
  std::string out = "{\"type\":\"FeatureCollection\",\"features\":[";
  for (std::size_t k = 0; k < decomposition.subdomains.size(); ++k) {
    const Subdomain& s = decomposition.subdomains[k];
    out += k == 0 ? "\n" : ",\n";
    out += "{\"type\":\"Feature\",\"properties\":{\"id\":";
    detail::append_int(out, static_cast<std::int64_t>(k));
    out += ",\"area\":";
    detail::append_shortest(out, s.area);
    out += ",\"weight\":";
    detail::append_shortest(out, s.weight);
    out += "},";
    append_polygon(out, decomposition, s);
    out += '}';
  }
  append_interior_features(out, decomposition);
  out += "\n]}\n";
  return out;
}

}  // namespace madd
