// resolve_intersections(): splits segments where they cross, touch or
// overlap, in passes over the exact contact search of validate()
// (pslg/validate_detail.hpp), until the pieces meet only at shared endpoints.
//
// One pass: every pair in contact gives split points. A vertex lying on a
// segment (a touch, or the end of an overlap) splits it at that vertex,
// exactly. A proper crossing gives a new vertex at the computed intersection,
// which lies on neither segment exactly; the pieces bend there by a rounding
// error, which can make them touch or cross something else, so the next pass
// looks again. Several segments crossing at one point would each compute
// a slightly different point: a crossing point within a few ulps of one
// already on either segment reuses it, so they share one vertex.
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include "kernel/coordinate_range.hpp"
#include "kernel/containment.hpp"
#include "kernel/segment_grid.hpp"
#include "madd/error.hpp"
#include "madd/intersections.hpp"
#include "pslg/validate_detail.hpp"

namespace madd {
namespace {

using detail::Contact;
using detail::SegmentConflict;

constexpr std::size_t max_contacts = std::size_t{1} << 20;  // about 60 MB of contacts at most
constexpr int max_passes = 32;

// The vertices splitting one segment, and where along it (for sorting).
struct SplitList {
  std::vector<std::uint32_t> vertices;
};

class Resolver {
public:
  explicit Resolver(const Pslg& input) : p_(input) {
    source_.resize(p_.segments.size());
    for (std::uint32_t s = 0; s < source_.size(); ++s) source_[s] = s;
    for (std::uint32_t v = 0; v < p_.points.size(); ++v) index_.emplace(key(p_.points[v]), v);
  }

  // One pass; false when nothing met, so the pieces are final.
  bool pass(bool first) {
    const detail::SegmentGrid grid(p_.points, p_.segments);
    const std::vector<SegmentConflict> contacts = detail::all_segment_contacts(p_, grid, max_contacts);
    splits_.assign(p_.segments.size(), {});
    const bool lone_on_segments = split_at_lone_vertices(grid);
    if (contacts.empty() && !lone_on_segments) return false;
    for (const SegmentConflict& c : contacts) {
      if (first && c.contact.kind == Contact::cross) ++crossings_;
      if (first && c.contact.kind == Contact::overlap) ++overlaps_;
      if (c.contact.kind == Contact::cross) {
        split_at_crossing(c.later, c.earlier);
      } else {
        split_at_endpoints(c.later, c.earlier);
        split_at_endpoints(c.earlier, c.later);
      }
    }
    rebuild_segments();
    return true;
  }

  ResolvedPslg finish(std::size_t input_points) {
    ResolvedPslg out;
    out.new_vertices = p_.points.size() - input_points;
    out.crossings = crossings_;
    out.overlaps = overlaps_;
    out.source_segment = std::move(source_);
    out.pslg = std::move(p_);
    return out;
  }

private:
  static std::pair<double, double> key(Point q) noexcept { return {q.x + 0.0, q.y + 0.0}; }
  struct KeyHash {
    std::size_t operator()(const std::pair<double, double>& k) const noexcept {
      return std::hash<double>()(k.first) * 31 + std::hash<double>()(k.second);
    }
  };

  Point at(std::uint32_t v) const { return p_.points[v]; }
  const Segment& seg(std::uint32_t s) const { return p_.segments[s]; }

  // A vertex on no segment that lies on one (or on several, where they cross)
  // splits each of them: the contact search only compares segments.
  bool split_at_lone_vertices(const detail::SegmentGrid& grid) {
    std::vector<char> on_some(p_.points.size(), 0);
    for (const Segment& s : p_.segments) on_some[s.a] = on_some[s.b] = 1;
    bool found = false;
    for (std::uint32_t v = 0; v < p_.points.size(); ++v) {
      if (on_some[v] || !grid.contains(at(v))) continue;
      for (const auto& entry : grid.cell_at(at(v))) {
        const Segment& s = seg(entry.item);
        if (!detail::on_segment(at(s.a), at(s.b), at(v))) continue;
        splits_[entry.item].vertices.push_back(v);
        found = true;
      }
    }
    return found;
  }

  // The endpoints of `from` lying strictly inside `onto` split it there.
  void split_at_endpoints(std::uint32_t from, std::uint32_t onto) {
    const Segment& t = seg(onto);
    for (const std::uint32_t v : {seg(from).a, seg(from).b}) {
      if (v == t.a || v == t.b) continue;
      if (detail::on_segment(at(t.a), at(t.b), at(v))) splits_[onto].vertices.push_back(v);
    }
  }

  void split_at_crossing(std::uint32_t s, std::uint32_t t) {
    const Point x = crossing_point(seg(s), seg(t));
    std::uint32_t v = near_split(s, x);
    if (v == no_index) v = near_split(t, x);
    if (v == no_index) v = vertex_at(x, s);
    splits_[s].vertices.push_back(v);
    splits_[t].vertices.push_back(v);
  }

  // Where the lines of s and t meet, clamped to the box both segments share
  // (the rounded point then stays between the endpoints of each).
  Point crossing_point(const Segment& s, const Segment& t) const {
    const Point a = at(s.a), b = at(s.b), c = at(t.a), d = at(t.b);
    const Point ab = b - a, cd = d - c;
    double u = cross(c - a, cd) / cross(ab, cd);
    if (!std::isfinite(u)) u = 0.5;  // nearly parallel: the box clamp below still applies
    Point x = lerp(a, b, std::clamp(u, 0.0, 1.0));
    const double lo_x = std::max(std::min(a.x, b.x), std::min(c.x, d.x));
    const double hi_x = std::min(std::max(a.x, b.x), std::max(c.x, d.x));
    const double lo_y = std::max(std::min(a.y, b.y), std::min(c.y, d.y));
    const double hi_y = std::min(std::max(a.y, b.y), std::max(c.y, d.y));
    x.x = std::clamp(x.x, lo_x, hi_x);
    x.y = std::clamp(x.y, lo_y, hi_y);
    // Keep inside the range the predicates are exact for (validate.cpp).
    x = {detail::flush_below_range(x.x), detail::flush_below_range(x.y)};
    return x;
  }

  // A split vertex of s within a few ulps of x: the same crossing point
  // computed from another pair of the segments meeting there.
  std::uint32_t near_split(std::uint32_t s, Point x) const {
    for (const std::uint32_t v : splits_[s].vertices) {
      const Point q = at(v);
      const double scale = std::max({std::abs(x.x), std::abs(x.y), std::abs(q.x), std::abs(q.y)});
      const double tolerance = 16.0 * scale * 0x1p-52;
      if (std::abs(q.x - x.x) <= tolerance && std::abs(q.y - x.y) <= tolerance) return v;
    }
    return no_index;
  }

  // The vertex at exactly x, made when there is none yet; its attributes are
  // interpolated along segment s, by the share of its length where x lies.
  std::uint32_t vertex_at(Point x, std::uint32_t s) {
    const auto found = index_.find(key(x));
    if (found != index_.end()) return found->second;
    if (p_.points.size() >= no_index - 1)
      throw InvalidInputError(InputProblem::other, "too many vertices after resolving intersections");
    const auto v = static_cast<std::uint32_t>(p_.points.size());
    const Point a = at(seg(s).a), b = at(seg(s).b);
    const double length = distance(a, b);
    const double share = length > 0.0 ? std::clamp(distance(a, x) / length, 0.0, 1.0) : 0.0;
    for (std::uint32_t k = 0; k < p_.attributes_per_point; ++k) {
      const double from = p_.attribute(seg(s).a, k), to = p_.attribute(seg(s).b, k);
      p_.attributes.push_back(from + share * (to - from));
    }
    if (!p_.point_markers.empty()) p_.point_markers.push_back(0);
    p_.points.push_back(x);
    index_.emplace(key(x), v);
    return v;
  }

  // Orders the split vertices of segment a->b from a to b: by the coordinate
  // on which a and b differ most (exact for vertices on the segment; a
  // crossing point is off it by a rounding error only), then the other.
  void sort_along(const Segment& s, std::vector<std::uint32_t>& vs) const {
    const Point a = at(s.a), b = at(s.b);
    const bool by_x = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
    const double sx = b.x >= a.x ? 1.0 : -1.0, sy = b.y >= a.y ? 1.0 : -1.0;
    std::sort(vs.begin(), vs.end(), [&](std::uint32_t u, std::uint32_t w) {
      const Point pu = at(u), pw = at(w);
      const double major_u = by_x ? sx * pu.x : sy * pu.y, major_w = by_x ? sx * pw.x : sy * pw.y;
      if (major_u != major_w) return major_u < major_w;
      const double minor_u = by_x ? sy * pu.y : sx * pu.x, minor_w = by_x ? sy * pw.y : sx * pw.x;
      return minor_u < minor_w;
    });
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  }

  // Replaces every split segment by its pieces, in order, and keeps only the
  // first of pieces joining the same two vertices (overlaps).
  void rebuild_segments() {
    std::vector<Segment> pieces;
    std::vector<std::uint32_t> source;
    std::unordered_map<std::uint64_t, std::uint32_t> seen;
    const auto add = [&](std::uint32_t a, std::uint32_t b, int marker, std::uint32_t from) {
      if (a == b) return;
      const std::uint64_t k = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      if (!seen.emplace(k, static_cast<std::uint32_t>(pieces.size())).second) return;
      pieces.push_back({a, b, marker});
      source.push_back(from);
    };
    for (std::uint32_t s = 0; s < p_.segments.size(); ++s) {
      const Segment sg = seg(s);
      std::vector<std::uint32_t>& vs = splits_[s].vertices;
      sort_along(sg, vs);
      std::uint32_t from = sg.a;
      for (const std::uint32_t v : vs) {
        if (v == sg.a || v == sg.b) continue;
        add(from, v, sg.marker, source_[s]);
        from = v;
      }
      add(from, sg.b, sg.marker, source_[s]);
    }
    p_.segments = std::move(pieces);
    source_ = std::move(source);
  }

  Pslg p_;
  std::vector<std::uint32_t> source_;
  std::vector<SplitList> splits_;
  std::unordered_map<std::pair<double, double>, std::uint32_t, KeyHash> index_;
  std::size_t crossings_ = 0, overlaps_ = 0;
};

}  // namespace

ResolvedPslg resolve_intersections(const Pslg& pslg) {
  Resolver resolver(pslg);
  for (int k = 0; k < max_passes; ++k)
    if (!resolver.pass(k == 0)) return resolver.finish(pslg.points.size());
  throw InvalidInputError(InputProblem::segments_intersect,
                          "the crossing segments could not be resolved: their pieces still meet after " +
                              std::to_string(max_passes) + " passes");
}

}  // namespace madd
