// Incremental Delaunay triangulation: Bowyer-Watson cavity insertion in a
// BRIO/Hilbert order, with a remembering visibility walk to locate each point.
// Ghost triangles (Shewchuk's "ghost vertex") make hull insertion the same
// operation as interior insertion: a ghost triangle over hull edge ab is in
// conflict with p when p lies strictly outside ab or inside the open segment.
#include <algorithm>
#include <string>

#include "triangulation/delaunay_mesh.hpp"
#include "triangulation/hilbert.hpp"
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

// p strictly inside segment ab, given that a, b, p are collinear. Exact: it
// only compares coordinates along an axis on which a and b differ.
bool strictly_between(Point a, Point b, Point p) noexcept {
  if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
  return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

// Works on vertex numbers that are insertion ranks: points[rank] is input
// point order[rank], so consecutive insertions touch nearby memory.
class Inserter {
public:
  // Every insertion adds two triangles (ghosts included): 2n - 2 in the end.
  Inserter(Mesh& mesh, std::span<const Point> points, std::span<const std::uint32_t> order)
      : m_(mesh), P_(points), order_(order), link_(points.size() + 1), in_cavity_(2 * points.size()) {
    m_.tv.resize(3 * (2 * points.size() - 2));
    m_.tn.resize(m_.tv.size());
  }

  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  void insert(std::uint32_t v);

private:
  bool ghost_conflict(std::uint32_t a, std::uint32_t b, Point p) const noexcept;
  bool in_conflict(std::uint32_t t, Point p) const noexcept;
  std::uint32_t locate(std::uint32_t v);
  void dig_cavity(std::uint32_t t0, Point p);
  void fill_cavity(std::uint32_t v);

  struct Rim {
    std::uint32_t a, b, outer;  // cavity boundary edge a->b and its twin outside
  };
  Mesh& m_;
  std::span<const Point> P_;
  std::span<const std::uint32_t> order_;
  std::vector<std::uint32_t> link_;    // per vertex (+ghost): new triangle whose rim edge starts there
  std::vector<std::uint8_t> in_cavity_;
  std::vector<std::uint32_t> stack_, cavity_;
  std::vector<Rim> rim_;
  std::uint32_t used_ = 0;  // triangles in use
  std::uint32_t last_ = 0;  // remembering walk: start where the last insertion ended
  std::uint32_t rng_ = 12345;
};

void Inserter::start(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const std::uint32_t g = m_.ghost;
  const std::uint32_t init[12] = {a, b, c, b, a, g, c, b, g, a, c, g};
  std::copy(init, init + 12, m_.tv.begin());
  used_ = 4;
  m_.link(2, 3 + 2);   // a->b : ghost (b,a,g)
  m_.link(0, 6 + 2);   // b->c : ghost (c,b,g)
  m_.link(1, 9 + 2);   // c->a : ghost (a,c,g)
  m_.link(3 + 0, 9 + 1);  // (a,g) | (g,a)
  m_.link(6 + 0, 3 + 1);  // (b,g) | (g,b)
  m_.link(9 + 0, 6 + 1);  // (c,g) | (g,c)
  last_ = 0;
}

bool Inserter::ghost_conflict(std::uint32_t a, std::uint32_t b, Point p) const noexcept {
  const Point pa = P_[a], pb = P_[b];
  const double o = orient2d(pa, pb, p);
  return o > 0 || (o == 0 && strictly_between(pa, pb, p));
}

bool Inserter::in_conflict(std::uint32_t t, Point p) const noexcept {
  const std::uint32_t a = m_.tv[3 * t], b = m_.tv[3 * t + 1], c = m_.tv[3 * t + 2];
  const std::uint32_t g = m_.ghost;
  if (c == g) return ghost_conflict(a, b, p);
  if (a == g) return ghost_conflict(b, c, p);
  if (b == g) return ghost_conflict(c, a, p);
  return incircle(P_[a], P_[b], P_[c], p) > 0;
}

// Visibility walk from the last insertion. On a Delaunay triangulation it
// always terminates; the rotating first edge only avoids pathological orders.
std::uint32_t Inserter::locate(std::uint32_t v) {
  const Point p = P_[v];
  const std::uint32_t g = m_.ghost;
  std::uint32_t t = last_;
  std::uint32_t came = no_index;  // half-edge we entered through (known side)
  for (;;) {
    const std::uint32_t* tv = &m_.tv[3 * t];
    const int gi = tv[0] == g ? 0 : tv[1] == g ? 1 : tv[2] == g ? 2 : -1;
    if (gi >= 0) {
      const std::uint32_t h = 3 * t + static_cast<std::uint32_t>(gi);
      if (ghost_conflict(m_.origin(h), m_.dest(h), p)) return t;
      came = m_.tn[h];
      t = came / 3;
      continue;
    }
    rng_ = rng_ * 1103515245u + 12345u;
    const std::uint32_t r = (rng_ >> 16) % 3;
    bool moved = false;
    for (std::uint32_t k = 0; k < 3 && !moved; ++k) {
      const std::uint32_t h = 3 * t + (r + k) % 3;
      if (h == came) continue;
      if (orient2d(P_[m_.origin(h)], P_[m_.dest(h)], p) < 0) {
        came = m_.tn[h];
        t = came / 3;
        moved = true;
      }
    }
    if (!moved) {
      for (int k = 0; k < 3; ++k) {
        if (P_[tv[k]] == p) throw_duplicate(P_, order_[tv[k]], order_[v]);
      }
      return t;
    }
  }
}

// Collects the triangles whose circumcircle strictly contains p (a connected,
// star-shaped region) and the half-edges on its rim, with an explicit stack.
void Inserter::dig_cavity(std::uint32_t t0, Point p) {
  cavity_.clear();
  rim_.clear();
  stack_.clear();
  in_cavity_[t0] = 1;
  stack_.push_back(t0);
  while (!stack_.empty()) {
    const std::uint32_t t = stack_.back();
    stack_.pop_back();
    cavity_.push_back(t);
    for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
      const std::uint32_t u = m_.tn[h] / 3;
      if (in_cavity_[u]) continue;
      if (in_conflict(u, p)) {
        in_cavity_[u] = 1;
        stack_.push_back(u);
      } else {
        rim_.push_back({m_.origin(h), m_.dest(h), m_.tn[h]});
      }
    }
  }
}

// Replaces the cavity by the fan of triangles (v, a, b) over its rim edges,
// reusing the cavity's slots first (a cavity of k triangles has k + 2 rim edges).
void Inserter::fill_cavity(std::uint32_t v) {
  const std::size_t k = rim_.size();
  std::uint32_t first = 0;
  for (std::size_t i = 0; i < k; ++i) {
    std::uint32_t s;
    if (i < cavity_.size()) {
      s = cavity_[i];
      in_cavity_[s] = 0;
    } else {
      s = used_++;
    }
    if (i == 0) first = s;
    const Rim& r = rim_[i];
    m_.tv[3 * s] = v;
    m_.tv[3 * s + 1] = r.a;
    m_.tv[3 * s + 2] = r.b;
    m_.link(3 * s, r.outer);
    link_[r.a] = s;  // the ghost is vertex n: link_ has n + 1 entries
  }
  // Edge 1 (b -> v) of the triangle over a->b meets edge 2 (v -> b) of the one over b->c.
  for (std::size_t i = 0; i < k; ++i) {
    const std::uint32_t s = m_.tn[rim_[i].outer] / 3;
    const std::uint32_t b = rim_[i].b;
    m_.link(3 * s + 1, 3 * link_[b] + 2);
  }
  last_ = first;
}

void Inserter::insert(std::uint32_t v) {
  const std::uint32_t t = locate(v);
  dig_cavity(t, P_[v]);
  fill_cavity(v);
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

} // namespace

bool build_delaunay(Mesh& mesh, std::span<const Point> input) {
  mesh = Mesh{};
  // Half-edge ids (3 per triangle, 2n triangles) must fit in 32 bits.
  if (input.size() >= (std::size_t{no_index} - 16) / 6) {
    throw InvalidInputError(InputProblem::other, "too many points for 32-bit triangle indices: " +
                                                     std::to_string(input.size()));
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
  for (std::uint32_t& v : mesh.tv) {
    if (v != mesh.ghost) v = order[v];
  }
  return true;
}

} // namespace madd::detail
