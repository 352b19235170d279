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

// Writes text to `path` through a temporary file and a rename, so that a
// failure never leaves a partial file. Throws Error on I/O failure.
void write_file_atomically(const std::string& path, std::string_view contents);

// Async-signal-safe, for a SIGINT/SIGTERM handler: from now on every
// write_file_atomically removes its temporary file and throws OutputError
// instead of finishing. Returns true when such a write is in progress (the
// handler should then return and let it unwind rather than exit at once).
bool interrupt_output_writes() noexcept;

} // namespace madd
