// verify_mesh, the mesh segments: markers as their decomposition segment's,
// each decomposition segment (separator, boundary or interior piece)
// covered by one chain of its mesh segments from
// its first end to its second, each input segment by one chain of boundary
// and interior segments lying on it up to the rounding of the interpolation that placed
// their vertices, and the points' markers by Triangle's rule. Also bounds
// the area the rounded boundary vertices add to or take from the domain.
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "kernel/bracket.hpp"
#include "kernel/number_format.hpp"
#include "kernel/threads.hpp"
#include "madd/decomposition.hpp"
#include "quality/parallel_log.hpp"
#include "quality/verify_mesh_detail.hpp"

namespace madd::detail {

namespace {

// On a piece of an input segment (boundary or interior): a nonzero marker.
bool on_input_segment(const MeshSegment& g) noexcept { return g.marker != 0; }

// Scratch space for walk_chain, kept across the chains of one part.
struct ChainScratch {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;  // (vertex, position in ids)
  std::vector<std::uint8_t> used;
};

// Walks the chain of mesh segments `ids` from vertex `start` to `end`: at
// each vertex exactly one unused segment goes on, each step advances along
// the direction dir_a -> dir_b (exact sign of the dot product), and every
// segment is used. Calls step(cur, next, along) for each step, along a
// bound on |dot(next - cur, dir_b - dir_a)| (its sign decided by a filter,
// kernel/bracket.hpp, and exactly where the filter cannot tell). Reports and returns false on the
// first break; name() says what the chain is, for that report only.
template <class Name, class Step>
bool walk_chain(const Mesh& m, std::span<const std::uint32_t> ids, std::uint32_t start, std::uint32_t end, Point dir_a,
                Point dir_b, const Name& name, ChainScratch& scratch, ProblemLog& log, Step&& step) {
  if (ids.empty()) {
    log.add(name() + " has no mesh segments");
    return false;
  }
  auto& ends = scratch.ends;
  ends.clear();
  for (std::uint32_t k = 0; k < ids.size(); ++k) {
    ends.push_back({m.segments[ids[k]].a, k});
    ends.push_back({m.segments[ids[k]].b, k});
  }
  std::sort(ends.begin(), ends.end());
  auto& used = scratch.used;
  used.assign(ids.size(), 0);
  std::uint32_t cur = start;
  std::size_t walked = 0;
  while (cur != end) {
    auto it = std::lower_bound(ends.begin(), ends.end(), std::pair<std::uint32_t, std::uint32_t>{cur, 0});
    std::uint32_t next_k = no_index;
    std::size_t choices = 0;
    for (; it != ends.end() && it->first == cur; ++it)
      if (used[it->second] == 0) {
        next_k = it->second;
        ++choices;
      }
    if (choices != 1) {
      log.add(name() + "'s mesh segments " + (choices == 0 ? "stop" : "branch") + " at vertex " + std::to_string(cur) +
              " " + point_text(m.points[cur]) + " instead of forming one chain to vertex " + std::to_string(end) + " " +
              point_text(m.points[end]));
      return false;
    }
    used[next_k] = 1;
    const MeshSegment& g = m.segments[ids[next_k]];
    const std::uint32_t next = g.a == cur ? g.b : g.a;
    const Bracket quick = dot_of_differences_bracket(m.points[next], m.points[cur], dir_b, dir_a);
    double along = quick.magnitude_bound();
    if (!quick.certainly_positive()) {
      const ExactSum exact = dot_of_differences_exact(m.points[next], m.points[cur], dir_b, dir_a);
      if (exact.sign() <= 0) {
        log.add("mesh segment " + std::to_string(ids[next_k]) + " runs backwards along " + name() + " (from " +
                point_text(m.points[cur]) + " to " + point_text(m.points[next]) + ")");
        return false;
      }
      along = exact.magnitude_bound();
    }
    step(cur, next, along);
    cur = next;
    ++walked;
  }
  if (walked != ids.size()) {
    log.add(name() + " has " + std::to_string(ids.size() - walked) + " mesh segments off its chain from vertex " +
            std::to_string(start) + " to vertex " + std::to_string(end));
    return false;
  }
  return true;
}

// Mesh segment indices grouped by key (no_index: left out), stable.
std::vector<std::uint32_t> grouped(const std::vector<std::uint32_t>& key, std::vector<std::uint32_t>& first,
                                   std::size_t groups) {
  first.assign(groups + 1, 0);
  for (const std::uint32_t k : key)
    if (k != no_index) ++first[k + 1];
  for (std::size_t g = 0; g < groups; ++g) first[g + 1] += first[g];
  std::vector<std::uint32_t> out(first[groups]);
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for (std::uint32_t s = 0; s < key.size(); ++s)
    if (key[s] != no_index) out[fill[key[s]]++] = s;
  return out;
}

void check_markers(const Mesh& m, ProblemLog& log, unsigned threads) {
  const Decomposition& d = m.decomposition;
  for (std::uint32_t s = 0; s < m.segments.size(); ++s) {
    const MeshSegment& g = m.segments[s];
    const bool separator = d.is_separator(g.piece);
    const int want = separator ? 0 : d.segments[g.piece].marker;
    if (g.marker != want || (!separator && want == 0))
      log.add("mesh segment " + std::to_string(s) + " on " + (separator ? "separator " : "boundary piece ") +
              std::to_string(g.piece) + " has marker " + std::to_string(g.marker) + ", expected " +
              (separator   ? "0"
               : want == 0 ? "nonzero"
                           : std::to_string(want)));
  }
  // Triangle's rule: a point's marker is that of the boundary segment it
  // lies on, the larger at a corner of two; 0 inside and on separators only.
  std::vector<int> want(m.points.size(), 0);
  std::vector<std::uint8_t> on_boundary(m.points.size(), 0);
  for (const MeshSegment& g : m.segments) {
    if (!on_input_segment(g)) continue;
    for (const std::uint32_t v : {g.a, g.b}) {
      want[v] = on_boundary[v] != 0 ? std::max(want[v], g.marker) : g.marker;
      on_boundary[v] = 1;
    }
  }
  const std::size_t parts = 4 * std::size_t{thread_count(threads, m.points.size())};
  log_in_parts(
      m.points.size(), parts, threads, log, [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& mine) {
        for (auto p = static_cast<std::uint32_t>(begin); p < end; ++p)
          if (m.point_markers[p] != want[p])
            mine.add("point " + std::to_string(p) + " " + point_text(m.points[p]) + " has marker " +
                     std::to_string(m.point_markers[p]) + ", expected " + std::to_string(want[p]) +
                     (on_boundary[p] != 0 ? " (the largest of its boundary segments')" : " (on no boundary segment)"));
      });
}

// Sum over the boundary edges pq of input segment ab of (|h_p| + |h_q|) |dt|,
// h the exact cross(w, . - a) and dt the exact dot(q - p, w) (w = b - a),
// over |w|^2: the trapezoid bound on twice the area between the chain and
// ab, as verify_decomposition's check_boundary_pieces derives it for the
// decomposition's pieces (the mesh's boundary chain is theirs, cut further).
struct Sliver {
  double sum = 0.0;
  std::size_t terms = 0;
};

void check_input_segment(const Mesh& m, const Pslg& domain, std::uint32_t input, std::span<const std::uint32_t> ids,
                         ChainScratch& scratch, Sliver& sliver, ProblemLog& log) {
  const Segment& whole = domain.segments[input];
  const Point a = domain.points[whole.a], b = domain.points[whole.b];
  const auto name = [input] { return "input segment " + std::to_string(input); };
  // Every vertex on ab was put there by interpolating two earlier ones
  // (discretise, then the mesher's splits), as the decomposition's were, so
  // the bound for ab cut into ids.size() pieces holds for all of them.
  const double allowed = off_line_bound(a, b, ids.size());
  const double length2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
  double off_cur = 0.0;  // |cross| at the current vertex; 0 at a
  walk_chain(m, ids, whole.a, whole.b, a, b, name, scratch, log, [&](std::uint32_t, std::uint32_t next, double along) {
    double off_next = 0.0;
    if (next != whole.b) {
      const Bracket quick = triangle_twice_area_bracket(a, b, m.points[next]);
      off_next = quick.magnitude_bound();
      if (!quick.certainly_at_most(allowed)) {
        const ExactSum cross = triangle_twice_area_exact(a, b, m.points[next]);
        off_next = cross.magnitude_bound();
        if (!cross.magnitude_at_most(allowed))
          log.add("boundary vertex " + std::to_string(next) + " " + point_text(m.points[next]) + " leaves " + name() +
                  " (off by " + number_text(std::abs(cross.approximate()) / std::sqrt(length2)) + ", more than the " +
                  number_text(allowed / std::sqrt(length2)) + " its interpolation can round to)");
      }
    }
    if (off_cur + off_next > 0.0) {
      sliver.sum += (off_cur + off_next) * along / length2;
      ++sliver.terms;
    }
    off_cur = off_next;
  });
}

}  // namespace

// The chains in parts of consecutive segments on the threads (log_in_parts:
// the report of one pass in segment order). The input segments' sliver
// bound is summed in a fixed number of parts, whatever the thread count, so
// that it is the same number for any count (its terms are >= 0: the
// rounding bound below holds for any order of summation).
double check_mesh_segments(const Mesh& m, const Pslg& domain, ProblemLog& log, unsigned threads) {
  const Decomposition& d = m.decomposition;
  check_markers(m, log, threads);
  // Each decomposition segment: one chain of its mesh segments from a to b.
  std::vector<std::uint32_t> key(m.segments.size());
  for (std::uint32_t s = 0; s < m.segments.size(); ++s) key[s] = m.segments[s].piece;
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> by_piece = grouped(key, first, d.segments.size());
  const std::vector<std::uint32_t> owner = interior_segment_owners(d);
  const std::size_t parts = 4 * std::size_t{thread_count(threads, d.segments.size())};
  log_in_parts(
      d.segments.size(), parts, threads, log, [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& mine) {
        ChainScratch scratch;
        for (auto j = static_cast<std::uint32_t>(begin); j < end; ++j) {
          const Segment& g = d.segments[j];
          const auto name = [&d, &owner, j] {
            const char* kind = d.is_separator(j)      ? "separator "
                               : owner[j] != no_index ? "interior piece "
                                                      : "boundary piece ";
            return std::string(kind) + std::to_string(j);
          };
          walk_chain(m, std::span<const std::uint32_t>(by_piece).subspan(first[j], first[j + 1] - first[j]), g.a, g.b,
                     d.points[g.a], d.points[g.b], name, scratch, mine, [](std::uint32_t, std::uint32_t, double) {});
        }
      });
  // Each input segment: one chain of the boundary segments on its pieces.
  for (std::uint32_t s = 0; s < m.segments.size(); ++s)
    key[s] = on_input_segment(m.segments[s]) ? d.segment_origin[m.segments[s].piece] : no_index;
  const std::vector<std::uint32_t> by_input = grouped(key, first, domain.segments.size());
  constexpr std::size_t sliver_parts = 64;
  std::vector<Sliver> sliver_of(sliver_parts);
  log_in_parts(domain.segments.size(), sliver_parts, threads, log,
               [&](std::size_t part, std::size_t begin, std::size_t end, ProblemLog& mine) {
                 ChainScratch scratch;
                 for (auto i = static_cast<std::uint32_t>(begin); i < end; ++i)
                   check_input_segment(
                       m, domain, i,
                       std::span<const std::uint32_t>(by_input).subspan(first[i], first[i + 1] - first[i]), scratch,
                       sliver_of[part], mine);
               });
  Sliver sliver;
  for (const Sliver& part : sliver_of) sliver.sum += part.sum, sliver.terms += part.terms;
  // Each term: a sum, a product, a quotient and |w|^2's 4 roundings; then the sum.
  return rounded_up(sliver.sum, sliver.terms + 7);
}

}  // namespace madd::detail
