#pragma once
// Reading and writing Triangle's .poly and .node files (docs/formats.md).
#include <iosfwd>
#include <string>
#include <string_view>

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

// Writes `pslg` as .poly text, each coordinate as the shortest text that reads
// back to the same double, so that parse_poly of the output gives back an equal Pslg.
std::string format_poly(const Pslg& pslg, std::string_view header_comment = {});

} // namespace madd
