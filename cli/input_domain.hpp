#pragma once
// A command's input domain: a Triangle .poly (or .node) as read_domain
// reads it, or the water polygons of a GeoJSON file or shapefile made a
// domain by read_coast (clipped, projected, cleaned: docs/coastal.md).
#include <cstdio>
#include <string>

#include "command_line.hpp"
#include "madd/coast.hpp"
#include "madd/pslg.hpp"

namespace madd::cli {

// The command line's CoastOptions, with the minimum island area 4 hmin^2
// when --hmin is given and --min-island-area is not (OceanMesh2D's rule).
CoastOptions coast_options(const CommandLine& line);

// `path` as a domain: for a polygon file (is_polygon_file) read_coast with
// the command line's options, its report said on `notes` (unless null);
// else read_domain(path, validation) with the identity projection.
CoastDomain read_input_domain(const std::string& path, const CommandLine& line, std::FILE* notes,
                              const ValidateOptions& validation = {});

// For a polygon file without --coast-markers: every boundary marker but the
// open marker is coast, so that the sides of the clip box (open sea) do not
// pull the size field's distance and feature-size terms fine.
void default_coast_markers(MeshSizeOptions& size, const std::string& path, const CoastDomain& coast,
                           const CommandLine& line);
// The same for a coast made from polygons in memory (the Python module's).
void default_coast_markers(MeshSizeOptions& size, const CoastDomain& coast, int open_marker);

// One line of what cleaning a coastline did, for the user.
std::string coast_report_line(const std::string& path, const CoastDomain& coast);

}  // namespace madd::cli
