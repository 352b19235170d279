#pragma once
// What the mesh writers (src/output/mesh_*.cpp) share: Triangle-style lines
// of numbers, the first_index rule, and the marker of every boundary edge.
#include <algorithm>
#include <concepts>
#include <functional>
#include <memory>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "madd/atomic_write.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_share.hpp"
#include "kernel/edge_key.hpp"
#include "kernel/number_format.hpp"
#include "mesh/pieces_view.hpp"

namespace madd::detail {

// Throws OptionError unless first_index is 0 or 1 (Triangle's two numberings).
void check_first_index(unsigned first_index);

// The whole mesh's .node, .ele and .neigh in pieces of this many lines (the
// header in the first), made on `threads` threads while they are written
// (FilePieces); joined, they are format_mesh_node's, ...ele's and ...neigh's
// text. They read `mesh`, which must outlive the write.
inline constexpr std::size_t mesh_lines_per_piece = std::size_t{1} << 16;

// Piece `piece` of a file of `lines` lines after its header: lines
// [piece L, (piece + 1) L), L = mesh_lines_per_piece, the header first in
// piece 0; header(out) appends the header, body(out, i) line i.
template <typename Header, typename Body>
std::string file_piece(std::size_t lines, std::size_t piece, std::size_t bytes_per_line, const Header& header,
                       const Body& body) {
  const std::size_t begin = piece * mesh_lines_per_piece;
  const std::size_t end = std::min(lines, begin + mesh_lines_per_piece);
  std::string out;
  out.reserve(bytes_per_line * (end > begin ? end - begin : 0) + 32);
  if (piece == 0) header(out);
  for (std::size_t i = begin; i < end; ++i) body(out, i);
  return out;
}

// Such a file in pieces made on `threads` threads (header and body kept by value).
template <typename Header, typename Body>
FilePieces line_pieces(std::size_t lines, std::size_t bytes_per_line, Header header, Body body, unsigned threads) {
  return {lines / mesh_lines_per_piece + 1,
          [=](std::size_t piece) { return file_piece(lines, piece, bytes_per_line, header, body); }, threads};
}

// A text of sections, each some fixed text then `count` lines made by
// body(out, i), cut into pieces of at most mesh_lines_per_piece lines (a
// section's fixed text opens its first piece): a file of several arrays
// (.vtu) made while it is written. The bodies may read what they capture
// until the pieces are all made.
class SectionedText {
public:
  using Body = std::function<void(std::string& out, std::size_t i)>;
  // The fixed text before the next lines (append to it).
  std::string& text() { return pending_; }
  void lines(std::size_t count, Body body);
  FilePieces pieces(unsigned threads);

private:
  struct Section {
    std::string before;
    std::size_t count = 0;
    Body body;
  };
  std::vector<Section> sections_;
  std::string pending_;
};

// The whole file: its pieces joined, in order.
inline std::string joined(const FilePieces& pieces) {
  std::string out;
  for (std::size_t i = 0; i < pieces.count; ++i) out += pieces.make(i);
  return out;
}
FilePieces mesh_node_pieces(const Mesh& mesh, unsigned first_index, unsigned threads);
FilePieces mesh_ele_pieces(const Mesh& mesh, unsigned first_index, unsigned threads);
FilePieces mesh_neigh_pieces(const Mesh& mesh, unsigned first_index, unsigned threads);
// The same files of a mesh kept in pieces (mesh/mesh_pieces.hpp): the same
// bytes as those of the merged mesh, read through PiecesView.
FilePieces mesh_node_pieces(const MeshPiecesData& mesh, unsigned first_index, unsigned threads);
FilePieces mesh_ele_pieces(const MeshPiecesData& mesh, unsigned first_index, unsigned threads);
FilePieces mesh_neigh_pieces(const MeshPiecesData& mesh, unsigned first_index, unsigned threads);
std::string format_mesh_edge(const MeshPiecesData& mesh, unsigned first_index);
std::string format_subdomain_mesh_node(const MeshPiecesData& mesh, std::uint32_t k, unsigned first_index);
std::string format_subdomain_mesh_ele(const MeshPiecesData& mesh, std::uint32_t k, unsigned first_index);
std::string format_mesh_msh(const MeshPiecesData& mesh);
FilePieces mesh_vtu_pieces(const MeshPiecesData& mesh, unsigned threads);

// One value of a line: integers as they are, doubles as %.17g, so a vertex
// has the same text in the whole mesh's files and in its split pieces.
inline void put(std::string& out, double v) { append_g17(out, v); }
inline void put(std::string& out, std::integral auto v) { append_int(out, static_cast<std::int64_t>(v)); }

// "v0 v1 ...\n", values separated by one space.
template <typename First, typename... Rest>
void line(std::string& out, First first, Rest... rest) {
  put(out, first);
  ((out += ' ', put(out, rest)), ...);
  out += '\n';
}

// Whether the mesh files carry a region attribute per triangle (Triangle's
// -A): when the input has regions, so that every file of a run, and every
// part of a distributed one (even a part with no triangles), has the same columns.
inline bool has_region_attributes(const Mesh& mesh) { return !mesh.decomposition.regions.empty(); }
inline bool has_region_attributes(const MeshPart& part) { return !part.decomposition.regions.empty(); }
inline bool has_region_attributes(const PiecesView& view) { return view.data().has_regions(); }
template <typename AnyMesh>  // a Mesh or a part's LocalMesh
double region_attribute(const AnyMesh& mesh, std::size_t t) {
  return t < mesh.triangle_attribute.size() ? mesh.triangle_attribute[t] : 0.0;
}

// The marker of every MeshSegment, by edge: what a boundary edge of the mesh
// is labelled with.
std::unordered_map<std::uint64_t, int> segment_markers(const std::vector<MeshSegment>& segments);

// The marker written for the domain-boundary edge {a, b}: its segment's, or 1
// (Triangle's marker of an unmarked boundary) should no segment cover it.
int boundary_marker(const std::unordered_map<std::uint64_t, int>& markers, std::uint32_t a, std::uint32_t b);

// A part's global numbering (include/madd/mesh_part_output.hpp), for the VTU writer.
struct VtuGlobalIds {
  const std::vector<std::uint64_t>* point_ids = nullptr;
  const std::vector<std::uint32_t>* point_owner = nullptr;
  const std::vector<std::uint64_t>* triangle_ids = nullptr;
  std::uint32_t rank = 0;
};

// format_mesh_vtu of a part's local mesh, with its global ids; `regions`:
// with the region attribute of every triangle.
std::string format_vtu(const LocalMesh& mesh, bool regions, const VtuGlobalIds& global);
// The same in pieces made on `threads` threads; the mesh and the arrays
// `global` points to must outlive the write (`global` itself need not).
FilePieces vtu_pieces(const LocalMesh& mesh, bool regions, const VtuGlobalIds& global, unsigned threads);

// The whole mesh's .vtu in pieces made on `threads` threads (joined:
// format_mesh_vtu's text); `mesh` must outlive the write.
FilePieces mesh_vtu_pieces(const Mesh& mesh, unsigned threads);

}  // namespace madd::detail
