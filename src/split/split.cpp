// One split: Sec. 3 (refinement, medial axis), Sec. 4.1-4.3 (graphs,
// partition, repartition), as pure geometry for Subdivision::commit.
#include "split/split.hpp"

#include <cmath>
#include <iterator>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>

#include "madd/bisect.hpp"
#include "madd/error.hpp"
#include "medial/medial_detail.hpp"
#include "madd/triangulation.hpp"
#include "split/refine.hpp"
#include "split/chord.hpp"
#include "split/locate.hpp"
#include "kernel/angles.hpp"
#include "kernel/stopwatch.hpp"

namespace madd::detail {

namespace {

constexpr double points_per_side = 4.0;  // spacing = sqrt(area) / (points_per_side * r)
// The refined boundary of one split holds at most max(min_point_cap,
// points_per_vertex_cap x the face's vertices) points, and never more than
// max_working_points: a needle-like face (perimeter thousands of times
// sqrt(area)) would otherwise cost as much as a huge input in every round
// (docs/hostile.md, "needles").
constexpr double max_working_points = 4.0e5;
constexpr double min_point_cap = 2.0e4;
constexpr double points_per_vertex_cap = 32.0;
constexpr int max_repartitions = 6;             // Sec. 4.3 attempts per bisection
constexpr double min_separator_fraction = 0.1;  // step 2 keeps separators >= this x sqrt(area per final subdomain)
constexpr std::uint32_t max_extra_targets = 2;  // j/plan targets tried besides floor(plan/2)/plan
constexpr double chord_trigger = 0.95;          // below this balance quality, look for a chord (split/chord.hpp)
constexpr double chord_gain = 0.02;             // a chord must balance at least this much better
// When no spacing of the dyadic rounds (first_spacing / 2^k) gives any valid
// separator, the boundary is sampled at these fractions of the first spacing
// before the face is given up. A narrow neck or a short feature can make the
// medial-axis approximation miss every separator that meets Phi0 at one
// sampling while another phase of the samples finds one: a coastal face that
// fails at r = 3, 6, 12 and 24 was measured to split at r = 4.5, 5 and 7.
constexpr double offset_spacings[] = {2.0 / 3.0, 0.6, 3.0 / 7.0, 0.3};
// When no even share gives a valid separator, shares of the weight on the
// smaller side tried (on the graphs of the first uneven_rounds spacings): a
// split that leaves one side at a quarter of the face still beats no split,
// which would leave the whole face as one subdomain.
constexpr double uneven_fractions[] = {0.4, 1.0 / 3.0, 0.25, 0.2};
constexpr int uneven_rounds = 3;
constexpr double max_chord_points = 1500.0;  // the chord search is quadratic in the boundary points
// At commit, an end of this split may move to a vertex a neighbour's commit
// put on the same straight segment within this fraction of the spacing
// (EndSnap, subdivision/subdivision.hpp): a quarter of the distance between two working
// points is far below what the split resolves, so the move costs nothing.
constexpr double snap_fraction = 0.25;

bool is_cut(const MedialGraph& g, const std::vector<std::uint8_t>& side, const MedialEdge& e) {
  return side[g.coarse[e.left]] != side[g.coarse[e.right]];
}

}  // namespace

// Two cut partial separators meeting at one boundary point would pinch a side
// there (and may form an angle below Phi0). Returns pairs of G'_D vertices to
// keep together so that the later of the two is not cut.
std::vector<std::pair<std::uint32_t, std::uint32_t>> pinch_conflicts(const MedialGraph& g,
                                                                     std::span<const BoundaryLinks> links,
                                                                     const std::vector<std::uint8_t>& side,
                                                                     double separator_angle_deg) {
  std::vector<std::uint8_t> used(links.size(), 0);  // bit s: a cut separator ends there on side s
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  std::unordered_map<std::uint32_t, std::uint32_t> at_tip;  // tip -> the first cut edge through it (index)
  for (std::uint32_t k = 0; k < g.edges.size(); ++k) {
    const MedialEdge& e = g.edges[k];
    if (!is_cut(g, side, e)) continue;
    bool clash = false;
    for (const std::uint32_t p : {e.from, e.to}) {
      if (p >= links.size()) continue;
      const std::uint32_t other = p == e.from ? e.to : e.from;
      if (links[p].tip) {
        // A separator passes through: a second cut edge must leave the first
        // >= Phi0 apart on the side away from the segment; a third is a pinch.
        const auto [it, first] = at_tip.try_emplace(p, k);
        if (first) continue;
        const MedialEdge& f = g.edges[it->second];
        const Point o = g.points[p], along = g.points[links[p].next];
        const double a1 = detail::ccw_angle_deg(o, along, g.points[f.from == p ? f.to : f.from]);
        const double a2 = detail::ccw_angle_deg(o, along, g.points[other]);
        clash = clash || (used[p] & 1U) != 0 || std::abs(a1 - a2) < separator_angle_deg + 1e-9;
        used[p] |= 1U;
        continue;
      }
      const auto bit = static_cast<std::uint8_t>(1U << link_side(g.points, links, p, g.points[other]));
      clash = clash || (used[p] & bit) != 0 || links[p].no_end;
      used[p] |= bit;
    }
    if (clash) out.emplace_back(g.coarse[e.left], g.coarse[e.right]);
  }
  return out;
}

Point largest_triangle_centroid(const Pslg& domain) {
  const Triangulation tri = triangulate(domain);
  double best = -1.0;
  Point at;
  for (const auto& t : tri.triangles) {
    const Point a = tri.points[t[0]], b = tri.points[t[1]], c = tri.points[t[2]];
    const double area = signed_area(a, b, c);
    if (area > best) {
      best = area;
      at = triangle_centroid(a, b, c);
    }
  }
  return at;
}

double balance_quality(std::uint32_t plan, double w0, double w1) {
  double best = INFINITY;
  for (std::uint32_t k0 = 1; k0 < plan; ++k0) best = std::min(best, std::max(w0 / k0, w1 / (plan - k0)));
  return (w0 + w1) / static_cast<double>(plan) / best;
}

std::uint32_t side0_plan(std::uint32_t plan, double w0, double w1) {
  std::uint32_t best = plan / 2;
  double best_cost = INFINITY;
  for (std::uint32_t k0 = 1; k0 < plan; ++k0) {
    const double cost = std::max(w0 / k0, w1 / (plan - k0));
    if (cost < best_cost) {
      best_cost = cost;
      best = k0;
    }
  }
  return best;
}

namespace {

// Per isolated point of the face: the G_D vertices holding it.
using IsolatedIn = std::vector<std::vector<std::uint32_t>>;

struct Candidate {
  SplitResult result;
  double quality = -1.0;
};

EndRef end_ref(const FaceDomain& fd, const MedialGraph& g, std::uint32_t point) {
  if (point < fd.refs.size()) return fd.refs[point];
  return EndRef{EndRef::centre, no_index, point, g.points[point]};
}

// The side of every working edge of the interior pieces and of every
// isolated point, for Subdivision::commit. Both sides of an interior edge are
// one G'_D vertex (the edge is a constraint, never a partial separator), and
// every G_D vertex holding an isolated point is on one side (valid_bisection).
void place_interior(const FaceDomain& fd, const Triangulation& tri, const MedialGraph& g,
                    const std::vector<std::uint8_t>& side, const IsolatedIn& isolated_in, SplitResult& r) {
  r.inner_sides.resize(fd.inner_edges_of.size());
  for (std::size_t k = 0; k < fd.inner_edges_of.size(); ++k) r.inner_sides[k].assign(fd.inner_edges_of[k], 0);
  r.point_sides.assign(isolated_in.size(), 0);
  for (std::size_t k = 0; k < isolated_in.size(); ++k) r.point_sides[k] = side[g.coarse[isolated_in[k].front()]];
  if (fd.inner_edge.empty()) return;
  const auto gd_vertex = [&](std::uint32_t t, int sub) {
    return g.first_vertex[t] + (g.centre[t] != no_index ? static_cast<std::uint32_t>(sub) : 0u);
  };
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t seg = tri.segment_of[t][i];
      if (seg != no_index && seg >= fd.ring_segments) {
        const auto& [piece, along] = fd.inner_edge[seg - fd.ring_segments];
        r.inner_sides[piece][along] = side[g.coarse[gd_vertex(t, i)]];
      }
    }
  }
}

SplitResult make_result(const Subdivision& sub, std::uint32_t face, const FaceDomain& fd, const Triangulation& tri,
                        const MedialGraph& g, const std::vector<std::uint8_t>& side, const IsolatedIn& isolated_in,
                        const EndSmoothing* smoothing) {
  SplitResult r;
  std::vector<CutEnd> cut;
  for (const MedialEdge& e : g.edges) {
    if (is_cut(g, side, e)) cut.push_back({{e.from, e.to}, side[g.coarse[e.left]]});
  }
  r.ring_side.assign(sub.faces[face].rings.size(), 0);
  std::vector<std::uint8_t> seen(r.ring_side.size(), 0);
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) {
      if (tri.neighbours[t][i] != no_index) continue;
      const std::uint32_t ring = fd.ring_of[tri.triangles[t][(i + 1) % 3]];
      if (seen[ring]) continue;
      seen[ring] = 1;
      const std::uint32_t v = g.first_vertex[t] + (g.centre[t] != no_index ? static_cast<std::uint32_t>(i) : 0u);
      r.ring_side[ring] = side[g.coarse[v]];
    }
  }
  place_interior(fd, tri, g, side, isolated_in, r);
  // Interior points: the centroid of the largest atom of each side, strictly inside it.
  double best[2] = {-1.0, -1.0};
  for (std::uint32_t v = 0; v < g.gd.vertex_count(); ++v) {
    const int s = side[g.coarse[v]];
    r.weight[s] += g.gd.vertex_weights[v];
    if (g.gd.vertex_weights[v] > best[s]) {
      best[s] = g.gd.vertex_weights[v];
      const auto c = vertex_triangle_corners(g, tri, v);
      r.interior[s] = triangle_centroid(c[0], c[1], c[2]);
    }
  }
  if (smoothing != nullptr) smooth_ends(g, fd, *smoothing, cut, r.weight, r.interior);
  for (const CutEnd& c : cut) r.edges.push_back({end_ref(fd, g, c.end[0]), end_ref(fd, g, c.end[1]), c.left_side});
  return r;
}

// Keep-together pairs for every isolated point a cut separator runs through
// (the G_D vertices holding it are on both sides).
void isolated_conflicts(const MedialGraph& g, const IsolatedIn& isolated_in, const std::vector<std::uint8_t>& side,
                        std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) {
  for (const auto& holders : isolated_in) {
    const std::uint32_t first = g.coarse[holders.front()];
    for (const std::uint32_t v : holders)
      if (side[g.coarse[v]] != side[first]) out.emplace_back(first, g.coarse[v]);
  }
}

// The G_D vertices holding each isolated point of the face; a pinned one is
// a triangulation vertex, and one triangle around it stands for all (they
// are one G'_D vertex: no separator ends there).
IsolatedIn locate_isolated(const FaceDomain& fd, const Triangulation& tri, const MedialGraph& g, std::uint32_t face) {
  IsolatedIn out;
  if (!fd.isolated.empty()) {
    const GdLocator locator(g, tri);
    for (const Point& p : fd.isolated) out.push_back(locator.containing(p));
  }
  if (!fd.pinned.empty()) {
    std::vector<std::uint32_t> pinned_of(fd.refs.size(), no_index);
    for (std::uint32_t k = 0; k < fd.pinned.size(); ++k) pinned_of[fd.pinned[k]] = k;
    out.resize(fd.pinned.size());
    for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t k = pinned_of[tri.triangles[t][i]];
        if (k != no_index && out[k].empty())
          out[k].push_back(g.first_vertex[t] +
                           (g.centre[t] != no_index ? static_cast<std::uint32_t>((i + 1) % 3) : 0u));
      }
    }
  }
  for (const auto& holders : out)
    if (holders.empty())
      throw DecompositionError("an isolated point is in no triangle of its subdomain (internal error)", face);
  return out;
}

// Bisects G'_D aiming at `target` on side 0, repartitioning with
// keep-together constraints while cut separators pinch at a boundary point
// (Sec. 4.3) or run through an isolated point. Returns an empty side vector
// when no valid bisection is found.
std::vector<std::uint8_t> valid_bisection(const MedialGraph& g, std::span<const BoundaryLinks> links,
                                          const IsolatedIn& isolated_in, double separator_angle_deg, double target,
                                          std::uint64_t seed, double weights[2]) {
  BisectOptions bo;
  bo.target_fraction = target;
  bo.balance_tolerance = 0.02;
  bo.seed = seed;
  bo.connected = true;
  for (int attempt = 0; attempt < max_repartitions; ++attempt) {
    Bisection b = bisect(g.contracted, bo);
    if (!b.connected[0] || !b.connected[1] || !(b.weight[0] > 0.0) || !(b.weight[1] > 0.0)) return {};
    auto conflicts = pinch_conflicts(g, links, b.side, separator_angle_deg);
    isolated_conflicts(g, isolated_in, b.side, conflicts);
    if (conflicts.empty()) {
      weights[0] = b.weight[0];
      weights[1] = b.weight[1];
      return std::move(b.side);
    }
    bo.keep_together.insert(bo.keep_together.end(), conflicts.begin(), conflicts.end());
  }
  return {};
}

// Side 0 aims at j/plan for j = floor(plan/2) first, then at nearby j when
// that split is not balanced enough: any j works, because the plan is shared
// between the sides after the split. Smooths the chosen separator (Sec. 5.1).
Candidate best_separator(const Subdivision& sub, std::uint32_t face, std::uint32_t plan, int round,
                         const SplitOptions& options, const FaceDomain& fd, const Triangulation& tri,
                         const MedialGraph& g, const IsolatedIn& isolated_in, std::span<const double> fractions) {
  Candidate out;
  const bool smooth = options.smoothing_iterations > 0;
  const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(round) * 7919u + face;
  std::vector<std::uint8_t> best_side;
  const auto consider = [&](double fraction, std::uint64_t target_seed) {
    double w[2] = {0.0, 0.0};
    auto side = valid_bisection(g, fd.links, isolated_in, options.separator_angle_deg, fraction, target_seed, w);
    if (side.empty()) return;
    const double q = balance_quality(plan, w[0], w[1]);
    if (q > out.quality) {
      out.quality = q;
      best_side = std::move(side);
    }
  };
  if (fractions.empty()) {
    // The k1 : k2 shares of the plan, the even one first.
    const std::uint32_t half = plan / 2;
    for (std::uint32_t j = half; j >= 1 && half - j <= max_extra_targets && out.quality < options.good_balance; --j)
      consider(static_cast<double>(j) / plan, seed + j);
  } else {
    for (std::size_t k = 0; k < fractions.size() && out.quality < options.good_balance; ++k)
      consider(fractions[k], seed + 1 + k);
  }
  if (best_side.empty()) return out;
  EndSmoothing ends;
  if (smooth) {
    double w[2] = {0.0, 0.0};
    for (std::uint32_t v = 0; v < g.contracted.vertex_count(); ++v) w[best_side[v]] += g.contracted.vertex_weights[v];
    const double floor = std::max(options.min_split_quality, out.quality - options.smoothing_tolerance);
    ends.iterations = options.smoothing_iterations;
    ends.separator_angle_deg = options.separator_angle_deg;
    ends.plan = plan;
    ends.min_quality = floor;
    double area = 0.0;
    for (std::uint32_t v = 0; v < g.gd.vertex_count(); ++v) {
      const auto c = vertex_triangle_corners(g, tri, v);
      area += triangle_area(c[0], c[1], c[2]);
    }
    ends.weight_per_area = area > 0.0 ? (w[0] + w[1]) / area : 1.0;
    ends.min_length = min_separator_fraction * std::sqrt(area / plan);
  }
  out.result = make_result(sub, face, fd, tri, g, best_side, isolated_in, smooth ? &ends : nullptr);
  out.quality = balance_quality(plan, out.result.weight[0], out.result.weight[1]);
  return out;
}

// One refinement round at `spacing`: refine, triangulate, build G_D and G'_D,
// choose the separator; the time of each phase is added to `times`.
Candidate try_spacing(const Subdivision& sub, std::uint32_t face, std::uint32_t plan, double spacing, int round,
                      const SplitOptions& options, const FaceDensity& density, SplitTimes& times,
                      std::span<const double> fractions = {}, bool pin_isolated = false) {
  Stopwatch clock;
  const FaceDomain fd =
      refine_face(sub, face, spacing, density.point_weights, options.adaptive_boundary_refinement, pin_isolated);
  times.refine += clock.lap();
  const Triangulation tri = triangulate(fd.pslg);
  times.triangulate += clock.lap();
  const bool smooth = options.smoothing_iterations > 0;
  MedialGraph g = build_medial_graph(tri, fd.links, MedialOptions{options.separator_angle_deg, smooth});
  if (density.graded && g.contracted.vertex_count() >= 2) set_vertex_weights(g, density_weights(g, tri, fd, density));
  times.graph += clock.lap();
  if (g.contracted.vertex_count() < 2) return Candidate{};
  const IsolatedIn isolated_in = locate_isolated(fd, tri, g, face);
  Candidate out = best_separator(sub, face, plan, round, options, fd, tri, g, isolated_in, fractions);
  out.result.snap = {snap_fraction * spacing, options.separator_angle_deg};
  times.bisect += clock.lap();
  return out;
}

// The chord fallback (split/chord.hpp) for a face whose best split so far
// has balance quality `best` (< 0: none found), on its boundary refined at
// half the first spacing.
std::optional<Chord> chord_split(const Subdivision& sub, std::uint32_t face, std::uint32_t plan,
                                 const SplitOptions& options, const FaceDensity& density, double best,
                                 SplitTimes& times) {
  const double area = sub.face_area(face);
  const double h = std::max(0.5 * std::sqrt(area) / (points_per_side * options.boundary_refinement),
                            face_perimeter(sub, face) / max_chord_points);
  ChordOptions co;
  co.separator_angle_deg = options.separator_angle_deg;
  co.plan = plan;
  co.min_quality = best < 0.0 ? options.min_split_quality : best + chord_gain;
  co.good_quality = options.good_balance;
  co.end_bonus = options.smoothing_iterations > 0;
  if (density.graded) {
    co.area_weight = density.r;
    co.sample_weight = density.a;
    co.samples = density.samples;
  }
  Stopwatch clock;
  const FaceDomain fd = refine_face(sub, face, h);
  times.refine += clock.lap();
  auto chord = best_chord(fd, co);
  if (chord) chord->result.snap = {snap_fraction * h, options.separator_angle_deg};
  times.bisect += clock.lap();
  return chord;
}

}  // namespace

SplitResult compute_split(const Subdivision& sub, std::uint32_t face, std::uint32_t plan, const SplitOptions& options,
                          const FaceDensity& density, const ResourceGuard* limits) {
  const double area = sub.face_area(face);
  // The working points cap counts the interior pieces too: they are refined alike.
  double perimeter = face_perimeter(sub, face);
  std::size_t vertices = sub.faces[face].inner_segments.size() + sub.faces[face].inner_points.size();
  for (const std::uint32_t seg : sub.faces[face].inner_segments)
    perimeter += distance(sub.points[sub.segments[seg].a], sub.points[sub.segments[seg].b]);
  for (const auto& ring : sub.faces[face].rings) vertices += ring.size();
  const double point_cap =
      std::min(max_working_points, std::max(min_point_cap, points_per_vertex_cap * static_cast<double>(vertices)));
  const double first_spacing = std::sqrt(area) / (points_per_side * options.boundary_refinement);
  double spacing = first_spacing;
  Candidate best;
  SplitTimes times;
  for (int round = 0; round <= options.max_split_retries; ++round, spacing *= 0.5) {
    if (limits != nullptr && round > 0) limits->check(sub.faces.size());
    const double h = std::max(spacing, perimeter / point_cap);
    Candidate c = try_spacing(sub, face, plan, h, round, options, density, times);
    // Refinement that does not improve the balance will not start to: the
    // limit is the shape (where acceptable separators exist), not the spacing.
    const bool stalled = round > 0 && c.quality < best.quality + 0.01;
    if (c.quality > best.quality) best = std::move(c);
    if (stalled && best.quality >= options.min_split_quality) break;
    if (best.quality >= options.good_balance) break;
    if (h > spacing) break;  // cannot refine further
  }
  // Graded by samples (cases 2 and 3) the chords are weighed as the
  // bisection weighs; boundary vertex weights (case 1) they cannot weigh.
  if (best.quality < chord_trigger && (!density.graded || density.point_weights == nullptr) &&
      static_cast<double>(vertices) <= max_chord_points) {
    if (auto chord = chord_split(sub, face, plan, options, density, best.quality, times)) {
      best.result = std::move(chord->result);
      best.quality = chord->quality;
    }
  }
  // Trying harder before giving up the face: uneven shares, where the only
  // separators meeting Phi0 cut off less than half (a neck near one end),
  // at the first spacings, then other samplings of the boundary.
  for (int k = 0; best.quality < 0.0 && k < uneven_rounds; ++k) {
    if (limits != nullptr) limits->check(sub.faces.size());
    const double h = std::max(first_spacing * std::ldexp(1.0, -k), perimeter / point_cap);
    Candidate c =
        try_spacing(sub, face, plan, h, options.max_split_retries + 1 + k, options, density, times, uneven_fractions);
    if (c.quality > best.quality) best = std::move(c);
  }
  for (std::size_t k = 0; best.quality < options.min_split_quality && k < std::size(offset_spacings); ++k) {
    if (limits != nullptr) limits->check(sub.faces.size());
    const double h = std::max(offset_spacings[k] * first_spacing, perimeter / point_cap);
    Candidate c = try_spacing(sub, face, plan, h, options.max_split_retries + 1 + uneven_rounds + static_cast<int>(k),
                              options, density, times);
    if (c.quality > best.quality) best = std::move(c);
  }
  // Keeping every separator off the isolated points found none: pin them
  // as points where no separator may end (refine_face).
  for (int k = 0; best.quality < 0.0 && !sub.faces[face].inner_points.empty() && k < uneven_rounds; ++k) {
    if (limits != nullptr) limits->check(sub.faces.size());
    const double h = std::max(first_spacing * std::ldexp(1.0, -k), perimeter / point_cap);
    Candidate c = try_spacing(sub, face, plan, h, options.max_split_retries + 1 + k, options, density, times, {}, true);
    if (c.quality > best.quality) best = std::move(c);
  }
  if (best.quality < 0.0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "no separator with angles >= %g degrees found for subdomain %u (area %g)",
                  options.separator_angle_deg, face, area);
    throw DecompositionError(buf, face, area, options.separator_angle_deg);
  }
  best.result.times = times;
  return std::move(best.result);
}

}  // namespace madd::detail
