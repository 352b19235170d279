// libFuzzer target: the ESRI shapefile reader (parse_shapefile). Any
// exception other than madd::Error, any crash or sanitizer report is a bug.
//
// One input holds the three files: byte 0 and 1 give the .shx's length S
// (little-endian), byte 2 the .prj's length P; then P bytes of .prj, S bytes
// of .shx (each cut short where the input ends) and the rest is the .shp.
// An input shorter than 3 bytes is a .shp alone. Seeds in
// fuzz/corpus/fuzz_shapefile/ were made so from the test's writer
// (tests/shapefile_test.cpp) and data/coast/lagoon.*.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "madd/error.hpp"
#include "madd/polygons.hpp"

namespace {

struct Files {
  std::string_view shp, shx, prj;
};

Files split(std::string_view in) {
  if (in.size() < 3) return {in, {}, {}};
  const std::size_t shx_size = static_cast<std::uint8_t>(in[0]) | std::size_t{static_cast<std::uint8_t>(in[1])} << 8;
  const std::size_t prj_size = static_cast<std::uint8_t>(in[2]);
  in.remove_prefix(3);
  Files f;
  f.prj = in.substr(0, prj_size);
  in.remove_prefix(f.prj.size());
  f.shx = in.substr(0, shx_size);
  in.remove_prefix(f.shx.size());
  f.shp = in;
  return f;
}

bool ring_ok(const madd::GisRing& ring, bool& in_range) {
  if (ring.points.size() < 3) return false;
  for (const madd::Point p : ring.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    in_range = in_range && p.x >= -180.0 && p.x <= 180.0 && p.y >= -90.0 && p.y <= 90.0;
  }
  return true;
}

// What the reader promises of a result: rings of 3+ finite points, records
// in file order, each record's outer rings numbered 0, 1, ..., each of its
// parts used once, and the coordinates by the .prj or the points' range.
void check(const madd::PolygonSet& set, std::string_view prj) {
  bool in_range = true;
  std::vector<std::uint32_t> sources;  // of the current record
  for (std::size_t i = 0; i < set.polygons.size(); ++i) {
    const madd::GisPolygon& p = set.polygons[i];
    const bool first = i == 0 || set.polygons[i - 1].feature != p.feature;
    if (i > 0 && set.polygons[i - 1].feature > p.feature) std::abort();
    if (p.polygon != (first ? 0 : set.polygons[i - 1].polygon + 1) || p.marker != 1) std::abort();
    if (first) sources.clear();
    if (!ring_ok(p.outer, in_range)) std::abort();
    sources.push_back(p.outer.source);
    for (const madd::GisRing& h : p.holes) {
      if (!ring_ok(h, in_range)) std::abort();
      sources.push_back(h.source);
    }
    std::vector<std::uint32_t> sorted = sources;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) std::abort();
  }
  if (prj.find_first_not_of(" \t\r\n\v\f") == std::string_view::npos &&
      (set.coordinates == madd::Coordinates::lonlat) != in_range)
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Files f = split(std::string_view(reinterpret_cast<const char*>(data), size));
  madd::PolygonSet set;
  try {
    set = madd::parse_shapefile(f.shp, f.shx, f.prj, "fuzz.shp");
  } catch (const madd::Error&) {
    return 0;
  }
  check(set, f.prj);
  // The .shx is only checked: without it, the same polygons.
  if (madd::parse_shapefile(f.shp, {}, f.prj, "fuzz.shp") != set) std::abort();
  return 0;
}
