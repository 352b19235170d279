// The mesh's boundary as the boundary lists of a coastal model
// (include/madd/model_output.hpp, model_boundaries): loops of boundary edges
// with the domain on their left, split into open and land runs.
#include <algorithm>
#include <cstdint>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "madd/error.hpp"
#include "madd/mesh_pieces.hpp"
#include "madd/model_output.hpp"
#include "mesh/pieces_view.hpp"
#include "output/mesh_text.hpp"
#include "triangulation/boundary_loops.hpp"

namespace madd {

const char* to_string(BoundaryKind kind) noexcept {
  switch (kind) {
  case BoundaryKind::open:
    return "open";
  case BoundaryKind::mainland:
    return "mainland";
  case BoundaryKind::island:
    return "island";
  }
  return "boundary";
}

namespace {

[[noreturn]] void malformed(const std::string& what) {
  throw InvalidInputError(InputProblem::other, "model boundaries: malformed mesh: " + what);
}

void check(const Mesh& mesh) {
  if (mesh.neighbours.size() != mesh.triangles.size()) malformed("neighbours and triangles differ in number");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (mesh.triangles[t][k] >= mesh.points.size()) malformed("triangle " + std::to_string(t) + " lacks a point");
      const std::uint32_t n = mesh.neighbours[t][k];
      if (n != no_index && n >= mesh.triangles.size())
        malformed("triangle " + std::to_string(t) + " has a neighbour out of range");
    }
}

struct LoopEdge {
  std::uint32_t a = 0, b = 0;
  bool open = false;
};

bool edge_less(const LoopEdge& u, const LoopEdge& v) { return u.a != v.a ? u.a < v.a : u.b < v.b; }

struct Loop {
  std::vector<LoopEdge> edges;
  double area = 0.0;  // signed: positive counter-clockwise
  LoopEdge smallest;  // its smallest directed edge (a, b)
};

// Every boundary edge in exactly one loop (triangulation/boundary_loops.hpp:
// traced through each vertex's fan, so loops never jump where boundaries
// touch), loops in the order of their first edge's side. AnyMesh: a Mesh,
// or the view of a mesh in pieces (which the library made and checked: its
// triangles' references are not checked again).
template <typename AnyMesh>
std::vector<Loop> boundary_loops(const AnyMesh& mesh, int open_marker) {
  if constexpr (std::is_same_v<AnyMesh, Mesh>) check(mesh);
  const std::unordered_map<std::uint64_t, int> markers = detail::segment_markers(mesh.segments);
  std::vector<detail::BoundaryLoop> traced;
  try {
    traced = detail::boundary_loops(mesh.triangles, mesh.neighbours);
  } catch (const InternalError& e) {
    malformed(e.what());
  }
  std::vector<Loop> loops;
  for (const detail::BoundaryLoop& t : traced) {
    Loop loop;
    const Point origin = mesh.points[t.vertices[0]];
    for (std::size_t k = 0; k < t.vertices.size(); ++k) {
      const std::uint32_t a = t.vertices[k], b = t.vertices[(k + 1) % t.vertices.size()];
      loop.edges.push_back({a, b, detail::boundary_marker(markers, a, b) == open_marker});
      const Point p = mesh.points[a], q = mesh.points[b];
      loop.area += 0.5 * ((p.x - origin.x) * (q.y - origin.y) - (p.y - origin.y) * (q.x - origin.x));
    }
    loop.smallest = *std::min_element(loop.edges.begin(), loop.edges.end(), edge_less);
    loops.push_back(std::move(loop));
  }
  return loops;
}

// The loop rotated to its start: its smallest directed edge, then, with
// both kinds, the first edge from there that opens an open run.
void rotate_to_start(std::vector<LoopEdge>& edges) {
  std::rotate(edges.begin(), std::min_element(edges.begin(), edges.end(), edge_less), edges.end());
  const std::size_t n = edges.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (edges[k].open && !edges[(k + n - 1) % n].open) {
      std::rotate(edges.begin(), edges.begin() + static_cast<std::ptrdiff_t>(k), edges.end());
      return;
    }
  }
}

struct Lists {
  std::vector<ModelBoundary> open, mainland, island;
};

// One loop's lists: one closed list when it is all one kind, else its
// maximal runs (open ones open, land ones mainland), in order along it.
void add_loop(Loop& loop, bool outer, Lists& lists) {
  rotate_to_start(loop.edges);
  const auto& edges = loop.edges;
  const bool uniform =
      std::all_of(edges.begin(), edges.end(), [&](const LoopEdge& e) { return e.open == edges[0].open; });
  for (std::size_t k = 0; k < edges.size();) {
    ModelBoundary list;
    list.kind = edges[k].open ? BoundaryKind::open : BoundaryKind::mainland;
    if (uniform && !edges[k].open && !outer) list.kind = BoundaryKind::island;
    list.closed = uniform;
    list.nodes.push_back(edges[k].a);
    const bool open = edges[k].open;
    for (; k < edges.size() && edges[k].open == open; ++k) list.nodes.push_back(edges[k].b);
    auto& into = list.kind == BoundaryKind::open       ? lists.open
                 : list.kind == BoundaryKind::mainland ? lists.mainland
                                                       : lists.island;
    into.push_back(std::move(list));
  }
}

template <typename AnyMesh>
std::vector<ModelBoundary> model_boundaries_of(const AnyMesh& mesh, int open_marker) {
  std::vector<Loop> loops = boundary_loops(mesh, open_marker);
  if (loops.empty()) return {};
  // The outer loop: the largest signed area (the first of equals).
  std::size_t outer = 0;
  for (std::size_t k = 1; k < loops.size(); ++k)
    if (loops[k].area > loops[outer].area) outer = k;
  std::vector<Loop*> holes;
  for (std::size_t k = 0; k < loops.size(); ++k)
    if (k != outer) holes.push_back(&loops[k]);
  std::sort(holes.begin(), holes.end(),
            [](const Loop* u, const Loop* v) { return edge_less(u->smallest, v->smallest); });
  Lists lists;
  add_loop(loops[outer], true, lists);
  for (Loop* hole : holes) add_loop(*hole, false, lists);
  std::vector<ModelBoundary> out = std::move(lists.open);
  for (auto* part : {&lists.mainland, &lists.island})
    out.insert(out.end(), std::make_move_iterator(part->begin()), std::make_move_iterator(part->end()));
  return out;
}

}  // namespace

std::vector<ModelBoundary> model_boundaries(const Mesh& mesh, int open_marker) {
  return model_boundaries_of(mesh, open_marker);
}

std::vector<ModelBoundary> model_boundaries(const MeshPieces& mesh, int open_marker) {
  return model_boundaries_of(detail::PiecesView(mesh.data()), open_marker);
}

namespace detail {

std::vector<ModelBoundary> model_boundaries(const PiecesView& mesh, int open_marker) {
  return model_boundaries_of(mesh, open_marker);
}

}  // namespace detail

}  // namespace madd
