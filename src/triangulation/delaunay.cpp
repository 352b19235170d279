// Incremental Delaunay triangulation: Bowyer-Watson cavity insertion in a
// BRIO/Hilbert order, with a remembering visibility walk to locate each point.
// Ghost triangles (Shewchuk's "ghost vertex") make hull insertion the same
// operation as interior insertion: a ghost triangle over hull edge ab is in
// conflict with p when p lies strictly outside ab or inside the open segment.
#include <algorithm>
#include <string>

#include "triangulation/cavity.hpp"
#include "triangulation/cdt.hpp"
#include "triangulation/hilbert.hpp"
#include "triangulation/walk.hpp"
#include "madd/error.hpp"
#include "madd/predicates.hpp"

namespace madd::detail {

namespace {

// a and b are input indices.
[[noreturn]] void throw_duplicate(std::span<const Point> input, std::uint32_t a, std::uint32_t b) {
  const Point p = input[a];
  throw InvalidInputError(InputProblem::duplicate_vertex,
                          "duplicate vertex: points " + std::to_string(std::min(a, b)) + " and " +
                              std::to_string(std::max(a, b)) + " are both (" + std::to_string(p.x) + ", " +
                              std::to_string(p.y) + ")",
                          {std::min(a, b), std::max(a, b)}, {p});
}

// Works on vertex numbers that are insertion ranks: points[rank] is input
// point order[rank], so consecutive insertions touch nearby memory.
class Inserter {
public:
  // Every insertion adds two triangles (ghosts included): 2n - 2 in the end.
  // The cavity's scratch is allocated before the arrays, as it was before the
  // core was shared: the heap then lays them out alike, and repeated runs
  // (glibc keeps freed memory once its mmap threshold has grown) peak no
  // higher.
  Inserter(HalfEdgeMesh& mesh, std::span<const Point> points, std::span<const std::uint32_t> order)
      : m_(mesh), P_(points), order_(order) {
    const std::size_t triangles = 2 * points.size() - 2;
    cavity_.reserve(triangles, points.size() + 1);
    m_.reserve(triangles);
  }

  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  void insert(std::uint32_t v);

private:
  HalfEdgeMesh& m_;
  std::span<const Point> P_;
  std::span<const std::uint32_t> order_;
  Cavity cavity_{Cavity::SlotOrder::examined};
  WalkRandom random_;
  std::uint32_t last_ = 0;  // remembering walk: start where the last insertion ended
};

void Inserter::start(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const std::uint32_t g = m_.ghost;
  const std::uint32_t init[12] = {a, b, c, b, a, g, c, b, g, a, c, g};
  m_.append_slots(4);
  std::copy(init, init + 12, m_.tv.begin());
  m_.link(2, 3 + 2);      // a->b : ghost (b,a,g)
  m_.link(0, 6 + 2);      // b->c : ghost (c,b,g)
  m_.link(1, 9 + 2);      // c->a : ghost (a,c,g)
  m_.link(3 + 0, 9 + 1);  // (a,g) | (g,a)
  m_.link(6 + 0, 3 + 1);  // (b,g) | (g,b)
  m_.link(9 + 0, 6 + 1);  // (c,g) | (g,c)
  last_ = 0;
}

void Inserter::insert(std::uint32_t v) {
  const Point p = P_[v];
  const std::uint32_t t = walk_visibly(m_, P_, p, last_, random_).triangle;
  if (t == no_index) throw InternalError("triangulate: internal error: point location failed");
  if (!m_.is_ghost(t)) {
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t u = m_.tv[3 * t + k];
      if (P_[u] == p) throw_duplicate(P_, order_[u], order_[v]);
    }
  }
  last_ = cavity_.insert(m_, P_, t, p, v).front();
}

// Chooses the first three non-collinear points of `order` as the starting
// triangle. Returns false when all points are collinear.
bool pick_start(std::span<const Point> P, std::vector<std::uint32_t>& order) {
  const std::size_t n = order.size();
  std::size_t j = 1;
  while (j < n && P[order[j]] == P[order[0]]) throw_duplicate(P, order[0], order[j]);
  std::size_t k = j + 1;
  while (k < n && orient2d(P[order[0]], P[order[j]], P[order[k]]) == 0) ++k;
  if (k >= n) return false;
  // Keep the walk-friendly order: move order[k] right after order[j].
  std::rotate(order.begin() + static_cast<std::ptrdiff_t>(j + 1), order.begin() + static_cast<std::ptrdiff_t>(k),
              order.begin() + static_cast<std::ptrdiff_t>(k + 1));
  return true;
}

// All points collinear: no triangle, but duplicates must still be reported.
void check_collinear_duplicates(std::span<const Point> P) {
  std::vector<std::uint32_t> idx(P.size());
  for (std::uint32_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](std::uint32_t a, std::uint32_t b) {
    return P[a].x < P[b].x || (P[a].x == P[b].x && (P[a].y < P[b].y || (P[a].y == P[b].y && a < b)));
  });
  for (std::size_t i = 1; i < idx.size(); ++i) {
    if (P[idx[i]] == P[idx[i - 1]]) throw_duplicate(P, idx[i - 1], idx[i]);
  }
}

}  // namespace

bool build_delaunay(HalfEdgeMesh& mesh, std::span<const Point> input) {
  mesh = HalfEdgeMesh{};
  // Half-edge ids (3 per triangle, 2n triangles) must fit in 32 bits.
  if (input.size() >= (std::size_t{no_index} - 16) / 6) {
    throw InvalidInputError(InputProblem::other,
                            "too many points for 32-bit triangle indices: " + std::to_string(input.size()));
  }
  mesh.ghost = static_cast<std::uint32_t>(input.size());
  if (input.size() < 3) {
    check_collinear_duplicates(input);
    return false;
  }
  std::vector<std::uint32_t> order = insertion_order(input);
  if (!pick_start(input, order)) {
    check_collinear_duplicates(input);
    return false;
  }
  if (orient2d(input[order[0]], input[order[1]], input[order[2]]) < 0) std::swap(order[1], order[2]);
  const auto n = static_cast<std::uint32_t>(order.size());
  {
    std::vector<Point> sorted(n);
    for (std::uint32_t i = 0; i < n; ++i) sorted[i] = input[order[i]];
    Inserter ins(mesh, sorted, order);
    ins.start(0, 1, 2);
    for (std::uint32_t i = 3; i < n; ++i) ins.insert(i);
  }
  // Back to input indices; the ghost (n) is the same in both numberings.
  for (std::uint32_t& v : std::span(mesh.tv).first(3 * std::size_t{mesh.slot_count()})) {
    if (v != mesh.ghost) v = order[v];
  }
  return true;
}

}  // namespace madd::detail
