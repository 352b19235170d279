// Delaunay refinement of one subdomain (docs/mesh.md, "Refinement").
//
// Two queues, subsegments first (Ruppert): a subsegment encroached by a
// vertex (one strictly inside its diametral circle) is split; then each bad
// triangle (smallest angle below the bound, or area above the size bound)
// gets a new vertex at its circumcentre or, when that is far, at Ungor's
// off-centre. A new vertex that would encroach a boundary or interior
// subsegment (an interior one is split on both its sides; it belongs to
// this subdomain alone) is not inserted: the subsegment is split instead
// and the triangle tried again. One
// that would encroach a separator is not inserted either, and the triangle
// stays (the decoupling, docs/mesh.md, makes that rare; it is counted).
//
// Small input angles (Shewchuk 2002, Miller-Pav-Walkington 2003): a
// subsegment at a sharp corner (an arm of a sector below 60 degrees between
// two segments at a vertex) is
// split at a power of two from the corner, so the splits of the two sides are
// concentric shells; a triangle whose small angle is an input angle, or whose
// short edge joins the two sides of a sharp corner at one distance, is left
// alone; and a split of a subsegment at a sharp corner that would make it
// shorter than the short edge of the triangle asking for it is refused
// when the triangle is skinny (Shewchuk's "Terminator"), which is what
// makes refinement terminate there.
#include "mesh/refine.hpp"
#include "kernel/edge_key.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_set>

#include "madd/error.hpp"
#include "madd/predicates.hpp"
#include "mesh/refinement_mesh.hpp"
#include "quality/mesh_angle.hpp"
#include "triangulation/cdt.hpp"

namespace madd::detail {

namespace {

// Below this angle at a corner, two boundary pieces form a sharp corner
// (Ruppert's bound: his algorithm needs input angles of at least 60 degrees).
constexpr double sharp_corner_deg = 60.0;

enum class Reason : std::uint8_t { none, input_angle, separator, precision, limit };

struct TriangleShape {
  double l2[3];  // squared length of edge i (opposite corner i)
  double area;   // signed, floating point (the sign is known from orient2d)
  int shortest;  // index of the shortest edge
};

TriangleShape shape_of(Point a, Point b, Point c) {
  TriangleShape s{};
  const Point e0 = c - b, e1 = a - c, e2 = b - a;
  s.l2[0] = dot(e0, e0);
  s.l2[1] = dot(e1, e1);
  s.l2[2] = dot(e2, e2);
  s.area = signed_area(a, b, c);
  s.shortest = s.l2[0] <= s.l2[1] ? (s.l2[0] <= s.l2[2] ? 0 : 2) : (s.l2[1] <= s.l2[2] ? 1 : 2);
  return s;
}

class Refiner {
public:
  // label_area[l]: the area bound of the triangles labelled l (their
  // region's; +infinity for none).
  Refiner(RefinementMesh& mesh, const RefineSettings& settings, const std::vector<double>& label_area)
      : m_(mesh), settings_(settings), label_area_(label_area) {
    const double theta = settings.min_triangle_angle_deg * std::numbers::pi / 180.0;
    beta_ = theta > 0 ? 1.0 / (2.0 * std::sin(theta)) : std::numeric_limits<double>::infinity();
    // One bound everywhere (or none): read once, no per-triangle cache.
    if (!settings.size) one_bound_ = std::numeric_limits<double>::infinity();
    else if (settings.size->uniform()) one_bound_ = settings.size->area_at({0.0, 0.0});
    find_sharp_corners();
  }

  void run();
  // The triangles left below the bound, by reason; `blocking` gets the
  // separator segments that stopped a fix (sorted, once each).
  MeshShortfall shortfall(std::vector<std::uint32_t>& blocking) const;

private:
  bool is_bad(std::uint32_t t) const;
  bool too_skinny(const TriangleShape& s) const;
  bool too_big(std::uint32_t t, const TriangleShape& s, Point a, Point b, Point c) const;  // t went through queue_fresh
  double bound_of(std::uint32_t t, double area, Point a, Point b, Point c) const;
  void check_limits();
  Reason input_angle_rule(std::uint32_t t, const TriangleShape& s) const;
  Point insertion_point(std::uint32_t t, const TriangleShape& s) const;
  void try_triangle(std::uint32_t t);
  bool split_subsegment(std::uint32_t a, std::uint32_t b);
  double split_parameter(std::uint32_t h) const;
  bool at_sharp_corner(std::uint32_t h) const;
  void queue_fresh();
  void check_encroached_by_apex(std::uint32_t h);
  void find_sharp_corners();
  RefinementMesh& m_;
  const RefineSettings& settings_;
  const std::vector<double>& label_area_;
  // The size bound's queries come in runs around each new point: each starts where the last ended.
  mutable BoundHint bound_hint_;
  // Per vertex: the last query of the field (bound_of) at the centroid of a
  // triangle with that corner, and the edge length there (NaN: none yet).
  struct FieldQuery {
    Point at;
    double edge = std::numeric_limits<double>::quiet_NaN();
  };
  mutable std::vector<FieldQuery> anchor_;
  double beta_ = 1.0;                // circumradius / shortest edge bound: 1 / (2 sin theta)
  std::vector<std::uint8_t> sharp_;  // per input vertex: two pieces meet there below 60 degrees
  std::vector<std::uint8_t>
      sharp_arm_;  // per segment end (2 s at a, 2 s + 1 at b): it bounds a sector below 60 degrees
  // Per input vertex: the unit of the shells boundary subsegments are split
  // in around it (0: none; see find_sharp_corners).
  std::vector<double> shell_unit_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> segment_queue_;
  std::vector<std::uint32_t> triangle_queue_;
  std::vector<std::uint32_t> generation_;  // per slot, bumped when the slot holds a new triangle
  std::vector<std::uint32_t> queued_generation_;
  std::vector<Reason> reason_;  // per slot: why the triangle there was left bad
  // Per slot: the size bound at the triangle's centroid, read when first
  // needed (NaN until then) and once: a bad triangle is looked at when made,
  // when taken from the queue and when split, and a skinny one needs no size
  // (a quarter of those made on a graded coast; the bound's query is a third
  // of a graded refinement's time). Under a graded field it may instead be
  // a value on the same side of the triangle's area (bound_of).
  mutable std::vector<double> size_bound_;                       // only under a varying bound
  double one_bound_ = std::numeric_limits<double>::quiet_NaN();  // the bound, when it is one value everywhere
  std::vector<std::uint32_t> blocker_;       // per slot: with Reason::separator, the separator segment in the way
  std::unordered_set<std::uint64_t> stuck_;  // subsegments whose split failed (precision)
  std::size_t steiner_ = 0;
  bool out_of_budget_ = false;
  std::size_t next_check_ = 8192;          // steiner_ at the next resource check
  std::vector<std::uint32_t> encroached_;  // scratch of try_triangle
};

// The sectors around input vertex corners: each sector is the fan of
// triangle corners at one vertex between two consecutive segments there
// (across unconstrained edges only); calls sector(v, angle, arms) once per
// sector, arms the segments bounding it (two, or one at a dangling end).
template <class Sector>
void for_each_sector(const RefinementMesh& m, Sector&& sector) {
  std::vector<std::uint8_t> seen(3 * std::size_t{m.slot_count()}, 0);
  std::vector<std::uint32_t> stack;
  for (std::uint32_t t0 = 0; t0 < m.slot_count(); ++t0) {
    if (!m.alive(t0)) continue;
    for (std::uint32_t i0 = 0; i0 < 3; ++i0) {
      const std::uint32_t v = m.corner(t0, static_cast<int>(i0));
      if (v >= m.input_vertex_count() || seen[3 * t0 + i0]) continue;
      double angle = 0;
      std::uint32_t arms[2] = {no_index, no_index};
      seen[3 * t0 + i0] = 1;
      stack.assign(1, 3 * t0 + i0);
      while (!stack.empty()) {
        const std::uint32_t c = stack.back();
        stack.pop_back();
        const std::uint32_t t = c / 3, i = c % 3;
        angle += angle_at(m.point(v), m.point(m.corner(t, static_cast<int>((i + 1) % 3))),
                          m.point(m.corner(t, static_cast<int>((i + 2) % 3))));
        // The two edges of t at v: opposite its other two corners.
        for (const std::uint32_t e : {(i + 1) % 3, (i + 2) % 3}) {
          const std::uint32_t h = 3 * t + e;
          if (m.segment_of(h) != no_index) {
            (arms[0] == no_index ? arms[0] : arms[1]) = m.segment_of(h);
            continue;
          }
          if (m.twin(h) == no_index) continue;
          const std::uint32_t u = m.twin(h) / 3;
          std::uint32_t j = 0;
          while (m.corner(u, static_cast<int>(j)) != v) ++j;
          if (seen[3 * u + j]) continue;
          seen[3 * u + j] = 1;
          stack.push_back(3 * u + j);
        }
      }
      sector(v, angle, arms);
    }
  }
}

void Refiner::find_sharp_corners() {
  const std::uint32_t n = m_.input_vertex_count();
  sharp_.assign(n, 0);
  shell_unit_.assign(n, 0.0);
  std::vector<std::uint32_t> pieces(n, 0), splittable(n, 0);
  std::vector<double> fixed_length(
      n, std::numeric_limits<double>::infinity());  // the shortest separator piece at the vertex
  for (std::size_t s = 0; s < m_.segment_count(); ++s) {
    const RefinementSegment& seg = m_.segment(static_cast<std::uint32_t>(s));
    for (const std::uint32_t v : {seg.a, seg.b}) {
      ++pieces[v];
      if (seg.splittable) ++splittable[v];
      else fixed_length[v] = std::min(fixed_length[v], distance(m_.point(seg.a), m_.point(seg.b)));
    }
  }
  // The sectors at each vertex between consecutive segments inside the
  // subdomain (one at a ring vertex between two ring pieces; two or more
  // where interior segments meet): the smallest decides a sharp corner, and
  // any sector off a straight angle makes the vertex a corner.
  constexpr double straight = 179.0 * std::numbers::pi / 180.0;
  std::vector<double> smallest(n, std::numeric_limits<double>::infinity());
  std::vector<std::uint8_t> bent(n, 0);
  sharp_arm_.assign(2 * m_.segment_count(), 0);
  for_each_sector(m_, [&](std::uint32_t v, double angle, const std::uint32_t* arms) {
    smallest[v] = std::min(smallest[v], angle);
    if (angle < sharp_corner_deg * std::numbers::pi / 180.0)
      for (int k = 0; k < 2; ++k)
        if (arms[k] != no_index) sharp_arm_[2 * arms[k] + (m_.segment(arms[k]).b == v ? 1 : 0)] = 1;
    if (angle < straight || angle > 2 * std::numbers::pi - straight) bent[v] = 1;
  });
  // Shells go around every real corner, not only sharp ones: with plain
  // midpoints the two sides of a corner are split at unrelated lengths, and
  // at bounds above Ruppert's 20.7 degrees the skinny corner triangles that
  // makes can feed each other into the corner without end (seen at 33
  // degrees on a 98 degree corner of the archipelago: 35,000 vertices within
  // 1e-3 of it). Between splittable pieces (boundary or interior) the shells
  // are powers of two; where a separator meets them they are powers of two
  // of the separator's piece there (which is never split), so the corner
  // triangle ends up isosceles with the corner's angle (>= Phi0) at its
  // apex. A vertex between two collinear pieces (a split point of the
  // decoupling, or a straight vertex of an interior polyline) is no corner;
  // a vertex where three or more pieces meet always is.
  for (std::uint32_t v = 0; v < n; ++v) {
    if (pieces[v] < 2) continue;  // an isolated vertex or a dangling end: a full turn, no corner
    sharp_[v] = smallest[v] < sharp_corner_deg * std::numbers::pi / 180.0 ? 1 : 0;
    if (splittable[v] == 0) continue;
    if (splittable[v] == pieces[v]) {
      if (pieces[v] > 2 || bent[v]) shell_unit_[v] = 1.0;
    } else {
      shell_unit_[v] = fixed_length[v];
    }
  }
}

bool Refiner::too_skinny(const TriangleShape& s) const {
  // circumradius / shortest edge = (product of the two longer edges) / (4 area).
  const int k = s.shortest;
  const double longer = s.l2[(k + 1) % 3] * s.l2[(k + 2) % 3];
  return longer > 16.0 * s.area * s.area * beta_ * beta_;
}

// Above the regional bound (Triangle's -a with regions) or the size bound:
// the smaller wins.
bool Refiner::too_big(std::uint32_t t, const TriangleShape& s, Point a, Point b, Point c) const {
  if (s.area > label_area_[m_.label(t)]) return true;
  if (!std::isnan(one_bound_)) return s.area > one_bound_;
  if (std::isnan(size_bound_[t])) size_bound_[t] = bound_of(t, s.area, a, b, c);
  return s.area > size_bound_[t];
}

// The size bound at t's centroid g, or, under a field of slope L
// (AreaBound::edge_slope), a value on the same side of t's area, read from
// the last query made in a triangle at one of t's corners v (each corner
// keeps its own, anchor_): the path from that query's centroid to v (inside
// the triangle it was made in, since remade or not, but in the domain) and
// on to g (inside t) lies in the domain, so h(g) is within L times its length
// of h there. Past that band the bound is known without a query; the
// tightest of the three corners decides. The margin covers the rounding of
// the field's value, far below 1e-9. No triangle within AreaBound::least is
// queried at all. (Reading only the last query, and only when t shared its
// newest corner, left 1.46 M of 2.7 M bounds to query on the Maine coast at
// L = 0.2; docs/mesh.md, "Size field".)
double Refiner::bound_of(std::uint32_t t, double area, Point a, Point b, Point c) const {
  const AreaBound& bound = *settings_.size;
  if (area <= bound.least()) return bound.least();
  const Point g = triangle_centroid(a, b, c);
  if (!(bound.edge_slope() > 0.0) || !settings_.bounds_from_neighbours) return bound.area_at(g, &bound_hint_);
  const std::uint32_t corners[3] = {m_.corner(t, 0), m_.corner(t, 1), m_.corner(t, 2)};
  const std::uint32_t most = std::max({corners[0], corners[1], corners[2]});
  if (anchor_.size() <= most) anchor_.resize(most + 1 + most / 2);
  double low = 0.0, high = std::numeric_limits<double>::infinity();
  for (const std::uint32_t v : corners) {
    const FieldQuery& q = anchor_[v];
    if (std::isnan(q.edge)) continue;
    const Point pv = m_.point(v);
    const double reach = bound.edge_slope() * (distance(q.at, pv) + distance(pv, g));
    low = std::max(low, (q.edge - reach) * (1.0 - 1e-9));
    high = std::min(high, (q.edge + reach) * (1.0 + 1e-9));
  }
  if (low > 0.0 && area <= bound.area_of_field_edge(low)) return bound.area_of_field_edge(low);
  if (std::isfinite(high) && area > bound.area_of_field_edge(high)) return bound.area_of_field_edge(high);
  const FieldQuery here{g, bound.field_edge_at(g, &bound_hint_)};
  for (const std::uint32_t v : corners) anchor_[v] = here;
  return bound.area_of_field_edge(here.edge);
}

bool Refiner::is_bad(std::uint32_t t) const {
  const Point a = m_.point(m_.corner(t, 0)), b = m_.point(m_.corner(t, 1)), c = m_.point(m_.corner(t, 2));
  const TriangleShape s = shape_of(a, b, c);
  return too_skinny(s) || too_big(t, s, a, b, c);
}

// Triangles refinement must not try to fix (docs/mesh.md, "Small angles").
Reason Refiner::input_angle_rule(std::uint32_t t, const TriangleShape& s) const {
  if (!too_skinny(s)) return Reason::none;
  // The smallest angle is opposite the shortest edge; it is an input angle
  // when both edges at it are segments.
  const int k = s.shortest;
  const std::uint32_t h1 = 3 * t + static_cast<std::uint32_t>((k + 1) % 3);
  const std::uint32_t h2 = 3 * t + static_cast<std::uint32_t>((k + 2) % 3);
  if (m_.segment_of(h1) != no_index && m_.segment_of(h2) != no_index) return Reason::input_angle;
  // The short edge joins two pieces of one sharp corner at (about) one distance from it.
  const std::uint32_t x = m_.corner(t, (k + 1) % 3), y = m_.corner(t, (k + 2) % 3);
  const auto corner_of = [&](std::uint32_t v, std::uint32_t& apex_a, std::uint32_t& apex_b) {
    const std::uint32_t sv = m_.vertex_segment(v);
    if (sv == no_index) return false;
    apex_a = m_.segment(sv).a;
    apex_b = m_.segment(sv).b;
    return true;
  };
  std::uint32_t xa = no_index, xb = no_index, ya = no_index, yb = no_index;
  if (!corner_of(x, xa, xb) || !corner_of(y, ya, yb)) return Reason::none;
  // On one segment, x and y are no two sides of a corner (a short edge along
  // one arm, far out, is an ordinary edge).
  if (m_.vertex_segment(x) == m_.vertex_segment(y)) return Reason::none;
  // x and y must lie on the two arms of the sharp sector (the angle x w y
  // below 60 degrees): where three or more segments meet at w, two pieces
  // at a wide angle there are no sharp corner.
  for (const std::uint32_t w : {xa, xb}) {
    if (w >= sharp_.size() || !sharp_[w] || (w != ya && w != yb)) continue;
    if (angle_at(m_.point(w), m_.point(x), m_.point(y)) >= sharp_corner_deg * std::numbers::pi / 180.0) continue;
    const double dx = distance(m_.point(w), m_.point(x)), dy = distance(m_.point(w), m_.point(y));
    if (std::abs(dx - dy) <= 0.05 * std::max(dx, dy)) return Reason::input_angle;
  }
  return Reason::none;
}

// The circumcentre, or Ungor's off-centre when the circumcentre is farther
// from the shortest edge than the apex of the triangle on that edge whose
// circumradius / edge ratio is exactly the bound.
Point Refiner::insertion_point(std::uint32_t t, const TriangleShape& s) const {
  const Point a = m_.point(m_.corner(t, 0)), b = m_.point(m_.corner(t, 1)), c = m_.point(m_.corner(t, 2));
  const Point centre = circumcentre(a, b, c);
  if (!settings_.off_centres || !std::isfinite(beta_)) return centre;
  const int k = s.shortest;
  const Point p = m_.point(m_.corner(t, (k + 1) % 3)), q = m_.point(m_.corner(t, (k + 2) % 3));
  const Point mid = midpoint(p, q);
  const double l = std::sqrt(s.l2[k]);
  // 0.5% nearer than the apex whose angle is exactly the bound, so the new
  // triangle on the short edge clears the bound by more than rounding.
  const double h = 0.995 * l * (beta_ + std::sqrt(beta_ * beta_ - 0.25));
  const double d = distance(mid, centre);
  if (!(d > h)) return centre;
  return mid + (h / d) * (centre - mid);
}

// The subsegment has an end at a sharp corner (an end of its segment where
// it bounds a sector below 60 degrees; where three or more pieces meet, the
// others there are no sharp corner).
bool Refiner::at_sharp_corner(std::uint32_t h) const {
  const std::uint32_t sid = m_.segment_of(h);
  const RefinementSegment& s = m_.segment(sid);
  const auto sharp_end = [&](std::uint32_t v) {
    return (v == s.a && sharp_arm_[2 * sid] != 0) || (v == s.b && sharp_arm_[2 * sid + 1] != 0);
  };
  return sharp_end(m_.origin(h)) || sharp_end(m_.dest(h));
}

// The midpoint parameter, or, with one end at a corner (shell_unit_), the power of
// two distance from the corner nearest the middle (concentric shells).
double Refiner::split_parameter(std::uint32_t h) const {
  const std::uint32_t sid = m_.segment_of(h);
  const RefinementSegment& s = m_.segment(sid);
  const std::uint32_t o = m_.origin(h), d = m_.dest(h);
  const auto parameter_of = [&](std::uint32_t v) { return v == s.a ? 0.0 : v == s.b ? 1.0 : m_.vertex_parameter(v); };
  const double to = parameter_of(o), td = parameter_of(d);
  const auto unit_at = [&](std::uint32_t v) {
    return (v == s.a || v == s.b) && v < shell_unit_.size() ? shell_unit_[v] : 0.0;
  };
  const bool corner_o = unit_at(o) > 0, corner_d = unit_at(d) > 0;
  if (corner_o == corner_d) return 0.5 * (to + td);
  const double full = distance(m_.point(s.a), m_.point(s.b));
  const double piece = distance(m_.point(o), m_.point(d));
  const double unit = corner_o ? unit_at(o) : unit_at(d);
  const double shell = unit * std::exp2(std::round(std::log2(0.5 * piece / unit)));
  const double from = corner_o ? to : td, towards = corner_o ? td : to;
  return from + (towards > from ? 1.0 : -1.0) * shell / full;
}

// The time and memory limits, every 8,192 new points.
void Refiner::check_limits() {
  if (settings_.guard && steiner_ >= next_check_) {
    settings_.guard->check(settings_.meshed ? settings_.meshed->load() : 0);
    next_check_ = steiner_ + 8192;
  }
}

bool Refiner::split_subsegment(std::uint32_t a, std::uint32_t b) {
  // The Steiner budget and the limits hold for segment splits too, not only
  // for the triangles the queue tests.
  if (out_of_budget_) return false;
  if (settings_.max_steiner_points && steiner_ >= settings_.max_steiner_points) {
    out_of_budget_ = true;
    return false;
  }
  check_limits();
  std::uint32_t h = m_.find_half_edge(a, b);
  if (h == no_index || m_.segment_of(h) == no_index) h = m_.find_half_edge(b, a);
  if (h == no_index || m_.segment_of(h) == no_index) return false;  // split already
  if (stuck_.count(edge_key(a, b))) return false;
  const std::uint32_t v = m_.split(h, split_parameter(h));
  if (v == no_index) {
    stuck_.insert(edge_key(a, b));
    return false;
  }
  ++steiner_;
  queue_fresh();
  return true;
}

void Refiner::check_encroached_by_apex(std::uint32_t h) {
  if (m_.segment_of(h) == no_index || !m_.segment(m_.segment_of(h)).splittable) return;
  const std::uint32_t o = m_.origin(h), d = m_.dest(h);
  const Point apex = m_.point(m_.corner(h / 3, static_cast<int>(h % 3)));
  if (dot(m_.point(o) - apex, m_.point(d) - apex) < 0) segment_queue_.push_back({o, d});
}

void Refiner::queue_fresh() {
  for (const std::uint32_t t : m_.fresh()) {
    if (generation_.size() <= t) {
      generation_.resize(t + 1 + t / 2, 0);
      queued_generation_.resize(generation_.size(), std::numeric_limits<std::uint32_t>::max());
      reason_.resize(generation_.size(), Reason::none);
      blocker_.resize(generation_.size(), no_index);
      if (std::isnan(one_bound_)) size_bound_.resize(generation_.size());
    }
    ++generation_[t];
    if (std::isnan(one_bound_)) size_bound_[t] = std::numeric_limits<double>::quiet_NaN();
    reason_[t] = Reason::none;
    for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h) check_encroached_by_apex(h);
    if (is_bad(t)) {
      queued_generation_[t] = generation_[t];
      triangle_queue_.push_back(t);
    }
  }
  m_.fresh().clear();
}

void Refiner::try_triangle(std::uint32_t t) {
  const Point a = m_.point(m_.corner(t, 0)), b = m_.point(m_.corner(t, 1)), c = m_.point(m_.corner(t, 2));
  const TriangleShape s = shape_of(a, b, c);
  // A small input angle excuses a triangle's shape, never its size: one
  // above the bound is split all the same (the bound ends that). Left alone,
  // a skinny triangle at a 25-degree corner of the Seto Inland Sea stayed
  // above the size field and failed the self-check.
  if (const Reason r = input_angle_rule(t, s); r != Reason::none && !too_big(t, s, a, b, c)) {
    reason_[t] = r;
    return;
  }
  if (out_of_budget_) {
    reason_[t] = Reason::limit;
    return;
  }
  const Point p = insertion_point(t, s);
  // Coordinates must resolve the new vertex from the triangle's corners.
  const double scale = std::max({std::abs(p.x), std::abs(p.y), std::numeric_limits<double>::min()});
  const double near = 64.0 * std::numeric_limits<double>::epsilon() * scale;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || distance(p, a) <= near || distance(p, b) <= near ||
      distance(p, c) <= near) {
    reason_[t] = Reason::precision;
    return;
  }
  const WalkResult w = m_.walk(t, p);
  std::vector<std::uint32_t>& encroached = encroached_;
  encroached.clear();
  if (w.blocked_by != no_index) {
    encroached.push_back(w.blocked_by);  // beyond a segment: its diametral circle holds p (or p is outside)
  } else if (w.triangle == no_index) {
    reason_[t] = Reason::precision;
    return;
  } else {
    // p on a segment edge of its triangle (a right triangle's circumcentre
    // on its hypotenuse): inside that subsegment's diametral circle, so it
    // encroaches (the cavity could not be star-shaped from p anyway).
    for (std::uint32_t h = 3 * w.triangle; h < 3 * w.triangle + 3; ++h)
      if (m_.segment_of(h) != no_index && orient2d(m_.point(m_.origin(h)), m_.point(m_.dest(h)), p) == 0)
        encroached.push_back(h);
  }
  if (w.triangle != no_index && encroached.empty()) {
    if (!m_.prepare(w.triangle, p)) {
      reason_[t] = Reason::precision;
      return;
    }
    for (const std::uint32_t h : m_.rim_segments()) {
      if (dot(m_.point(m_.origin(h)) - p, m_.point(m_.dest(h)) - p) < 0) encroached.push_back(h);
    }
    if (encroached.empty()) {
      m_.commit();
      ++steiner_;
      queue_fresh();
      return;
    }
    m_.abandon();
  }
  // p encroaches: split the boundary subsegments instead (unless at a sharp
  // corner that would make them shorter than this triangle's short edge);
  // a separator is never split.
  // (Half-edges die with each split, so the subsegments are named by their ends first.)
  struct Encroached {
    std::uint32_t a, b;
    bool splittable, sharp;
  };
  std::vector<Encroached> list;
  std::uint32_t blocking = no_index;  // the first separator in the way
  for (const std::uint32_t h : encroached) {
    list.push_back({m_.origin(h), m_.dest(h), m_.segment(m_.segment_of(h)).splittable, at_sharp_corner(h)});
    if (!list.back().splittable && blocking == no_index) blocking = m_.segment_of(h);
  }
  bool split_any = false, separator = false;
  const double shortest = std::sqrt(s.l2[s.shortest]);
  const bool skinny = too_skinny(s);
  // Read before the splits below change the mesh (t may die with them).
  const bool big = skinny && std::any_of(list.begin(), list.end(), [](const Encroached& e) { return e.sharp; }) &&
                   too_big(t, s, a, b, c);
  for (const Encroached& e : list) {
    if (!e.splittable) {
      separator = true;
      continue;
    }
    // Shewchuk's rule is for skinny triangles: one bad only by its size
    // still splits the arm (its size bound ends that).
    if (e.sharp && skinny && !big && 0.5 * distance(m_.point(e.a), m_.point(e.b)) < shortest) continue;
    split_any |= split_subsegment(e.a, e.b);
  }
  if (split_any) {
    if (m_.alive(t) && queued_generation_[t] != generation_[t]) {
      queued_generation_[t] = generation_[t];
      triangle_queue_.push_back(t);
    }
    return;
  }
  reason_[t] = separator ? Reason::separator : encroached.empty() ? Reason::precision : Reason::input_angle;
  blocker_[t] = blocking;
}

void Refiner::run() {
  // Every triangle starts fresh: encroached subsegments and bad triangles are queued.
  for (std::uint32_t t = 0; t < m_.slot_count(); ++t) m_.fresh().push_back(t);
  queue_fresh();
  std::size_t head = 0;
  for (;;) {
    if (!segment_queue_.empty()) {
      const auto [a, b] = segment_queue_.back();
      segment_queue_.pop_back();
      split_subsegment(a, b);
      continue;
    }
    if (head == triangle_queue_.size()) break;
    const std::uint32_t t = triangle_queue_[head++];
    if (head > 4096 && head * 2 > triangle_queue_.size()) {
      triangle_queue_.erase(triangle_queue_.begin(), triangle_queue_.begin() + static_cast<std::ptrdiff_t>(head));
      head = 0;
    }
    if (!m_.alive(t) || queued_generation_[t] != generation_[t]) continue;
    queued_generation_[t] = std::numeric_limits<std::uint32_t>::max();
    if (!is_bad(t)) continue;
    if (settings_.max_steiner_points && steiner_ >= settings_.max_steiner_points) out_of_budget_ = true;
    check_limits();
    try_triangle(t);
  }
}

MeshShortfall Refiner::shortfall(std::vector<std::uint32_t>& blocking) const {
  MeshShortfall f;
  blocking.clear();
  for (std::uint32_t t = 0; t < m_.slot_count(); ++t) {
    if (!m_.alive(t)) continue;
    // Counted with verify_mesh's own measure, so the two always agree.
    if (smallest_angle_deg(m_.point(m_.corner(t, 0)), m_.point(m_.corner(t, 1)), m_.point(m_.corner(t, 2))) >=
        settings_.min_triangle_angle_deg - mesh_angle_slack_deg) {
      // Too large but for a separator in the way: no shortfall (verify_mesh
      // allows none of size), but the separator is split for the next round
      // (src/mesh/rounds.hpp), as for an angle.
      if (t < reason_.size() && reason_[t] == Reason::separator && blocker_[t] != no_index && is_bad(t))
        blocking.push_back(blocker_[t]);
      continue;
    }
    switch (t < reason_.size() ? reason_[t] : Reason::none) {
    case Reason::input_angle:
      ++f.input_angle;
      break;
    case Reason::separator:
      ++f.separator;
      if (blocker_[t] != no_index) blocking.push_back(blocker_[t]);
      break;
    case Reason::limit:
      ++f.limit;
      break;
    default:
      ++f.precision;
      break;
    }
  }
  std::sort(blocking.begin(), blocking.end());
  blocking.erase(std::unique(blocking.begin(), blocking.end()), blocking.end());
  return f;
}

std::vector<RefinementSegment> refinement_segments(const Pslg& pslg, const std::vector<bool>& splittable) {
  std::vector<RefinementSegment> out(pslg.segments.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {pslg.segments[i].a, pslg.segments[i].b, splittable[i]};
  return out;
}

}  // namespace

SubdomainMesh refine_subdomain(const Pslg& pslg, const std::vector<bool>& splittable, const RefineSettings& settings) {
  // Refinement grows the triangulator's own mesh. The labels are 1 + the
  // index of the region of pslg.regions whose face holds a triangle, 0 for
  // none (the triangulator's -A flood on the region numbers).
  HalfEdgeMesh cdt;
  std::vector<std::uint32_t> labels;
  // All points collinear: no triangles, and nothing to refine.
  (void)constrained_delaunay(cdt, pslg, {}, pslg.regions.empty() ? nullptr : &labels);
  RefinementMesh m(std::move(cdt), pslg.points, refinement_segments(pslg, splittable), std::move(labels));
  std::vector<double> label_area(pslg.regions.size() + 1, std::numeric_limits<double>::infinity());
  for (std::size_t r = 0; r < pslg.regions.size(); ++r)
    if (pslg.regions[r].max_area > 0) label_area[r + 1] = pslg.regions[r].max_area;
  // 10% over the estimate: most meshes fit without a copy, few waste much.
  m.reserve(static_cast<std::size_t>(std::min(1.1 * settings.expected_triangles, 4e8)));
  Refiner refiner(m, settings, label_area);
  refiner.run();
  SubdomainMesh out;
  out.shortfall = refiner.shortfall(out.blocking_separators);
  out.points.assign(m.points().begin(), m.points().end());
  out.point_segment.resize(m.vertex_count());
  out.point_parameter.resize(m.vertex_count());
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
    out.point_segment[v] = m.vertex_segment(v);
    out.point_parameter[v] = m.vertex_parameter(v);
  }
  // Exactly as long as they must be: every subdomain's piece is held until
  // the merge.
  std::uint32_t alive = 0;
  for (std::uint32_t t = 0; t < m.slot_count(); ++t) alive += m.alive(t) ? 1 : 0;
  out.triangles.reserve(alive);
  if (!pslg.regions.empty()) out.triangle_attribute.reserve(alive);
  std::vector<std::uint32_t> index(m.slot_count(), no_index);
  for (std::uint32_t t = 0; t < m.slot_count(); ++t) {
    if (!m.alive(t)) continue;
    index[t] = static_cast<std::uint32_t>(out.triangles.size());
    out.triangles.push_back({m.corner(t, 0), m.corner(t, 1), m.corner(t, 2)});
    if (!pslg.regions.empty())
      out.triangle_attribute.push_back(m.label(t) == 0 ? 0.0 : pslg.regions[m.label(t) - 1].attribute);
  }
  out.neighbours.resize(out.triangles.size());
  for (std::uint32_t t = 0; t < m.slot_count(); ++t) {
    if (!m.alive(t)) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = m.twin(3 * t + i);
      out.neighbours[index[t]][i] = h == no_index ? no_index : index[h / 3];
    }
  }
  return out;
}

}  // namespace madd::detail
