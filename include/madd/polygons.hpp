#pragma once
// Water polygons as GIS users have them (docs/coastal.md): GeoJSON (RFC 7946)
// and ESRI shapefiles, read strictly into one value, in the file's own
// coordinates (longitude/latitude in degrees, or projected metres). What a
// coastline becomes as a domain (clipped, projected, cleaned) is
// madd/coast.hpp's business; these readers only parse.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "madd/geometry.hpp"

namespace madd {

// One ring as read: open (the file's closing vertex, equal to the first, is
// dropped), in the file's order and direction, at least 3 vertices. Nothing
// else is cleaned: consecutive duplicates, spikes and touching rings are
// kept as the file has them, for madd/coast.hpp to clean and report.
struct GisRing {
  std::vector<Point> points;  // x = longitude (or easting), y = latitude (or northing)
  std::uint32_t source = 0;   // the ring's 0-based index in its polygon (GeoJSON) or record part (shapefile)
  friend bool operator==(const GisRing&, const GisRing&) = default;
};

// One polygon: an outer ring and its holes (islands of a water polygon).
struct GisPolygon {
  GisRing outer;
  std::vector<GisRing> holes;
  int marker = 1;             // the feature's integer property "marker" (GeoJSON), else 1
  std::uint32_t feature = 0;  // 0-based feature (GeoJSON) or record (shapefile) index in the file
  std::uint32_t polygon = 0;  // 0-based polygon index within a MultiPolygon feature (0 for a Polygon);
                              // within a shapefile record, the index of this outer ring among its outers
  friend bool operator==(const GisPolygon&, const GisPolygon&) = default;
};

enum class Coordinates : std::uint8_t {
  lonlat,     // WGS84 longitude and latitude in degrees (GeoJSON always; a shapefile whose .prj is a GEOGCS)
  projected,  // metres of some projection (a shapefile whose .prj is a PROJCS)
};

// Every polygon of a file, in file order.
struct PolygonSet {
  std::vector<GisPolygon> polygons;
  Coordinates coordinates = Coordinates::lonlat;
  friend bool operator==(const PolygonSet&, const PolygonSet&) = default;
};

// Parses GeoJSON text (RFC 7946): a FeatureCollection, a Feature or a bare
// geometry, of Polygon and MultiPolygon geometries (a GeometryCollection's
// polygons too); other geometry types (points, lines) are skipped, and a
// feature with a null geometry is skipped, as is a polygon with no rings.
// Coordinates are longitude, latitude (a third value, the altitude, is read
// and dropped; a fourth is refused). Rings must be closed (last position
// equal to the first) with at least 4 positions; every coordinate finite,
// longitude within [-180, 180] and latitude within [-90, 90] (after RFC 7946
// a larger value is a projected file mislabelled: refused). A feature's
// "marker" property must be an integer in the range of int (3 and 3.0 alike)
// or null (as absent); "bbox", "id" and foreign members are ignored. The
// members of a bare GeometryCollection count as features (GisPolygon::feature
// is the member's index), and within a feature, polygons count on through a
// GeometryCollection's members (GisPolygon::polygon).
// Errors: malformed JSON anywhere in the text (RFC 8259 strictly, and
// member names repeated in an object) is a ParseError "path:line:column:
// message", even when the text also has a GeoJSON problem before it;
// well-formed JSON that is not such GeoJSON is an InvalidInputError whose
// message is "path: feature K, polygon P, ring R, vertex V: message (line L,
// column C)": the arrays on the way down to the problem, those that are
// there, 0-based as in the file ("geometry G" for a GeometryCollection's
// member, no "polygon" for a Polygon, no "feature" for a bare geometry),
// and where the offending value starts (columns in bytes). Never allocates
// for a size the text cannot hold; nesting deeper than 64 is refused.
PolygonSet parse_geojson(std::string_view text, const std::string& path = "<memory>");

// Parses an ESRI shapefile's polygons from the bytes of its .shp, its .shx
// (may be empty: then not checked) and its .prj text (may be empty: no .prj).
// Shape types Polygon (5), PolygonZ (15) and PolygonM (25) (Z and M values
// dropped), and Null shapes (skipped); any other type is refused. The framing
// is checked exactly (the header's file length is the file's size, records
// numbered from 1, each content the size its counts give, part starts
// increasing from 0; the .shx agrees entry for entry). A record's parts are
// rings: closed, at least 4 points, every coordinate 0 or of magnitude within
// [1e-40, 1e70] (madd's supported range). Which are outer rings and which
// holes is decided by nesting (a ring inside an odd number of the record's
// other rings is a hole, of the smallest ring holding it), not by direction,
// since real files get the direction wrong. Coordinates: projected when the
// .prj is a PROJCS, lon/lat when it is a GEOGCS (WKT 2's PROJCRS and GEOGCRS
// too), and without a .prj lon/lat when every coordinate lies within
// [-180, 180] x [-90, 90], else projected; any other .prj is refused.
// Errors: InvalidInputError "path: byte B: message" for the file's framing,
// "path: record K, part R, vertex V: message" for a record's geometry (K the
// record's 0-based index, so the record numbered K + 1; R and V 0-based in
// the record and the part), "path: .shx byte B: message" for the index and
// "path: .prj: message". Never allocates for a count the bytes cannot hold.
PolygonSet parse_shapefile(std::string_view shp, std::string_view shx, std::string_view prj,
                           const std::string& path = "<memory>");

// True when `path` names a polygon file by its extension: .geojson, .json
// (GeoJSON) or .shp (shapefile), case-insensitively.
bool is_polygon_file(const std::string& path);

// Reads a polygon file from disk by its extension: .geojson or .json, or
// .shp with the .shx and .prj beside it (same stem; a missing .shx or .prj is
// allowed, as parse_shapefile says). Throws InputFileError when it cannot be
// read, and what the parsers throw.
PolygonSet read_polygons(const std::string& path);

}  // namespace madd
