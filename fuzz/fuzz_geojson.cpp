// libFuzzer target: the GeoJSON reader. Any exception other than madd::Error,
// any crash or sanitizer report is a bug; so is a result that breaks what
// parse_geojson promises (open rings of 3 or more vertices, coordinates
// within lon/lat ranges, ring sources in order) or that does not survive a
// write/read round trip unchanged.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "madd/error.hpp"
#include "madd/polygons.hpp"

namespace {

void append_number(std::string& out, double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, result.ptr);
}

void check_ring(const madd::GisRing& ring, std::uint32_t source) {
  if (ring.points.size() < 3 || ring.source != source) std::abort();
  for (const madd::Point& p : ring.points)
    if (!(std::abs(p.x) <= 180.0 && std::abs(p.y) <= 90.0)) std::abort();
}

void append_ring(std::string& out, const madd::GisRing& ring) {
  out += '[';
  for (std::size_t k = 0; k <= ring.points.size(); ++k) {
    const madd::Point p = ring.points[k % ring.points.size()];
    out += k ? ",[" : "[";
    append_number(out, p.x);
    out += ',';
    append_number(out, p.y);
    out += ']';
  }
  out += ']';
}

// The set as a FeatureCollection that reads back the same: feature k at
// index k (null geometries fill the gaps), polygon p at index p of a
// MultiPolygon (empty polygons fill the gaps).
std::string format(const madd::PolygonSet& set) {
  std::string out = R"({"type":"FeatureCollection","features":[)";
  std::size_t i = 0;
  for (std::uint32_t feature = 0; i < set.polygons.size(); ++feature) {
    if (feature) out += ',';
    if (set.polygons[i].feature != feature) {
      if (set.polygons[i].feature < feature) std::abort();  // features must come in order
      out += R"({"type":"Feature","properties":null,"geometry":null})";
      continue;
    }
    out += R"({"type":"Feature","properties":{"marker":)" + std::to_string(set.polygons[i].marker) +
           R"(},"geometry":{"type":"MultiPolygon","coordinates":[)";
    for (std::uint32_t polygon = 0; i < set.polygons.size() && set.polygons[i].feature == feature; ++polygon) {
      if (polygon) out += ',';
      const madd::GisPolygon& p = set.polygons[i];
      if (p.polygon < polygon) std::abort();  // polygons of a feature must come in order
      out += '[';
      if (p.polygon == polygon) {
        append_ring(out, p.outer);
        for (const madd::GisRing& hole : p.holes) {
          out += ',';
          append_ring(out, hole);
        }
        ++i;
      }
      out += ']';
    }
    out += "]}}";
  }
  return out + "]}";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  madd::PolygonSet set;
  try {
    set = madd::parse_geojson(text, "fuzz.geojson");
  } catch (const madd::Error&) {
    return 0;
  }
  if (set.coordinates != madd::Coordinates::lonlat) std::abort();
  for (const madd::GisPolygon& p : set.polygons) {
    check_ring(p.outer, 0);
    for (std::size_t h = 0; h < p.holes.size(); ++h) check_ring(p.holes[h], static_cast<std::uint32_t>(h + 1));
  }
  if (madd::parse_geojson(format(set), "roundtrip.geojson") != set) std::abort();
  return 0;
}
