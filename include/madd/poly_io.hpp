#pragma once
// Reading and writing Triangle's .poly and .node files (docs/formats.md).
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd {

struct PolyFile {
  Pslg pslg;
  SourceMap source;
  friend bool operator==(const PolyFile&, const PolyFile&) = default;
};

// Parses .poly text. `path` names the file in error messages and locates the
// companion .node file when the vertex count is 0. Accepts everything Triangle
// accepts (comments, 0- or 1-based ids, optional attributes, markers, regions).
// Throws ParseError ("path:line:column: message") on malformed text. Never
// allocates for a count that the remaining text cannot hold.
// Does not validate the geometry: call validate() (read_domain does both).
PolyFile parse_poly(std::string_view text, const std::string& path = "<memory>");

// Parses .node text into the points (and attributes, markers) of a Pslg.
PolyFile parse_node(std::string_view text, const std::string& path = "<memory>");

// Reads a file from disk and parses it (.poly, or .node by extension).
PolyFile read_poly_file(const std::string& path);

// read_poly_file + validate: the one entry point for untrusted input.
Pslg read_domain(const std::string& path, const ValidateOptions& options = {});

// What the values of a background mesh are (paper Sec. 5.2, case 2; a size
// file of `madd mesh --sizes`): density weights, finite and >= 0, or areas
// (required subdomain areas, largest triangle areas), finite and > 0.
enum class SampleValue { weight, area };

// A background mesh: the points of a .node file (or of a .poly, by extension,
// as read_poly_file reads it), each with its first attribute as its value. A
// file without attributes, or a value the kind cannot have, is bad input: a
// ParseError located at the file's line. The one reader of --weights,
// --areas, --sizes and the script's read_weights and read_areas.
std::vector<ValuedPoint> read_background_samples(const std::string& path, SampleValue value);

// Writes `pslg` as .poly text, each coordinate as the shortest text that reads
// back to the same double, so that parse_poly of the output gives back an equal Pslg.
std::string format_poly(const Pslg& pslg, std::string_view header_comment = {});

}  // namespace madd
