#pragma once
// Internals of verify_decomposition(), split by concern.
#include <cstdint>
#include <string>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// Collects problems up to a cap, so that a badly broken decomposition gives a
// readable report instead of millions of lines.
class ProblemLog {
public:
  explicit ProblemLog(Verification& out, std::size_t cap = 40) : out_(out), cap_(cap) {}
  void add(std::string problem);
  void finish();  // appends "... and K more" when problems were dropped
  // Adds what another log of `count` problems kept (`kept`: its first ones,
  // in order), as if they had been added here one by one.
  void absorb(std::vector<std::string>&& kept, std::size_t count);
  std::size_t count() const noexcept { return count_; }

private:
  Verification& out_;
  std::size_t cap_;
  std::size_t count_ = 0;
};

// Reports a pair of segments that cross, overlap, or touch anywhere other than
// a shared endpoint (including a vertex in the interior of a segment: a
// T-junction), if any. Exact (orient2d); a uniform grid keeps it near-linear.
void check_segments_disjoint(const std::vector<Point>& points, const std::vector<Segment>& segments, ProblemLog& log);

// The boundary pieces: each input segment's pieces lie on it (up to the
// rounding bound of the interpolation that placed their vertices), form one
// chain from its first end to its second advancing along it, and carry its
// marker (or 1); separators carry marker 0. Returns an upper bound on how far
// twice the area the subdomains cover may differ from twice the domain's
// because of those rounded vertices (0 when every one is exactly on its segment).
double check_boundary_pieces(const Decomposition& d, const Pslg& domain, ProblemLog& log);

// A bound on |cross(b - a, p - a)| (exact) for every vertex p that
// interpolation put on input segment ab cut into `pieces` pieces: how far
// rounding can move such a vertex off the line ab, times |b - a|. Derived in
// verify_decomposition_pieces.cpp; verify_mesh applies it to the mesh's
// boundary edges, whose vertices are placed the same way.
double off_line_bound(Point a, Point b, std::size_t pieces) noexcept;

// "(x, y)" with full precision, for messages.
std::string point_text(Point p);

}  // namespace madd::detail
