#pragma once
// Bowyer-Watson insertion on the half-edge core: the cavity of a new point
// (the triangles whose circumcircle strictly holds it, a connected region
// grown from a triangle holding the point) and the fan of triangles that
// replaces it. In a constrained mesh the cavity never crosses a segment (the
// cavity of a constrained Delaunay triangulation), so the segments stay
// edges; a subsegment is split by digging from both of its sides.
//
// A ghost triangle (over hull edge ab) is in conflict with p when p lies
// strictly outside ab or inside the open segment ab (Shewchuk's rule), so
// that a point outside the hull is inserted like any other.
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"
#include "triangulation/half_edge_mesh.hpp"

namespace madd::detail {

// Whether the ghost triangle over hull edge a->b (seen from the ghost) is in
// conflict with p: p strictly outside the hull edge b->a or inside it.
bool ghost_conflict(Point a, Point b, Point p) noexcept;

class Cavity {
public:
  // Which cavity slot each fan triangle takes: the i-th examined, or the
  // i-th last found. Either is deterministic; the triangulator and the
  // refinement each keep the numbering they had before they shared this
  // code, so that their triangles (and the refinement's queue order, which
  // follows reused slots) stay what they were.
  enum class SlotOrder : std::uint8_t { examined, last_found_first };

  struct RimEdge {
    std::uint32_t a, b;   // the rim edge a->b, seen from inside the cavity
    std::uint32_t outer;  // its twin outside (no_index: none)
  };
  // What a constrained mesh also keeps of a rim edge (apart, so that the
  // triangulator's rim stays small).
  struct RimSide {
    std::uint32_t inner;    // the rim half-edge itself (valid until fill())
    std::uint32_t segment;  // its segment, or no_index
  };

  explicit Cavity(SlotOrder order) noexcept : order_(order) {}
  // Scratch for this many slots and vertices up front (it grows on demand
  // otherwise), for a caller that knows its final size.
  void reserve(std::size_t slots, std::size_t vertices);

  // Digs the cavity of p from triangle t, which holds p in its closure.
  void dig(const HalfEdgeMesh& m, std::span<const Point> points, std::uint32_t t, Point p);
  // Digs the cavity of p lying strictly inside the segment half-edge h of a
  // constrained mesh, from both sides of h when it has a twin; h and its
  // twin are then not on the rim, and the fan closes over them (or stays
  // open at h on the outside of the mesh).
  void dig_on_edge(const HalfEdgeMesh& m, std::span<const Point> points, std::uint32_t h, Point p);

  // Every fan triangle (p, a, b) but the ghosts strictly counter-clockwise:
  // the cavity is star-shaped from p, exactly.
  bool star_shaped(std::span<const Point> points, Point p) const noexcept;
  // In a constrained mesh, per rim edge, its side (empty otherwise).
  const std::vector<RimSide>& rim_sides() const noexcept { return rim_sides_; }
  const std::vector<std::uint32_t>& triangles() const noexcept { return triangles_; }

  // Replaces the cavity by the fan of triangles (v, a, b), one per rim edge,
  // in rim order: edge 0 is the rim edge (keeping its segment), edge 1 is
  // b->v and edge 2 is v->a. The cavity's slots are reused first (as
  // SlotOrder says), then freed ones, then new ones. Returns the fan's
  // slots (valid until the next fill).
  std::span<const std::uint32_t> fill(HalfEdgeMesh& m, std::uint32_t v);
  // dig() then fill() at once, for a caller that does not look before it
  // leaps (the triangulator).
  std::span<const std::uint32_t> insert(HalfEdgeMesh& m, std::span<const Point> points, std::uint32_t t, Point p,
                                        std::uint32_t v);
  // Forgets the cavity, leaving the mesh as it was.
  void clear() noexcept;

private:
  void start(const HalfEdgeMesh& m, std::uint32_t t);
  void grow(const HalfEdgeMesh& m, std::span<const Point> points, Point p);
  template <bool Constrained, bool FoundOrder>
  void grow_from_stack(const HalfEdgeMesh& m, const Point* points, Point p);
  void order_slots(HalfEdgeMesh& m);
  void ready_fill(HalfEdgeMesh& m, std::uint32_t v);
  std::span<const std::uint32_t> finish() noexcept;
  void reset() noexcept;
  template <bool Closed, bool Constrained>
  void fill_fan(HalfEdgeMesh& m, std::uint32_t v);

  SlotOrder order_;
  std::vector<std::uint32_t> triangles_, stack_;
  std::vector<std::uint32_t> fan_;  // the slots of the last fan, in rim order (its first entries)
  // Per slot: in the cavity being dug. An enum rather than a byte, whose
  // stores the compiler must assume alias everything (the arrays included).
  enum class Mark : std::uint8_t { out, in };
  std::vector<Mark> in_cavity_;
  std::vector<RimEdge> rim_;
  std::vector<RimSide> rim_sides_;                        // per rim edge, in a constrained mesh
  std::vector<std::uint32_t> link_;                       // per vertex: the fan triangle whose rim edge starts there
  std::uint32_t skip_ = no_index, skip_twin_ = no_index;  // the split edge and its twin (dig_on_edge)
  std::uint32_t open_a_ = no_index, open_b_ = no_index;   // its ends, when the fan stays open there
  std::uint32_t ghost_ = no_index;                        // the mesh's, as dug
};

}  // namespace madd::detail
