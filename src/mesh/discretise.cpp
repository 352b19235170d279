// The decoupling step (docs/mesh.md, "Decoupling"): every segment of the
// decomposition, separator, boundary or interior piece, is split once into pieces no
// longer than the local target length
//
//   h(p) = min(size_factor * sqrt(A(p)), feature_factor * lfs(p)),
//
// A the area bound and lfs the distance to the nearest non-incident feature,
// with the pieces spread so that each holds the same share of the integral of
// 1/h along the segment. The split points are computed once per segment, from
// its two end points in index order, and both subdomains of a separator
// refer to the same points: the meshes of the two sides meet at identical
// vertices by construction.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

#include "madd/mesh.hpp"
#include "kernel/resource_limits.hpp"
#include "kernel/threads.hpp"
#include "mesh/discretise.hpp"
#include "mesh/discretise_rules.hpp"
#include "mesh/feature_distance.hpp"
#include "quality/area_bound.hpp"
#include "mesh/subdomain_regions.hpp"

namespace madd {

namespace detail {
namespace {

// The limits are checked every this many segments, and after a segment
// that took the split points made so far past a multiple of this many.
constexpr std::uint32_t segments_between_checks = 4096;
constexpr std::size_t points_between_checks = std::size_t{1} << 18;

// Parameters in (0, 1) of the split points of segment j, from its lower-index
// end: the integral of 1/h, sampled and summed by the trapezoid rule, split
// into equal shares.
// The target length at p on segment j, before grading from the ends;
// `regional` is the smallest area bound of the regions on j's sides
// (+infinity for none), one more size bound.
double local_target(Point p, const Segment& s, const AreaBound& size, const FeatureDistance& features, double regional,
                    BoundHint* hint = nullptr) {
  double h = feature_factor * features.to_nonincident(p, s.a, s.b);
  if (size.bounded()) {
    const double area = size.area_at(p, hint);
    if (std::isfinite(area)) h = std::min(h, size_factor / (1.0 + size.edge_slope()) * std::sqrt(area));
  }
  if (std::isfinite(regional)) h = std::min(h, size_factor * std::sqrt(regional));
  return h;
}

// Per vertex: the smallest target length of the segments meeting there, at
// that end. A piece next to a vertex is then no longer than the shortest
// piece of any other segment there, plus the grading: where a separator
// (whose local feature size ignores the boundary it ends on) meets short
// boundary pieces, its first pieces are short too, and the triangle between
// them has no reason to be skinny (docs/mesh.md, "Decoupling").
std::vector<double> vertex_targets(const Decomposition& d, const AreaBound& size, const FeatureDistance& features,
                                   const std::vector<double>& regional, unsigned threads) {
  // Each segment's two end targets on the threads (each a search for the
  // nearest feature), then the least at each vertex in segment order.
  std::vector<std::array<double, 2>> ends(d.segments.size());
  for_each_on_threads(d.segments.size(), threads, [&](std::size_t j) {
    const Segment& s = d.segments[j];
    ends[j] = {local_target(d.points[s.a], s, size, features, regional[j]),
               local_target(d.points[s.b], s, size, features, regional[j])};
  });
  std::vector<double> out(d.points.size(), std::numeric_limits<double>::infinity());
  for (std::uint32_t j = 0; j < d.segments.size(); ++j) {
    const Segment& s = d.segments[j];
    out[s.a] = std::min(out[s.a], ends[j][0]);
    out[s.b] = std::min(out[s.b], ends[j][1]);
  }
  return out;
}

// `features` are the features the segment's pieces must resolve: every
// segment, or, for a boundary piece refinement may still split, only the
// separators (see detail::discretise).
std::vector<double> split_parameters(const Decomposition& d, std::uint32_t j, const AreaBound& size,
                                     const FeatureDistance& features, const std::vector<double>& at_vertex,
                                     bool graded_from_ends, double regional) {
  const Segment& s = d.segments[j];
  const std::uint32_t lo = std::min(s.a, s.b), hi = std::max(s.a, s.b);
  const Point a = d.points[lo], b = d.points[hi];
  const double length = distance(a, b);
  BoundHint hint;  // the samples come in order along the segment
  const auto target = [&](double t) {
    const double h = local_target(lerp(a, b, t), s, size, features, regional, &hint);
    if (!graded_from_ends) return h;
    return std::min(h, std::min(at_vertex[lo] + grading * t * length, at_vertex[hi] + grading * (1 - t) * length));
  };
  std::vector<double> density;  // 1/h at the samples, in units of pieces per segment length
  std::size_t samples = 16;
  double pieces = 0;
  for (int pass = 0; pass < 2; ++pass) {
    density.assign(samples + 1, 0.0);
    for (std::size_t i = 0; i <= samples; ++i) {
      const double h = target(static_cast<double>(i) / static_cast<double>(samples));
      density[i] = h > 0 && std::isfinite(h) ? length / h : 0.0;
    }
    pieces = 0;
    for (std::size_t i = 0; i < samples; ++i)
      pieces += 0.5 * (density[i] + density[i + 1]) / static_cast<double>(samples);
    // Resample where the pieces come out finer than the samples.
    const double wanted = std::min(4.0 * pieces, static_cast<double>(max_pieces_per_segment));
    if (pass == 1 || wanted <= static_cast<double>(samples)) break;
    samples = static_cast<std::size_t>(wanted);
  }
  const auto n =
      static_cast<std::size_t>(std::clamp(std::ceil(pieces - 1e-9), 1.0, static_cast<double>(max_pieces_per_segment)));
  std::vector<double> out;
  if (n == 1) return out;
  // Invert the cumulative integral piecewise linearly.
  double cumulative = 0;
  std::size_t i = 0;
  for (std::size_t k = 1; k < n; ++k) {
    const double goal = pieces * static_cast<double>(k) / static_cast<double>(n);
    for (;;) {
      const double step = 0.5 * (density[i] + density[i + 1]) / static_cast<double>(samples);
      if (cumulative + step >= goal || i + 1 == samples) {
        const double f = step > 0 ? std::clamp((goal - cumulative) / step, 0.0, 1.0) : 0.5;
        out.push_back((static_cast<double>(i) + f) / static_cast<double>(samples));
        break;
      }
      cumulative += step;
      ++i;
    }
  }
  // Strictly increasing and inside (0, 1) (equal shares guarantee it but for rounding).
  out.erase(std::remove_if(out.begin(), out.end(), [](double t) { return !(t > 0 && t < 1); }), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace
}  // namespace detail

Decomposition discretise(const Decomposition& decomposition, const MeshSizeOptions& size) {
  return detail::discretise(decomposition, detail::AreaBound(size), true);
}

Decomposition discretise(const Decomposition& decomposition, const Pslg& domain, const MeshSizeOptions& size) {
  return detail::discretise(decomposition, detail::AreaBound(size, &domain), true);
}

Decomposition discretise(const Decomposition& decomposition, const Pslg& domain, const MeshSizeOptions& size,
                         const DecomposeOptions& limits) {
  const detail::ResourceGuard guard({limits.time_limit_seconds, limits.max_memory_bytes,
                                     static_cast<std::uint32_t>(decomposition.subdomains.size())});
  return detail::discretise(decomposition, detail::AreaBound(size, &domain, limits.threads), true, &guard,
                            limits.threads);
}

Decomposition detail::discretise(const Decomposition& decomposition, const AreaBound& field, bool boundary_by_features,
                                 const ResourceGuard* guard, unsigned threads, const RegionView* view) {
  // The features every piece resolves: every segment (interior ones too, so
  // that a narrow gap between an interior segment and the shore is resolved)
  // and every isolated input vertex, as a segment of length 0 (the distance
  // to it is the distance to the point; it shares no end with any piece).
  std::vector<Segment> all_features = decomposition.segments;
  for (const Subdomain& sub : decomposition.subdomains)
    for (const std::uint32_t v : sub.interior_points) all_features.push_back({v, v, 0});
  const detail::FeatureDistance features(decomposition.points, all_features);
  // Regions with an area bound bound the segments beside them too.
  const std::vector<double> regional =
      view != nullptr ? view->segment_area : detail::region_view(decomposition, threads).segment_area;
  const std::vector<double> at_vertex = detail::vertex_targets(decomposition, field, features, regional, threads);
  // Boundary pieces our refinement may split need only resolve the
  // separators near them (the decoupling); elsewhere it splits them itself.
  std::vector<Segment> separators;
  for (std::uint32_t j = 0; j < decomposition.segments.size(); ++j) {
    if (decomposition.is_separator(j)) separators.push_back(decomposition.segments[j]);
  }
  const detail::FeatureDistance separator_features(decomposition.points, separators);
  Decomposition out = decomposition;
  out.segments.clear();
  out.segment_origin.clear();
  // pieces[j]: the new segments of old segment j, from its lower-index end.
  // Each segment's split parameters are its own (the same on any number of
  // threads); the points are numbered in segment order below.
  std::vector<std::vector<double>> split(decomposition.segments.size());
  std::atomic<std::size_t> made{0};  // split points, on all threads
  detail::for_each_on_threads(split.size(), threads, [&](std::size_t j) {
    if (guard != nullptr && j % segments_between_checks == 0) guard->check(0);
    const bool only_separators = !boundary_by_features && !decomposition.is_separator(static_cast<std::uint32_t>(j));
    split[j] = detail::split_parameters(decomposition, static_cast<std::uint32_t>(j), field,
                                        only_separators ? separator_features : features, at_vertex, !only_separators,
                                        regional[j]);
    const std::size_t before = made.fetch_add(split[j].size());
    if (guard != nullptr && (before + split[j].size()) / points_between_checks != before / points_between_checks)
      guard->check(0);
  });
  std::vector<std::vector<std::uint32_t>> pieces(decomposition.segments.size());
  for (std::uint32_t j = 0; j < decomposition.segments.size(); ++j) {
    const Segment& s = decomposition.segments[j];
    const std::uint32_t lo = std::min(s.a, s.b), hi = std::max(s.a, s.b);
    std::uint32_t from = lo;
    for (const double t : split[j]) {
      const auto v = static_cast<std::uint32_t>(out.points.size());
      out.points.push_back(lerp(decomposition.points[lo], decomposition.points[hi], t));
      pieces[j].push_back(static_cast<std::uint32_t>(out.segments.size()));
      out.segments.push_back({from, v, s.marker});
      out.segment_origin.push_back(decomposition.segment_origin[j]);
      from = v;
    }
    pieces[j].push_back(static_cast<std::uint32_t>(out.segments.size()));
    out.segments.push_back({from, hi, s.marker});
    out.segment_origin.push_back(decomposition.segment_origin[j]);
  }
  // Rings: each old segment becomes its pieces, in the ring's direction;
  // interior segments become their pieces (indices increase with j, so the
  // list stays sorted).
  for (Subdomain& sub : out.subdomains) {
    std::vector<std::uint32_t> interior;
    for (const std::uint32_t j : sub.interior_segments)
      interior.insert(interior.end(), pieces[j].begin(), pieces[j].end());
    std::sort(interior.begin(), interior.end());
    sub.interior_segments = std::move(interior);
    for (std::size_t r = 0; r < sub.rings.size(); ++r) {
      std::vector<std::uint32_t> ring, ring_segments;
      for (std::size_t k = 0; k < sub.rings[r].size(); ++k) {
        const std::uint32_t j = sub.ring_segments[r][k];
        const bool forward = sub.rings[r][k] == std::min(decomposition.segments[j].a, decomposition.segments[j].b);
        const std::vector<std::uint32_t>& list = pieces[j];
        for (std::size_t q = 0; q < list.size(); ++q) {
          const std::uint32_t piece = forward ? list[q] : list[list.size() - 1 - q];
          const Segment& p = out.segments[piece];
          ring.push_back(forward ? p.a : p.b);
          ring_segments.push_back(piece);
        }
      }
      sub.rings[r] = std::move(ring);
      sub.ring_segments[r] = std::move(ring_segments);
    }
  }
  return out;
}

std::vector<std::uint32_t> detail::split_separator_pieces(Decomposition& d, const std::vector<std::uint32_t>& pieces) {
  // New segment of each split piece: from the midpoint to the higher-index end.
  std::vector<std::uint32_t> upper(d.segments.size(), no_index);
  for (const std::uint32_t j : pieces) {
    const Segment s = d.segments[j];
    const std::uint32_t lo = std::min(s.a, s.b), hi = std::max(s.a, s.b);
    const auto mid = static_cast<std::uint32_t>(d.points.size());
    d.points.push_back(lerp(d.points[lo], d.points[hi], 0.5));
    d.segments[j] = {lo, mid, s.marker};
    upper[j] = static_cast<std::uint32_t>(d.segments.size());
    d.segments.push_back({mid, hi, s.marker});
    d.segment_origin.push_back(d.segment_origin[j]);
  }
  std::vector<std::uint32_t> changed;
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    Subdomain& sub = d.subdomains[k];
    bool touched = false;
    for (std::size_t r = 0; r < sub.rings.size(); ++r) {
      std::vector<std::uint32_t> ring, segments;
      for (std::size_t i = 0; i < sub.rings[r].size(); ++i) {
        const std::uint32_t v = sub.rings[r][i], j = sub.ring_segments[r][i];
        if (upper[j] == no_index) {
          ring.push_back(v);
          segments.push_back(j);
          continue;
        }
        touched = true;
        const std::uint32_t mid = d.segments[j].b;
        // From the lower end: lower half (j) then upper half; from the higher end, the reverse.
        const bool from_lower = v == d.segments[j].a;
        ring.insert(ring.end(), {v, mid});
        segments.insert(segments.end(), {from_lower ? j : upper[j], from_lower ? upper[j] : j});
      }
      sub.rings[r] = std::move(ring);
      sub.ring_segments[r] = std::move(segments);
    }
    if (touched) changed.push_back(k);
  }
  return changed;
}

}  // namespace madd
