#pragma once
// The views of a Decomposition as files (docs/formats.md, outputs 1-5). Every
// format_* function returns the whole text, so a caller can produce all its
// outputs before writing any; the write_* functions never leave partial output.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "madd/atomic_write.hpp"
#include "madd/decomposition.hpp"
#include "madd/metrics.hpp"

namespace madd {

// Output 1: the whole subdivision as one Triangle .poly (1-based ids, %.17g):
// every point, every segment (boundary and interior pieces keep their marker,
// separators 0), the original holes, and one region per subdomain at its
// interior_point with attribute = subdomain number and max area -1, so
// `triangle -pA` labels triangles. A subdomain that interior segments cut
// into several faces gets a region in each; when the decomposition has the
// input's regions, each face gets the attribute and max area of the input
// region covering it instead, and a comment naming its subdomain
// (docs/formats.md, "Interior segments in the outputs").
std::string format_decomposition_poly(const Decomposition& decomposition, std::string_view header_comment = {});

// Output 2, one file: subdomain `k` as a standalone .poly (1-based ids, its
// ring vertices and segments with their global markers, then its interior
// segments and isolated points, one hole point per hole ring, and, when the
// decomposition has the input's regions, one region per face as output 1).
// Shared points are written with the same %.17g text everywhere. With
// regions, each call triangulates the whole decomposition to find its faces;
// write_split and add_split do that once for all files.
// Throws std::out_of_range unless k < decomposition.subdomains.size().
std::string format_subdomain_poly(const Decomposition& decomposition, std::uint32_t k);

// File name of subdomain k in output 2: "<stem>-<k>.poly" with k zero-padded
// to the number of digits of count-1.
std::string split_file_name(std::string_view stem, std::uint32_t k, std::uint32_t count);

// Output 2: writes every subdomain's .poly into directory `dir` (created when
// missing). All files are staged in a temporary sibling directory first; on
// any failure nothing in `dir` changes. Files of an earlier run named
// "<stem>-<digits>.poly" that this run does not produce are removed, so the
// directory holds exactly this decomposition. Throws OutputError on I/O failure.
void write_split(const Decomposition& decomposition, const std::string& dir, std::string_view stem);
// The same, as one output of a set written all or nothing with the others.
void add_split(OutputSet& outputs, const Decomposition& decomposition, const std::string& dir, std::string_view stem);

// Output 3: the paper's subdomain file (Sec. 6): points, segments with
// markers, subdomains (number, area, weight, bounding segment ids ring by
// ring), and each subdomain's hole points; then, only when there are some, a
// fifth section with each subdomain's interior segments and isolated points.
// Layout in docs/formats.md.
std::string format_subdomain_file(const Decomposition& decomposition);

struct SvgOptions {
  double width = 1000.0;             // pixels of the longer side; the aspect ratio is kept
  bool numbers = false;              // write each subdomain's number at its interior point
  double mark_angles_below_deg = 0;  // circle every new angle below this (0 = none)
  friend bool operator==(const SvgOptions&, const SvgOptions&) = default;
};

// Throws OptionError on an option out of its range (format_svg calls it).
void check_options(const SvgOptions& options);

// Output 4: an SVG picture: one <path> per subdomain (fill-rule evenodd, so
// holes stay empty), the original boundary thick, separators thin, interior
// segments dashed and isolated points as dots, y pointing up as in the input. Size is linear in the decomposition
// (compact numbers).
std::string format_svg(const Decomposition& decomposition, const SvgOptions& options = {});

// Output 5: every figure of `m` as one JSON object (NaN figures as null).
std::string format_report_json(const Metrics& m);

}  // namespace madd
