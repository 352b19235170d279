#pragma once
// One water body as a domain: its rings settled on a constrained Delaunay
// triangulation, the connected piece of water kept, and the domain rebuilt
// from that piece's boundary loops (src/gis/coast_domain.cpp says why).
#include <optional>
#include <string>

#include "gis/marked_ring.hpp"
#include "madd/coast.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// p lies in the body's water: inside its outer ring and in none of its holes.
bool holds_water(const MarkedPolygon& body, Point p);

// The valid domain of `body` (in metres): its rings as one PSLG (vertices
// shared where rings touch, crossings split), triangulated; of the pieces of
// water that meet only at points the one holding `water_at`, else the
// largest; that piece's boundary loops as the domain's segments (each with
// its edge's marker), and a hole point in every island left inside it.
// Fills the report's crossings, pinches, pockets, islands, area and
// segment counts. Throws InvalidInputError naming the nearest input vertex
// (feature, polygon, ring, vertex of `set`) when what is left is not a
// valid domain.
Pslg domain_of_body(const MarkedPolygon& body, const std::optional<Point>& water_at, const PolygonSet& set,
                    const std::string& path, CoastReport& report);

}  // namespace madd::detail
