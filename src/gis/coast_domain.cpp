// From water polygons to one domain (include/madd/coast.hpp;
// docs/coastal.md, "From polygons to a domain").
//
// The polygons are clipped in the file's coordinates (a box in lon/lat is a
// box there), projected, cleaned ring by ring, and sorted into water bodies;
// one body is chosen. What rings do to each other (touching at a point,
// crossing, an island pinching a bay shut) is then settled on a constrained
// Delaunay triangulation of the body: its water triangles, in pieces that
// meet only across non-segment edges, are the water as Triangle's rules read
// the rings; the piece kept is the largest (or the one holding water_at),
// and the domain is rebuilt from that piece's boundary loops. So the domain
// is connected by construction, and every ring it keeps is one the water
// really has on one side.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "kernel/coordinate_range.hpp"
#include "gis/clip_box.hpp"
#include "gis/coast_pieces.hpp"
#include "gis/ring_cleaning.hpp"
#include "madd/coast.hpp"
#include "madd/error.hpp"
#include "madd/intersections.hpp"
#include "madd/triangulation.hpp"

namespace madd {

namespace {

using detail::MarkedPolygon;
using detail::MarkedRing;
using detail::VertexOrigin;

void check_coast_options(const CoastOptions& options) {
  if (options.clip) {
    const ClipBox& b = *options.clip;
    if (!(std::isfinite(b.x0) && std::isfinite(b.y0) && std::isfinite(b.x1) && std::isfinite(b.y1)))
      throw OptionError("clip", "must be four finite numbers");
    if (!(b.x0 < b.x1 && b.y0 < b.y1)) throw OptionError("clip", "must have x0 < x1 and y0 < y1");
  }
  if (options.water_at && !(std::isfinite(options.water_at->x) && std::isfinite(options.water_at->y)))
    throw OptionError("water_at", "must be a finite point");
  if (!(options.min_island_area >= 0.0 && std::isfinite(options.min_island_area)))
    throw OptionError("min_island_area", "must be a finite area >= 0");
  if (!(options.merge_distance >= 0.0 && std::isfinite(options.merge_distance)))
    throw OptionError("merge_distance", "must be a finite length >= 0");
}

// A coordinate below 1e-40 in magnitude (sub-femtometre, in degrees or in
// metres) read as 0: the exact predicates the clipping and cleaning decide
// with hold in [1e-40, 1e70] (validate()'s range), and the readers only
// refuse what is not finite or not a longitude or latitude.
Point tame(Point p) { return {detail::flush_below_range(p.x), detail::flush_below_range(p.y)}; }

MarkedRing marked(const GisRing& ring, int marker, std::uint32_t polygon, std::uint32_t which) {
  MarkedRing out;
  for (std::size_t k = 0; k < ring.points.size(); ++k)
    out.push(tame(ring.points[k]), marker, {polygon, which, static_cast<std::uint32_t>(k)});
  return out;
}

std::vector<MarkedPolygon> marked_polygons(const PolygonSet& set, CoastReport& report) {
  std::vector<MarkedPolygon> out;
  for (std::size_t p = 0; p < set.polygons.size(); ++p) {
    const GisPolygon& g = set.polygons[p];
    const auto id = static_cast<std::uint32_t>(p);
    MarkedPolygon m{marked(g.outer, g.marker, id, 0), {}};
    for (std::size_t h = 0; h < g.holes.size(); ++h)
      m.holes.push_back(marked(g.holes[h], g.marker, id, static_cast<std::uint32_t>(h + 1)));
    report.rings_read += 1 + g.holes.size();
    report.vertices_read += g.outer.points.size();
    for (const GisRing& h : g.holes) report.vertices_read += h.points.size();
    detail::orient_for_water(m);
    out.push_back(std::move(m));
  }
  report.polygons_read = set.polygons.size();
  return out;
}

template <typename F>
void for_each_ring(std::vector<MarkedPolygon>& bodies, F f) {
  for (MarkedPolygon& body : bodies) {
    f(body.outer);
    for (MarkedRing& hole : body.holes) f(hole);
  }
}

// The projection's centre: the clip box's, else that of the water's extent.
Projection projection_for(const PolygonSet& set, const CoastOptions& options, std::vector<MarkedPolygon>& bodies) {
  Projection projection;
  projection.geographic = set.coordinates == Coordinates::lonlat;
  if (!projection.geographic) return projection;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  if (options.clip) {
    x0 = options.clip->x0, x1 = options.clip->x1, y0 = options.clip->y0, y1 = options.clip->y1;
  } else {
    for_each_ring(bodies, [&](MarkedRing& ring) {
      for (Point p : ring.points)
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    });
  }
  if (x0 <= x1) projection.lon0_deg = 0.5 * (x0 + x1), projection.lat0_deg = 0.5 * (y0 + y1);
  return projection;
}

double extent_of(std::vector<MarkedPolygon>& bodies) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for_each_ring(bodies, [&](MarkedRing& ring) {
    for (Point p : ring.points)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  });
  return x0 <= x1 ? std::max(x1 - x0, y1 - y0) : 0.0;
}

// Cleans every ring; drops rings left without area, and bodies whose outer ring went.
void clean_bodies(std::vector<MarkedPolygon>& bodies, double merge_distance, CoastReport& report) {
  const auto clean = [&](MarkedRing& ring) {
    const detail::RingCleaning done = detail::clean_ring(ring, merge_distance);
    report.vertices_merged += done.merged, report.spikes_removed += done.spikes;
    const bool collapsed = detail::flat(ring);
    report.rings_collapsed += collapsed ? 1 : 0;
    return collapsed;
  };
  std::vector<MarkedPolygon> kept;
  for (MarkedPolygon& body : bodies) {
    if (clean(body.outer)) {
      report.rings_collapsed += body.holes.size();
      continue;
    }
    std::erase_if(body.holes, clean);
    kept.push_back(std::move(body));
  }
  bodies = std::move(kept);
}

double net_area(const MarkedPolygon& body) {
  double area = detail::signed_area_of(body.outer);
  for (const MarkedRing& hole : body.holes) area += detail::signed_area_of(hole);
  return area;
}

// Islands and bodies below min_island_area go.
void drop_small(std::vector<MarkedPolygon>& bodies, double min_area, CoastReport& report) {
  if (min_area <= 0.0) return;
  for (MarkedPolygon& body : bodies)
    report.small_islands_removed +=
        std::erase_if(body.holes, [&](const MarkedRing& hole) { return -detail::signed_area_of(hole) < min_area; });
  report.bodies_dropped += std::erase_if(bodies, [&](const MarkedPolygon& body) { return net_area(body) < min_area; });
}

std::size_t chosen_body(const std::vector<MarkedPolygon>& bodies, const std::optional<Point>& water_at) {
  std::size_t best = 0;
  for (std::size_t b = 1; b < bodies.size(); ++b)
    if (net_area(bodies[b]) > net_area(bodies[best])) best = b;
  if (!water_at) return best;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (detail::holds_water(bodies[b], *water_at)) return b;
  throw OptionError("water_at", "must lie in the water of a body that is kept (not on land, not in a removed piece)");
}

}  // namespace

CoastDomain coast_domain(const PolygonSet& set, const CoastOptions& options, const std::string& path) {
  check_coast_options(options);
  CoastDomain result;
  CoastReport& report = result.report;
  std::vector<MarkedPolygon> bodies = marked_polygons(set, report);
  if (options.clip) {
    const ClipBox box = detail::box_off_vertices(bodies, *options.clip);
    bodies = detail::clip_to_box(bodies, box, options.open_marker);
  }
  // Spikes and duplicates as the file has them first: the projection's
  // rounding would turn a spike whose return lies on its way out (exactly,
  // in degrees) into a needle that no exact test calls a spike.
  clean_bodies(bodies, 0.0, report);
  result.projection = projection_for(set, options, bodies);
  for_each_ring(bodies, [&](MarkedRing& ring) {
    for (Point& p : ring.points) p = tame(result.projection.to_metres(p));
  });
  const double merge = options.merge_distance > 0.0 ? options.merge_distance : 1e-9 * extent_of(bodies);
  clean_bodies(bodies, merge, report);
  report.bodies = bodies.size();
  drop_small(bodies, options.min_island_area, report);
  if (bodies.empty())
    throw InvalidInputError(InputProblem::empty_domain,
                            (path.empty() ? std::string() : path + ": ") +
                                (options.clip ? "no water inside the clip box" : "no water polygon") +
                                (options.min_island_area > 0.0 ? " of at least the minimum island area" : ""));
  std::optional<Point> water_at;
  if (options.water_at) water_at = result.projection.to_metres(*options.water_at);
  const std::size_t chosen = chosen_body(bodies, water_at);
  report.bodies_dropped += bodies.size() - 1;
  result.domain = detail::domain_of_body(bodies[chosen], water_at, set, path, report);
  for (const Segment& s : result.domain.segments)
    ++(s.marker == options.open_marker ? report.open_segments : report.land_segments);
  return result;
}

CoastDomain read_coast(const std::string& path, const CoastOptions& options) {
  return coast_domain(read_polygons(path), options, path);
}

}  // namespace madd
