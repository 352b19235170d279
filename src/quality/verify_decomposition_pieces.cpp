// verify_decomposition, the boundary pieces: each input segment's pieces lie
// on it up to the rounding of the interpolation that placed their vertices,
// form one chain from its first end to its second, and carry its marker. Also
// bounds the area the rounded vertices can add to or take from the domain.
#include <algorithm>
#include <cmath>
#include <utility>

#include "kernel/exact_sum.hpp"
#include "kernel/number_format.hpp"
#include "madd/decomposition.hpp"
#include "quality/verify_decomposition_detail.hpp"

namespace madd::detail {

namespace {
constexpr double eps = 0x1p-53;  // unit roundoff
}  // namespace

// How far a vertex on a piece of input segment ab may lie from the line ab,
// times |b - a|: a bound on |cross(b - a, p - a)| over the vertices of the k
// pieces ab was cut into.
//
// Every vertex madd puts on an input segment is p = lerp(s0, s1, t), t in
// [0, 1], s0 and s1 the ends of the piece being refined (src/split/refine.cpp),
// so its depth (ends are depth 0, p is one deeper than its deeper end) is at
// most k - 1, the number of vertices on ab. Per coordinate, p.x =
// fl(s0.x + fl(t fl(s1.x - s0.x))) differs from the point X of the chord
// s0 s1 at parameter t by at most gamma_2 (|s1.x - s0.x| + |p.x|)
// (two relative errors on t (s1.x - s0.x), one on the sum, which is p.x / (1 + delta)),
// gamma_2 = 2 eps / (1 - 2 eps). X lies no farther from the line than s0 or
// s1 (the distance to a line is affine along a chord), and the error moves p
// off the line by its component along the unit normal (-w.y, w.x) / |w|,
// w = b - a. Writing W = |w.x|, H = |w.y|, X0 = max(|a.x|, |b.x|), Y0 likewise
// and D for the farthest any vertex on ab lies from the closed segment ab (so
// |s1.x - s0.x| <= W + 2D, |p.x| <= X0 + D), one level adds at most
//   gamma_2 ((W + X0 + 3D) H + (H + Y0 + 3D) W) / |w|
// and, as each level moves p by at most gamma_2 (W + H + X0 + Y0 + 6D),
// D <= k gamma_2 (W + H + X0 + Y0) / (1 - 6 k gamma_2). With k < 2^32 that is
// k gamma_2 (1 + 1e-5) (W + H + X0 + Y0), so over at most k levels
//   |cross(w, p - a)| <= k gamma_2 ((W + X0) H + (H + Y0) W + 7 k eps (W + H + X0 + Y0)(W + H)).
// rounded_up covers gamma_2 / (2 eps) and the at most 14 roundings of this
// expression (W and H are rounded differences). Independent of the domain's
// size or area: near (1e9, 1e9) a unit triangle's pieces stray ~1e-7 from its
// sides, which the former fixed 1e-9 sqrt(area) rejected.
double off_line_bound(Point a, Point b, std::size_t pieces) noexcept {
  const double W = std::abs(b.x - a.x), H = std::abs(b.y - a.y);
  const double X0 = std::max(std::abs(a.x), std::abs(b.x)), Y0 = std::max(std::abs(a.y), std::abs(b.y));
  const double k = static_cast<double>(pieces);
  const double feedback = 7.0 * k * eps * (W + H + X0 + Y0) * (W + H);
  return rounded_up(k * (2.0 * eps) * ((W + X0) * H + (H + Y0) * W + feedback), 16);
}

namespace {

std::string piece_text(std::uint32_t g) { return "boundary piece " + std::to_string(g); }

// The pieces of one input segment (a, b): vertices near the line, one chain
// from a to b that advances along b - a at every step. Adds to `sliver` the
// trapezoid bound on the area between the chain and the segment (see
// check_boundary_pieces) and to `terms` the number of its terms.
void check_one_segment(const Decomposition& d, const Pslg& domain, std::uint32_t input,
                       const std::vector<std::uint32_t>& pieces, ProblemLog& log, double& sliver, std::size_t& terms) {
  const Segment& whole = domain.segments[input];
  const Point a = domain.points[whole.a], b = domain.points[whole.b];
  const std::string name = "input segment " + std::to_string(input);
  if (pieces.empty()) {
    log.add(name + " has no boundary pieces");
    return;
  }
  // |cross(b - a, p - a)| per piece end, exact, and its upper bound.
  const double allowed = off_line_bound(a, b, pieces.size());
  const double length2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);  // 4 roundings below |w|^2
  std::vector<double> off(2 * pieces.size(), 0.0);
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const Segment& piece = d.segments[pieces[j]];
    for (int end = 0; end < 2; ++end) {
      const std::uint32_t v = end == 0 ? piece.a : piece.b;
      if (v == whole.a || v == whole.b) continue;
      const ExactSum cross = triangle_twice_area_exact(a, b, d.points[v]);
      off[2 * j + end] = cross.magnitude_bound();
      if (!cross.magnitude_at_most(allowed))
        log.add(piece_text(pieces[j]) + " leaves " + name + " at " + point_text(d.points[v]) + " (off by " +
                number_text(std::abs(cross.approximate()) / std::sqrt(length2)) + ", more than the " +
                number_text(allowed / std::sqrt(length2)) + " its interpolation can round to)");
    }
  }
  // The chain, walked from a: at each vertex exactly one unused piece goes on,
  // and it advances along b - a (exact sign of the dot product).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;  // (vertex, local piece)
  for (std::uint32_t j = 0; j < pieces.size(); ++j) {
    ends.push_back({d.segments[pieces[j]].a, j});
    ends.push_back({d.segments[pieces[j]].b, j});
  }
  std::sort(ends.begin(), ends.end());
  std::vector<std::uint8_t> used(pieces.size(), 0);
  std::uint32_t cur = whole.a;
  std::size_t walked = 0;
  while (cur != whole.b) {
    auto it = std::lower_bound(ends.begin(), ends.end(), std::pair<std::uint32_t, std::uint32_t>{cur, 0});
    std::uint32_t next_piece = no_index;
    std::size_t choices = 0;
    for (; it != ends.end() && it->first == cur; ++it)
      if (!used[it->second]) {
        next_piece = it->second;
        ++choices;
      }
    if (choices != 1) {
      log.add(name + "'s pieces " + (choices == 0 ? "stop" : "branch") + " at " + point_text(d.points[cur]) +
              " instead of forming one chain to its end " + point_text(b));
      return;
    }
    used[next_piece] = 1;
    const Segment& piece = d.segments[pieces[next_piece]];
    const std::uint32_t next = piece.a == cur ? piece.b : piece.a;
    const ExactSum along = dot_of_differences_exact(d.points[next], d.points[cur], b, a);
    if (along.sign() <= 0) {
      log.add(piece_text(pieces[next_piece]) + " runs backwards along " + name + " (from " + point_text(d.points[cur]) +
              " to " + point_text(d.points[next]) + ")");
      return;
    }
    // (|cross at cur| + |cross at next|) |dot(next - cur, w)| / |w|^2: the
    // trapezoid term of this piece, an upper bound but for 7 roundings.
    const double ends_off = off[2 * next_piece] + off[2 * next_piece + 1];
    if (ends_off > 0.0) {
      sliver += ends_off * along.magnitude_bound() / length2;
      ++terms;
    }
    cur = next;
    ++walked;
  }
  if (walked != pieces.size())
    log.add(name + " has " + std::to_string(pieces.size() - walked) + " pieces off its chain from " + point_text(a) +
            " to " + point_text(b));
}

}  // namespace

// Returns a bound on |twice the area the subdomains cover - twice the
// domain's|, for check of full cover. The subdomains' rings consist of
// separators, each walked once each way (so they cancel exactly), and boundary
// pieces; the domain's rings of the whole input segments. So the two twice-areas differ
// by the sum over input segments ab of twice the signed area between the chain
// a = p_0, ..., p_m = b and ab. In coordinates t along ab and h across it
// (|w| units), with h_0 = h_m = 0, that is sum_i (t_i h_i+1 - t_i+1 h_i)
// = -sum_i (t_i+1 - t_i)(h_i + h_i+1) (the two differ by a telescoping sum),
// at most sum_i |t_i+1 - t_i| (|h_i| + |h_i+1|) in magnitude, where
// h_i = cross(w, p_i - a) / |w| and t_i+1 - t_i = dot(p_i+1 - p_i, w) / |w|,
// all known exactly. A correct decomposition whose boundary vertices were
// rounded off their segments stays within it; a gap or an overlap of any
// greater area does not.
double check_boundary_pieces(const Decomposition& d, const Pslg& domain, ProblemLog& log) {
  std::vector<std::vector<std::uint32_t>> pieces(domain.segments.size());
  for (std::uint32_t g = 0; g < d.segments.size(); ++g) {
    const Segment& piece = d.segments[g];
    const std::uint32_t origin = d.segment_origin[g];
    if (origin == no_index) {
      if (piece.marker != 0)
        log.add("separator segment " + std::to_string(g) + " has marker " + std::to_string(piece.marker));
      continue;
    }
    pieces[origin].push_back(g);
    const Segment& whole = domain.segments[origin];
    const int want = domain.has_segment_markers && whole.marker != 0 ? whole.marker : 1;
    if (piece.marker != want)
      log.add(piece_text(g) + " has marker " + std::to_string(piece.marker) + ", expected " + std::to_string(want));
  }
  double sliver = 0.0;
  std::size_t terms = 0;
  for (std::uint32_t i = 0; i < domain.segments.size(); ++i)
    check_one_segment(d, domain, i, pieces[i], log, sliver, terms);
  // Each term: a sum, a product, a quotient and |w|^2's 4 roundings (a
  // denominator rounded up by at most (1 + eps) per rounding); then the sum.
  return rounded_up(sliver, terms + 7);
}

}  // namespace madd::detail
