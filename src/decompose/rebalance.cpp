// The balance repair (rebalance.hpp): merge the largest subdomain with its
// smaller neighbours, split the union again, keep it when it helps.
#include "decompose/rebalance.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <optional>
#include <span>
#include <unordered_set>
#include <utility>
#include <vector>

#include "decompose/grading.hpp"
#include "kernel/box.hpp"
#include "kernel/threads.hpp"
#include "madd/error.hpp"

namespace madd::detail {

namespace {

// The faces across the separators of `face`, the smallest first (ties: lower id).
std::vector<std::uint32_t> neighbours_by_area(const Subdivision& sub, std::uint32_t face,
                                              const std::vector<double>& area) {
  std::vector<std::uint32_t> out;
  for (const auto& ring : sub.faces[face].ring_segments) {
    for (const std::uint32_t seg : ring) {
      for (const std::uint32_t f : sub.seg_faces[seg]) {
        if (f != face && f != no_index) out.push_back(f);
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  std::sort(out.begin(), out.end(),
            [&](std::uint32_t x, std::uint32_t y) { return area[x] != area[y] ? area[x] < area[y] : x < y; });
  return out;
}

// Splits `face` into `plan` subdomains as the N-way driver would (one face
// at a time); the new faces are appended. Throws DecompositionError.
void split_into(Subdivision& sub, std::uint32_t face, std::uint32_t plan, const SplitOptions& split_options,
                const ResourceGuard& guard, const FaceMeasure& measure) {
  if (plan < 2) return;
  const FaceDensity density = measure.density ? measure.density(sub, face) : FaceDensity{};
  const SplitResult r = compute_split(sub, face, plan, split_options, density, &guard);
  const std::uint32_t k0 = side0_plan(plan, r.weight[0], r.weight[1]);
  const std::uint32_t added = sub.commit(face, r);
  split_into(sub, face, k0, split_options, guard, measure);
  split_into(sub, added, plan - k0, split_options, guard, measure);
}

double weight_of(const Subdivision& sub, std::uint32_t face, const FaceMeasure& measure) {
  return measure.weight ? measure.weight(sub, face) : sub.face_area(face);
}

struct Repair {
  Subdivision sub;
  double largest = 0.0;       // the largest of the new subdomains
  double added_length = 0.0;  // separator length inside the union, after minus before
};

// Total length of the separators between two faces of `faces`.
double inner_separator_length(const Subdivision& sub, const std::vector<std::uint32_t>& faces) {
  const auto in = [&](std::uint32_t f) { return std::find(faces.begin(), faces.end(), f) != faces.end(); };
  double length = 0.0;
  for (std::uint32_t s = 0; s < sub.segments.size(); ++s) {
    if (in(sub.seg_faces[s][0]) && in(sub.seg_faces[s][1]))
      length += distance(sub.points[sub.segments[s].a], sub.points[sub.segments[s].b]);
  }
  return length;
}

// The density the union of `faces` is split by, its samples recalibrated to
// the measure's weights: each face's samples scaled so that its density
// (r x area + a x samples) takes the union's density in the share its weight
// takes of the union's weight. A graded measure's weight (madd mesh: the
// face's expected triangles) and its samples (merged per grid cell, without
// the pinches' clusters) disagree by up to a fifth of a subdomain at N =
// 256; split by the samples alone, a union of a face the weight calls heavy
// with a neighbour was cut where its faces met, the repair never kept (Lake
// Vanern (b) at N = 256 kept 4 of 64 tries).
FaceDensity calibrated_density(const Subdivision& sub, std::span<const std::uint32_t> faces,
                               const FaceMeasure& measure) {
  std::vector<FaceDensity> parts;
  std::vector<double> weight, sampled, density;
  double weight_sum = 0.0, density_sum = 0.0;
  for (const std::uint32_t f : faces) {
    parts.push_back(measure.density(sub, f));
    double samples = 0.0;
    for (const ValuedPoint& p : parts.back().samples) samples += p.value;
    sampled.push_back(samples);
    weight.push_back(weight_of(sub, f, measure));
    density.push_back(parts.back().r * sub.face_area(f) + parts.back().a * samples);
    weight_sum += weight.back();
    density_sum += density.back();
  }
  FaceDensity out = parts[0];
  out.samples.clear();
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const FaceDensity& part = parts[k];
    const double wanted = weight_sum > 0.0 ? density_sum * weight[k] / weight_sum : density[k];
    double scale = 1.0;
    if (sampled[k] > 0.0 && part.a > 0.0)
      scale = std::max(0.0, (wanted - part.r * sub.face_area(faces[k])) / (part.a * sampled[k]));
    if (!std::isfinite(scale)) scale = 1.0;
    for (const ValuedPoint& p : part.samples) out.samples.push_back({p.at, p.value * scale});
  }
  return out;
}

// `measure` with the density of `union_density` (each face its samples inside it).
FaceMeasure with_density(const FaceMeasure& measure, FaceDensity union_density) {
  FaceMeasure out = measure;
  out.density = [union_density = std::move(union_density)](const Subdivision& s, std::uint32_t f) {
    FaceDensity d{union_density.graded, union_density.r, union_density.a, union_density.point_weights, {}};
    Box around;  // the outer ring's box: a sample outside it is in no hole's face either
    for (const std::uint32_t v : s.faces[f].rings[0]) around.add(s.points[v]);
    for (const ValuedPoint& p : union_density.samples)
      if (around.contains(p.at) && point_in_face(s, f, p.at)) d.samples.push_back(p);
    return d;
  };
  return out;
}

// In a copy of `sub`: merges `face` with `partners` and splits the union into
// as many subdomains as it was made of (by the calibrated density when the
// measure is graded).
std::optional<Repair> try_repair(const Subdivision& sub, std::uint32_t face, std::span<const std::uint32_t> partners,
                                 const SplitOptions& split_options, const ResourceGuard& guard,
                                 const FaceMeasure& measure) {
  Repair out{sub, 0.0};
  const auto before = static_cast<std::uint32_t>(sub.faces.size());
  FaceMeasure split_measure = measure;
  if (measure.weight && measure.density) {
    std::vector<std::uint32_t> faces{face};
    faces.insert(faces.end(), partners.begin(), partners.end());
    split_measure = with_density(measure, calibrated_density(sub, faces, measure));
  }
  // Merged one at a time, each with a partner that touches the union so far.
  std::vector<std::uint32_t> left(partners.begin(), partners.end());
  std::uint32_t merged = face;
  while (!left.empty()) {
    bool progress = false;
    for (std::size_t k = 0; k < left.size(); ++k) {
      const auto last = static_cast<std::uint32_t>(out.sub.faces.size() - 1);
      const std::uint32_t partner = left[k];
      if (!out.sub.merge(merged, partner)) continue;
      // merge() keeps the lower id and moves the last face into the other one.
      const std::uint32_t keep = std::min(merged, partner), gone = std::max(merged, partner);
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      for (std::uint32_t& id : left) {
        if (id == last) id = gone;
      }
      merged = keep;
      progress = true;
      break;
    }
    if (!progress) return std::nullopt;
  }
  try {
    split_into(out.sub, merged, static_cast<std::uint32_t>(partners.size() + 1), split_options, guard, split_measure);
  } catch (const DecompositionError&) {
    return std::nullopt;  // no valid separator for the union: try other partners
  }
  std::vector<std::uint32_t> old_faces{face}, new_faces{merged};
  old_faces.insert(old_faces.end(), partners.begin(), partners.end());
  out.largest = weight_of(out.sub, merged, measure);
  for (std::uint32_t f = before - static_cast<std::uint32_t>(partners.size()); f < before; ++f) {
    out.largest = std::max(out.largest, weight_of(out.sub, f, measure));
    new_faces.push_back(f);
  }
  out.added_length = inner_separator_length(out.sub, new_faces) - inner_separator_length(sub, old_faces);
  return out;
}

// A hash of the points of `face`'s rings, in order.
std::uint64_t ring_key(const Subdivision& sub, std::uint32_t face) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the coordinates' bits
  const auto mix = [&h](std::uint64_t x) {
    for (int i = 0; i < 8; ++i) h = (h ^ ((x >> (8 * i)) & 0xff)) * 1099511628211ull;
  };
  for (const auto& ring : sub.faces[face].rings) {
    for (const std::uint32_t v : ring) {
      mix(std::bit_cast<std::uint64_t>(sub.points[v].x));
      mix(std::bit_cast<std::uint64_t>(sub.points[v].y));
    }
    mix(~std::uint64_t{0});  // between rings
  }
  return h;
}

// The partners to merge `face` with, in the order they are tried: one
// neighbour (the smallest first), then two faces to split in three (two of
// its neighbours, or a neighbour and that neighbour's smallest other
// neighbour), which leaves more room for the cuts where the pair alone has
// one acceptable separator (an island near it, a neck); last the face's
// sibling, since their union is the face whose split made it and would most
// likely split the same way again. Only unions whose even shares would be
// at most `improved` are listed.
std::vector<std::vector<std::uint32_t>> candidate_unions(const Subdivision& sub, std::uint32_t face,
                                                         const std::vector<double>& area, double improved,
                                                         const RebalanceOptions& options) {
  const std::vector<std::uint32_t> around = neighbours_by_area(sub, face, area);
  const std::size_t near = std::min<std::size_t>(around.size(), options.partners);
  const std::uint32_t sibling = sub.faces[face].sibling;
  std::vector<std::vector<std::uint32_t>> unions;
  for (std::size_t k = 0; k < near; ++k) {
    if (around[k] != sibling && 0.5 * (area[face] + area[around[k]]) <= improved) unions.push_back({around[k]});
  }
  const auto add_triple = [&](std::uint32_t a, std::uint32_t b) {
    if (a == b || b == face || (area[face] + area[a] + area[b]) / 3.0 > improved) return;
    std::vector<std::uint32_t> t{std::min(a, b), std::max(a, b)};
    if (std::find(unions.begin(), unions.end(), t) == unions.end()) unions.push_back(std::move(t));
  };
  for (std::size_t i = 0; i < near; ++i) {
    for (std::size_t j = i + 1; j < near; ++j) add_triple(around[i], around[j]);
  }
  for (std::size_t k = 0; k < near; ++k) {
    for (const std::uint32_t next : neighbours_by_area(sub, around[k], area)) {
      if (next == face) continue;
      add_triple(around[k], next);
      break;
    }
  }
  // A face at the end of a bay, with one neighbour as heavy as itself,
  // cannot shed weight into two or three faces: then it and a chain of
  // three (its neighbour, that one's lightest other neighbour, and that
  // one's) split in four (the Maine coast's graded field at N = 64: a face
  // 1.16 x the mean, 1.11 after).
  if (unions.size() < 3) {
    for (std::size_t k = 0; k < near; ++k) {
      std::vector<std::uint32_t> chain{around[k]};
      double weight = area[face] + area[around[k]];
      while (chain.size() < 3) {
        std::uint32_t next = no_index;
        for (const std::uint32_t f : neighbours_by_area(sub, chain.back(), area)) {
          if (f != face && std::find(chain.begin(), chain.end(), f) == chain.end()) {
            next = f;
            break;
          }
        }
        if (next == no_index) break;
        chain.push_back(next);
        weight += area[next];
      }
      if (chain.size() < 3 || weight / 4.0 > improved) continue;
      std::sort(chain.begin(), chain.end());
      if (std::find(unions.begin(), unions.end(), chain) == unions.end()) unions.push_back(std::move(chain));
    }
  }
  const auto near_end = around.begin() + static_cast<std::ptrdiff_t>(near);
  if (std::find(around.begin(), near_end, sibling) != near_end && 0.5 * (area[face] + area[sibling]) <= improved)
    unions.push_back({sibling});
  return unions;
}

}  // namespace

std::uint32_t rebalance(Subdivision& sub, const SplitOptions& split_options_in, const ResourceGuard& guard,
                        const RebalanceOptions& options, const FaceMeasure& measure) {
  // One refinement round for the repair splits: on every run of the sweeps
  // (docs/performance.md) the result is the same as with four, in less time.
  SplitOptions split_options = split_options_in;
  split_options.max_split_retries = std::min(split_options.max_split_retries, 1);
  const auto n = static_cast<std::uint32_t>(sub.faces.size());
  if (n < 2) return 0;
  // `area` holds what is balanced: the areas, or the measure's weights.
  // Each face's weight on the threads (a graded measure integrates the
  // field over the face), summed in face order.
  std::vector<double> area(n);
  const auto weigh_all = [&] {
    for_each_on_threads(n, options.threads,
                        [&](std::size_t f) { area[f] = weight_of(sub, static_cast<std::uint32_t>(f), measure); });
  };
  weigh_all();
  double total = 0.0, total_area = 0.0;
  for (std::uint32_t f = 0; f < n; ++f) {
    total += area[f];
    total_area += sub.face_area(f);
  }
  const double bound = options.target * total / n;
  const double max_added_length = options.max_added_separator * std::sqrt(total_area / n);
  // A face that could not be improved is not tried again until its rings
  // change (by its rings' points: a repair moves face ids, and resetting
  // every face after each repair spent the tries on the same faces again).
  std::unordered_set<std::uint64_t> tried;
  std::uint32_t repairs = 0;
  const std::uint32_t max_attempts = std::max<std::uint32_t>(32, n / 4);
  for (std::uint32_t attempts = 0; attempts < max_attempts;) {
    // The heaviest face above the bound not tried as it is (keys are
    // hashed only for faces in that order, heaviest first).
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t x, std::uint32_t y) { return area[x] != area[y] ? area[x] > area[y] : x < y; });
    std::int64_t worst = -1;
    for (const std::uint32_t f : order) {
      if (area[f] <= bound) break;
      if (tried.empty() || !tried.contains(ring_key(sub, f))) {
        worst = f;
        break;
      }
    }
    if (worst < 0) break;
    const auto face = static_cast<std::uint32_t>(worst);
    const double improved = (1.0 - options.min_gain) * area[face];
    const std::vector<std::vector<std::uint32_t>> unions = candidate_unions(sub, face, area, improved, options);
    // The unions tried a batch at a time on the threads (each repair on its
    // own copy of sub), then weighed in order as one thread trying them one
    // by one would, down to where it would have stopped: the same repair for
    // any thread count, at the cost of at most a batch's tries beyond it.
    std::optional<Repair> best;
    const std::size_t batch = thread_count(options.threads, unions.size());
    bool enough = false;
    for (std::size_t first = 0; first < unions.size() && !enough && attempts < max_attempts; first += batch) {
      const std::size_t count = std::min({batch, unions.size() - first, std::size_t{max_attempts - attempts}});
      std::vector<std::optional<Repair>> batch_repairs(count);
      for_each_on_threads(count, options.threads, [&](std::size_t i) {
        guard.check(n);
        batch_repairs[i] = try_repair(sub, face, unions[first + i], split_options, guard, measure);
      });
      for (std::optional<Repair>& repair : batch_repairs) {
        ++attempts;
        if (!repair || repair->largest > improved || repair->added_length > max_added_length) continue;
        if (!best || repair->largest < best->largest) best = std::move(repair);
        if (best->largest <= bound) {
          enough = true;
          break;
        }
      }
    }
    if (!best) {
      tried.insert(ring_key(sub, face));
      continue;
    }
    sub = std::move(best->sub);
    weigh_all();
    ++repairs;
  }
  sub.compact();
  return repairs;
}

}  // namespace madd::detail
