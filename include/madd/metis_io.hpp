#pragma once
// Reading METIS graph files, the format gpmetis reads (docs/formats.md, "Graphs").
#include <string>
#include <string_view>

#include "madd/graph.hpp"

namespace madd {

// Parses METIS graph text (header "n m [fmt [ncon]]", fmt 000/001/010/011,
// '%' comments). Throws ParseError with line and column on malformed input,
// including asymmetric adjacency and self-loops. Weights are non-negative
// integers (edge weights positive); a blank vertex line is a vertex without
// neighbours; duplicate neighbours are an error. Header counts are checked
// against the remaining text before anything is allocated.
Graph parse_metis(std::string_view text, const std::string& path = "<memory>");

// Reads a METIS graph file from disk and parses it. Throws InputFileError
// when the file cannot be read.
Graph read_metis_file(const std::string& path);

}  // namespace madd
