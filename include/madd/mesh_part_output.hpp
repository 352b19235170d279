#pragma once
// One share's part of a mesh (include/madd/mesh_share.hpp) as files
// (docs/formats.md, "Mesh outputs", and docs/mpi.md): what each madd-mpi rank
// writes. Vertex and triangle ids in these files are global: those of
// `madd mesh`'s PREFIX.node and PREFIX.ele for the same options.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "madd/atomic_write.hpp"
#include "madd/mesh_share.hpp"

namespace madd {

// PREFIX-R.node: "<#vertices> 2 2 1", then "id x y global owner marker": local
// ids from first_index, the vertex's global id (with the same first_index),
// the share that owns it (the lowest share using it) and its boundary marker.
std::string format_part_node(const MeshPart& part, unsigned first_index = 1);

// PREFIX-R.ele: "<#triangles> 3 2", then "id a b c k global": local vertex ids,
// counter-clockwise; the subdomain k and the triangle's global id as
// attributes; with regions in the input "3 3" and the region attribute third.
std::string format_part_ele(const MeshPart& part, unsigned first_index = 1);

// PREFIX-R.vtu: format_mesh_vtu's grid of the part's triangles, with
// PointData Int64 "global_id" (the GlobalIds attribute; 0-based) and Int32
// "owner", CellData Int64 "global_id" (GlobalIds) and Int32 "rank".
std::string format_part_vtu(const MeshPart& part);

// PREFIX.pvtu: the parallel VTK file that opens the pieces as one grid;
// `pieces` are their file names relative to the .pvtu's directory. With
// region_attributes (the input has regions) the pieces' Float64
// "region_attribute" cell array is declared too.
std::string format_parts_pvtu(const std::vector<std::string>& pieces, bool region_attributes = false);

// "<stem>-<share><extension>", share zero-padded as split_file_name pads it.
std::string part_file_name(std::string_view stem, std::uint32_t share, std::uint32_t shares,
                           std::string_view extension);

// Which files add_mesh_part writes.
struct MeshPartFormats {
  bool triangle = true;      // PREFIX-R.node, PREFIX-R.ele
  bool vtu = false;          // PREFIX-R.vtu, and PREFIX.pvtu from share 0
  unsigned first_index = 1;  // of the Triangle files: 0 or 1
  friend bool operator==(const MeshPartFormats&, const MeshPartFormats&) = default;
};

// Adds the part's files under `prefix` to `outputs` (share 0 also adds
// PREFIX.pvtu naming every share's .vtu). Throws OptionError on a bad
// first_index, OutputError when a path is already in the set. The .node,
// .ele and .vtu are made while they are written, on `threads` threads (FilePieces):
// `part` must outlive outputs.write().
void add_mesh_part(OutputSet& outputs, const MeshPart& part, const std::string& prefix,
                   const MeshPartFormats& formats = {}, unsigned threads = 1);

}  // namespace madd
