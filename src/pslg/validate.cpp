// validate() and domain_area(): the semantic checks of docs/formats.md, "Bad input".
// Checks run from the most local to the most global, so that each error names
// the real cause: vertices, then segments, then intersections (exact, on a
// grid), then the regions left after flooding from the outside and the holes.
#include <charconv>
#include <cmath>
#include <cstring>

#include "kernel/coordinate_range.hpp"
#include "pslg/validate_detail.hpp"
#include "madd/error.hpp"

namespace madd {
namespace {

using detail::Contact;

std::string number(double v) {
  char buf[40];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  (void)ec;
  return std::string(buf, ptr);
}
std::string at(Point p) {
  std::string s(1, '(');
  s += number(p.x);
  s += ", ";
  s += number(p.y);
  s += ')';
  return s;
}

// Builds every InvalidInputError: ids in the file's base, line from the SourceMap.
class Reporter {
public:
  Reporter(const Pslg& p, const SourceMap& s) : p_(p), s_(s) {}
  std::int64_t id(std::size_t index) const { return static_cast<std::int64_t>(index) + p_.first_index; }
  std::string vertex(std::uint32_t v) const { return "vertex " + std::to_string(id(v)) + " " + at(p_.points[v]); }
  std::string segment(std::uint32_t s) const {
    return "segment " + std::to_string(id(s)) + " (vertices " + std::to_string(id(p_.segments[s].a)) + "-" +
           std::to_string(id(p_.segments[s].b)) + ")";
  }
  std::string hole(std::uint32_t h) const { return "hole " + std::to_string(id(h)) + " " + at(p_.holes[h]); }
  std::string region(std::uint32_t r) const { return "region " + std::to_string(id(r)) + " " + at(p_.regions[r].at); }

  enum class Item { point, segment, hole, region };
  [[noreturn]] void fail(InputProblem problem, const std::string& message, std::vector<std::int64_t> ids,
                         std::vector<Point> points, Item item, std::uint32_t index) const {
    const std::vector<std::uint32_t>& lines = item == Item::point     ? s_.point_lines
                                              : item == Item::segment ? s_.segment_lines
                                              : item == Item::hole    ? s_.hole_lines
                                                                      : s_.region_lines;
    const std::string& path = item == Item::point && !s_.point_path.empty() ? s_.point_path : s_.path;
    const std::size_t line = index < lines.size() ? lines[index] : 0;
    throw InvalidInputError(problem, message, std::move(ids), std::move(points), path, line, line ? 1 : 0);
  }

private:
  const Pslg& p_;
  const SourceMap& s_;
};
using Item = Reporter::Item;

// The exact predicates' range (kernel/coordinate_range.hpp).
bool supported(Point q) noexcept { return detail::in_exact_range(q.x) && detail::in_exact_range(q.y); }
const char* const range_note =
    " is outside the supported range: every coordinate must be 0 or of magnitude within [1e-40, 1e70]";

void check_values(const Pslg& p, const Reporter& r, const ValidateOptions& options) {
  for (std::uint32_t v = 0; v < p.points.size(); ++v)
    if (!supported(p.points[v]))
      r.fail(InputProblem::other, r.vertex(v) + range_note, {r.id(v)}, {p.points[v]}, Item::point, v);
  for (std::uint32_t h = 0; h < p.holes.size(); ++h)
    if (!supported(p.holes[h]))
      r.fail(InputProblem::other, r.hole(h) + range_note, {r.id(h)}, {p.holes[h]}, Item::hole, h);
  for (std::uint32_t k = 0; k < p.regions.size(); ++k)
    if (!supported(p.regions[k].at))
      r.fail(InputProblem::other, r.region(k) + range_note, {r.id(k)}, {p.regions[k].at}, Item::region, k);
  for (std::uint32_t s = 0; s < p.segments.size(); ++s)
    if (p.segments[s].a >= p.points.size() || p.segments[s].b >= p.points.size())
      r.fail(InputProblem::other, "segment " + std::to_string(r.id(s)) + " refers to a missing vertex", {r.id(s)}, {},
             Item::segment, s);
  if (!options.check_weights || p.attributes_per_point == 0) return;
  for (std::uint32_t v = 0; v < p.points.size(); ++v) {
    const double w = p.attribute(v, 0);
    if (!std::isfinite(w) || w < 0.0)
      r.fail(InputProblem::bad_weight,
             r.vertex(v) + " has boundary weight " + number(w) +
                 "; weights must be finite and >= 0 when grading by weight",
             {r.id(v)}, {p.points[v]}, Item::point, v);
  }
}

std::uint64_t mix(std::uint64_t x) noexcept {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}
std::uint64_t bits(double v) noexcept {
  v += 0.0;  // -0.0 becomes +0.0: they are the same point
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// Open-addressing hash on exact coordinates: O(n), and the reported pair is
// the first vertex (in file order) that repeats an earlier one.
void check_duplicates(const Pslg& p, const Reporter& r) {
  std::size_t size = 16;
  while (size < 2 * p.points.size()) size *= 2;
  std::vector<std::uint32_t> table(size, no_index);
  for (std::uint32_t v = 0; v < p.points.size(); ++v) {
    const Point q = p.points[v];
    std::size_t slot = mix(bits(q.x) ^ mix(bits(q.y))) & (size - 1);
    while (table[slot] != no_index) {
      const Point o = p.points[table[slot]];
      if (o.x == q.x && o.y == q.y)
        r.fail(InputProblem::duplicate_vertex,
               "vertex " + std::to_string(r.id(v)) + " repeats the coordinates of " + r.vertex(table[slot]),
               {r.id(v), r.id(table[slot])}, {q}, Item::point, v);
      slot = (slot + 1) & (size - 1);
    }
    table[slot] = v;
  }
}

void check_zero_length(const Pslg& p, const Reporter& r) {
  for (std::uint32_t s = 0; s < p.segments.size(); ++s) {
    const Segment& seg = p.segments[s];
    if (seg.a == seg.b)
      r.fail(InputProblem::zero_length_segment, r.segment(s) + " has zero length", {r.id(s)}, {p.points[seg.a]},
             Item::segment, s);
  }
}

std::vector<std::uint32_t> vertex_degrees(const Pslg& p) {
  std::vector<std::uint32_t> degree(p.points.size(), 0);
  for (const Segment& seg : p.segments) {
    ++degree[seg.a];
    ++degree[seg.b];
  }
  return degree;
}

void check_intersections(const Pslg& p, const detail::SegmentGrid& grid, const Reporter& r) {
  const auto conflict = detail::find_segment_conflict(p, grid);
  if (!conflict) return;
  const char* verb = conflict->contact.kind == Contact::cross   ? " crosses "
                     : conflict->contact.kind == Contact::touch ? " touches "
                                                                : " overlaps ";
  r.fail(InputProblem::segments_intersect,
         r.segment(conflict->later) + verb + r.segment(conflict->earlier) + " at " + at(conflict->contact.at),
         {r.id(conflict->later), r.id(conflict->earlier)}, {conflict->contact.at}, Item::segment, conflict->later);
}

void check_holes_on_segments(const Pslg& p, const detail::SegmentGrid& grid, const Reporter& r) {
  for (std::uint32_t h = 0; h < p.holes.size(); ++h) {
    if (const auto s = detail::segment_under(p, grid, p.holes[h]))
      r.fail(InputProblem::hole_on_segment, r.hole(h) + " lies on " + r.segment(*s), {r.id(h), r.id(*s)}, {p.holes[h]},
             Item::hole, h);
  }
}

// A piece with the domain on neither side: a boundary left open (a vertex
// of odd degree on it), a stray segment outside, or a ring whose both sides
// the hole points remove.
[[noreturn]] void fail_outside_piece(const Pslg& p, const detail::DomainPieces& dp, std::uint32_t k,
                                     const std::vector<std::uint32_t>& degree,
                                     const std::vector<std::uint32_t>& hole_of_face, const Reporter& r) {
  const std::uint32_t s = dp.resolved.source_segment[k];
  // A loose end first (degree 1), then a fork (odd degree).
  std::uint32_t ends[2] = {p.segments[s].a, p.segments[s].b};
  if (degree[ends[1]] < degree[ends[0]]) std::swap(ends[0], ends[1]);
  for (const std::uint32_t v : ends)
    if (degree[v] % 2 != 0)
      r.fail(InputProblem::open_boundary,
             r.vertex(v) + " is an endpoint of " + std::to_string(degree[v]) +
                 " segment(s), an odd number, with the domain on neither side: the boundary is not closed there",
             {r.id(v)}, {p.points[v]}, Item::point, v);
  const std::uint32_t f = dp.faces.face_of_half_edge(2 * k), g = dp.faces.face_of_half_edge(2 * k + 1);
  const std::uint32_t other = f == no_index ? g : f;
  if ((f == no_index || g == no_index) && other != no_index && hole_of_face[other] != no_index) {
    const std::uint32_t h = hole_of_face[other];
    r.fail(InputProblem::hole_outside_domain,
           r.hole(h) + " lies outside the domain, in the region bounded by " + r.segment(s), {r.id(h), r.id(s)},
           {p.holes[h]}, Item::hole, h);
  }
  r.fail(InputProblem::interior_segment,
         r.segment(s) + " does not bound the domain: the regions on both sides of it are removed", {r.id(s)},
         {p.points[p.segments[s].a]}, Item::segment, s);
}

// The kept faces joined across the pieces that have the domain on both
// sides must be one: the domain is connected (docs/formats.md, "The domain").
void check_connected(const Pslg& p, const detail::DomainPieces& dp, const Reporter& r) {
  const std::uint32_t faces = dp.faces.ring_count();
  std::vector<std::uint32_t> parent(faces);
  for (std::uint32_t f = 0; f < faces; ++f) parent[f] = f;
  const auto root = [&](std::uint32_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  const auto pieces = static_cast<std::uint32_t>(dp.resolved.pslg.segments.size());
  for (std::uint32_t k = 0; k < pieces; ++k) {
    if (dp.domain_sides(k) != 3U) continue;
    const std::uint32_t a = root(dp.faces.face_of_half_edge(2 * k)), b = root(dp.faces.face_of_half_edge(2 * k + 1));
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  std::vector<std::uint32_t> first_piece(faces, no_index);  // per part: the first piece bounding it
  std::vector<std::uint32_t> parts;
  for (std::uint32_t k = 0; k < pieces; ++k) {
    for (const std::uint32_t h : {2 * k, 2 * k + 1}) {
      const std::uint32_t f = dp.faces.face_of_half_edge(h);
      if (!dp.is_kept(f) || first_piece[root(f)] != no_index) continue;
      first_piece[root(f)] = k;
      parts.push_back(dp.resolved.source_segment[k]);
    }
  }
  if (parts.size() > 1)
    r.fail(InputProblem::disconnected_domain,
           "the domain has " + std::to_string(parts.size()) + " disconnected parts: " + r.segment(parts[1]) +
               " bounds one, " + r.segment(parts[0]) + " another",
           {r.id(parts[1]), r.id(parts[0])}, {p.points[p.segments[parts[1]].a], p.points[p.segments[parts[0]].a]},
           Item::segment, parts[1]);
}

// The domain is what Triangle keeps after flooding from the outside and from
// every hole point: the bounded faces of the segment graph holding no hole
// point. Every segment must have it on at least one side (on both: an
// interior segment), it must be connected across the interior segments, and
// every isolated vertex must lie in it (docs/formats.md, "The domain").
void check_regions(const Pslg& p, const detail::DomainPieces& dp, const std::vector<std::uint32_t>& degree,
                   const Reporter& r) {
  const detail::FaceMap& fm = dp.faces;
  std::vector<std::uint32_t> hole_of_face(fm.ring_count(), no_index);
  for (std::uint32_t h = 0; h < dp.real_holes; ++h) {
    const std::uint32_t f = fm.hole_face[h];
    if (f == no_index)
      r.fail(InputProblem::hole_outside_domain, r.hole(h) + " lies outside every boundary", {r.id(h)}, {p.holes[h]},
             Item::hole, h);
    if (hole_of_face[f] == no_index) hole_of_face[f] = h;
  }
  const auto pieces = static_cast<std::uint32_t>(dp.resolved.pslg.segments.size());
  bool any_kept = false;
  for (std::uint32_t k = 0; k < pieces && !any_kept; ++k) any_kept = dp.domain_sides(k) != 0U;
  if (!any_kept) {
    for (std::uint32_t v = 0; v < p.points.size(); ++v)
      if (degree[v] % 2 != 0)
        r.fail(InputProblem::open_boundary,
               r.vertex(v) + " is an endpoint of " + std::to_string(degree[v]) +
                   " segment(s), an odd number: the boundary is not closed there",
               {r.id(v)}, {p.points[v]}, Item::point, v);
    std::uint32_t h = 0;
    while (h + 1 < dp.real_holes && hole_of_face[fm.hole_face[h]] != h) ++h;
    if (dp.real_holes == 0)
      r.fail(InputProblem::empty_domain, "the segments enclose no region", {}, {}, Item::segment, 0);
    r.fail(InputProblem::empty_domain,
           "the hole points remove every region bounded by the segments; " + r.hole(h) + " removes one of them",
           {r.id(h)}, {p.holes[h]}, Item::hole, h);
  }
  check_connected(p, dp, r);
  for (std::uint32_t k = 0; k < pieces; ++k)
    if (dp.domain_sides(k) == 0U) fail_outside_piece(p, dp, k, degree, hole_of_face, r);
  for (std::size_t i = 0; i < dp.isolated.size(); ++i) {
    const std::uint32_t v = dp.isolated[i];
    if (!dp.is_kept(dp.isolated_face(i)))
      r.fail(InputProblem::isolated_vertex,
             r.vertex(v) + " is on no segment and lies outside the domain (madd triangulate takes it)", {r.id(v)},
             {p.points[v]}, Item::point, v);
  }
}

// Crossings and overlaps, the first in file order; a vertex lying inside a
// segment (a touch) is allowed: triangulate() splits the segment there.
void check_pslg_intersections(const Pslg& p, const detail::SegmentGrid& grid, const Reporter& r) {
  const auto conflict = detail::find_segment_conflict(p, grid, false);
  if (!conflict) return;
  const char* verb = conflict->contact.kind == Contact::cross ? " crosses " : " overlaps ";
  r.fail(InputProblem::segments_intersect,
         r.segment(conflict->later) + verb + r.segment(conflict->earlier) + " at " + at(conflict->contact.at) +
             " (madd triangulate --resolve-crossings inserts the intersection vertices)",
         {r.id(conflict->later), r.id(conflict->earlier)}, {conflict->contact.at}, Item::segment, conflict->later);
}

}  // namespace

void validate_pslg(const Pslg& pslg, const SourceMap& source, const ValidatePslgOptions& options) {
  const Reporter r(pslg, source);
  check_values(pslg, r, {});
  check_duplicates(pslg, r);
  check_zero_length(pslg, r);
  if (pslg.segments.empty()) {
    if (!pslg.holes.empty())
      r.fail(InputProblem::empty_domain, r.hole(0) + " would remove every triangle: there are no segments to stop it",
             {r.id(0)}, {pslg.holes[0]}, Item::hole, 0);
    return;
  }
  const detail::SegmentGrid grid(pslg.points, pslg.segments);
  if (!options.allow_intersections) check_pslg_intersections(pslg, grid, r);
  check_holes_on_segments(pslg, grid, r);
}

void validate(const Pslg& pslg, const SourceMap& source, const ValidateOptions& options) {
  const Reporter r(pslg, source);
  check_values(pslg, r, options);
  if (pslg.segments.empty() && pslg.holes.empty() && options.allow_point_set) {
    check_duplicates(pslg, r);
    return;
  }
  if (pslg.segments.empty())
    throw InvalidInputError(InputProblem::empty_domain, "there are no segments, so there is no domain", {}, {},
                            source.path, 0, 0);
  check_duplicates(pslg, r);
  check_zero_length(pslg, r);
  const detail::SegmentGrid grid(pslg.points, pslg.segments);
  // Crossings and overlaps are errors; a vertex inside a segment splits it,
  // whether it ends another segment or is on none.
  const auto conflict = detail::find_segment_conflict(pslg, grid, true);
  const bool touches = conflict ? conflict->contact.kind == Contact::touch : detail::lone_vertex_on_segment(pslg, grid);
  if (conflict && !touches) check_intersections(pslg, grid, r);
  if (touches) check_pslg_intersections(pslg, grid, r);
  check_holes_on_segments(pslg, grid, r);
  check_regions(pslg, detail::trace_domain_pieces(pslg, touches), vertex_degrees(pslg), r);
}

double domain_area(const Pslg& pslg) {
  if (pslg.segments.empty()) return 0.0;
  const detail::DomainPieces dp = detail::trace_domain_pieces(pslg, detail::has_vertex_inside_segment(pslg));
  double area = 0.0;
  for (std::uint32_t ring = 0; ring < dp.faces.ring_count(); ++ring) {
    if (dp.is_kept(dp.faces.face_of_ring[ring])) area += dp.faces.ring_area[ring];
  }
  return area;
}

}  // namespace madd
