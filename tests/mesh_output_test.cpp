// The mesh outputs (include/madd/mesh_output.hpp) read back by the strict
// readers of mesh_output_test_support.hpp: Triangle's tables, gmsh MSH 4.1
// and VTK .vtu against the Mesh they came from, the split pieces against the
// whole mesh, and the all-or-nothing writing. The meshes are made without the
// mesher (tests/mesh_fixtures.hpp), so these tests do not depend on it.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_output.hpp"
#include "madd/output.hpp"
#include "madd/poly_io.hpp"
#include "mesh_fixtures.hpp"
#include "output/mesh_text.hpp"
#include "output_formats_test_support.hpp"
#include "scratch_files.hpp"
#include "mesh_output_test_support.hpp"

namespace {

using namespace madd;
using namespace madd::test;
namespace fs = std::filesystem;

const Mesh& pipe_mesh() {
  static const Mesh m = [] {
    DecomposeOptions o;
    o.subdomains = 6;
    return mesh_without_steiner_points(decompose(read_domain(MADD_DATA_DIR "/pipe.poly"), o));
  }();
  return m;
}

// A square with a square hole, each outer side and the hole with its own
// marker (the hole's negative, which gmsh cannot use as a tag).
const Mesh& square_mesh() {
  static const Mesh m = [] {
    const Pslg p = marked_square_domain();
    DecomposeOptions o;
    o.subdomains = 4;
    return mesh_without_steiner_points(decompose(p, o));
  }();
  return m;
}

const std::vector<const Mesh*>& meshes() {
  static const std::vector<const Mesh*> all{&pipe_mesh(), &square_mesh()};
  return all;
}

using Edge = std::pair<std::uint32_t, std::uint32_t>;
Edge undirected(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

// The boundary pieces' mesh edges and their markers, from the decomposition
// (not from the Mesh's own segment markers, which the writers read).
std::map<Edge, int> expected_boundary(const Mesh& m) {
  std::map<Edge, int> out;
  for (const MeshSegment& s : m.segments)
    if (!m.decomposition.is_separator(s.piece)) out[undirected(s.a, s.b)] = m.decomposition.segments[s.piece].marker;
  return out;
}

std::set<Edge> separator_edges(const Mesh& m) {
  std::set<Edge> out;
  for (const MeshSegment& s : m.segments)
    if (m.decomposition.is_separator(s.piece)) out.insert(undirected(s.a, s.b));
  return out;
}

// How many triangles use each undirected edge.
std::map<Edge, int> edge_uses(const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  std::map<Edge, int> uses;
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i)
      ++uses[undirected(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)])];
  return uses;
}

std::uint32_t index_of(const std::string& word, unsigned first_index) {
  const std::int64_t v = integer_of(word) - first_index;
  REQUIRE(v >= 0);
  return static_cast<std::uint32_t>(v);
}

// The .node and .ele of a whole mesh or of one piece, read back.
struct TriangleMesh {
  std::vector<Point> points;
  std::vector<std::string> coordinate_text;  // "x y" as written
  std::vector<int> markers;
  std::vector<std::int64_t> point_attribute;  // the split pieces' global ids
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::int64_t> triangle_attribute;
  std::vector<double> region_attribute;  // the second attribute, with regions
};

TriangleMesh read_triangle_mesh(const std::string& node, const std::string& ele, unsigned first_index,
                                bool with_global_ids, bool with_regions) {
  TriangleMesh m;
  const TriangleTable nodes = parse_triangle_table(node, 4, with_global_ids ? 5 : 4, first_index);
  CHECK(nodes.header ==
        std::vector<std::int64_t>{static_cast<std::int64_t>(nodes.rows.size()), 2, with_global_ids ? 1 : 0, 1});
  for (const auto& row : nodes.rows) {
    m.points.push_back({real_of(row[0]), real_of(row[1])});
    m.coordinate_text.push_back(row[0] + " " + row[1]);
    if (with_global_ids) m.point_attribute.push_back(integer_of(row[2]));
    m.markers.push_back(static_cast<int>(integer_of(row.back())));
  }
  const TriangleTable eles = parse_triangle_table(ele, 3, with_regions ? 6 : 5, first_index);
  CHECK(eles.header == std::vector<std::int64_t>{static_cast<std::int64_t>(eles.rows.size()), 3, with_regions ? 2 : 1});
  for (const auto& row : eles.rows) {
    std::array<std::uint32_t, 3> t{};
    for (std::size_t i = 0; i < 3; ++i) {
      t[i] = index_of(row[i], first_index);
      REQUIRE(t[i] < m.points.size());
    }
    m.triangles.push_back(t);
    m.triangle_attribute.push_back(integer_of(row[3]));
    if (with_regions) m.region_attribute.push_back(real_of(row[4]));
  }
  return m;
}

TEST_SUITE("mesh_output") {

TEST_CASE("mesh .node and .ele: every triangle's vertices read back to the mesh's coordinates") {
  for (const Mesh* mesh : meshes()) {
    for (const unsigned first_index : {0u, 1u}) {
      CAPTURE(first_index);
      const TriangleMesh back =
          read_triangle_mesh(format_mesh_node(*mesh, first_index), format_mesh_ele(*mesh, first_index), first_index,
                             false, !mesh->decomposition.regions.empty());
      REQUIRE(back.points.size() == mesh->points.size());
      CHECK(back.points == mesh->points);  // %.17g reads back exactly
      CHECK(back.markers == mesh->point_markers);
      REQUIRE(back.triangles.size() == mesh->triangles.size());
      for (std::size_t t = 0; t < back.triangles.size(); ++t) {
        for (std::size_t i = 0; i < 3; ++i)
          CHECK(back.points[back.triangles[t][i]] == mesh->points[mesh->triangles[t][i]]);
        CHECK(signed_area(back.points[back.triangles[t][0]], back.points[back.triangles[t][1]],
                          back.points[back.triangles[t][2]]) > 0);  // counter-clockwise, as Triangle writes
        CHECK(back.triangle_attribute[t] == mesh->triangle_subdomain[t]);
        if (!mesh->decomposition.regions.empty()) CHECK(back.region_attribute[t] == mesh->triangle_attribute[t]);
      }
    }
  }
}

TEST_CASE("mesh .neigh: symmetric, across the shared edge, -1 exactly on the domain boundary") {
  for (const Mesh* mesh : meshes()) {
    for (const unsigned first_index : {0u, 1u}) {
      const TriangleTable neigh = parse_triangle_table(format_mesh_neigh(*mesh, first_index), 2, 4, first_index);
      CHECK(neigh.header == std::vector<std::int64_t>{static_cast<std::int64_t>(mesh->triangles.size()), 3});
      const auto& tris = mesh->triangles;
      REQUIRE(neigh.rows.size() == tris.size());
      const auto uses = edge_uses(tris);
      std::size_t outside = 0;
      for (std::size_t t = 0; t < tris.size(); ++t) {
        for (std::size_t i = 0; i < 3; ++i) {
          const std::uint32_t a = tris[t][(i + 1) % 3], b = tris[t][(i + 2) % 3];
          const std::int64_t n = integer_of(neigh.rows[t][i]);
          if (n == -1) {
            ++outside;
            CHECK(uses.at(undirected(a, b)) == 1);
            continue;
          }
          const std::uint32_t u = index_of(neigh.rows[t][i], first_index);
          REQUIRE(u < tris.size());
          // u has the edge b -> a, and names t across it.
          bool found = false;
          for (std::size_t j = 0; j < 3; ++j) {
            if (tris[u][(j + 1) % 3] == b && tris[u][(j + 2) % 3] == a) {
              found = true;
              CHECK(index_of(neigh.rows[u][j], first_index) == t);
            }
          }
          CHECK(found);
        }
      }
      CHECK(outside == expected_boundary(*mesh).size());
    }
  }
}

TEST_CASE("mesh .edge: every edge once, boundary edges with their piece's marker, the rest 0") {
  for (const Mesh* mesh : meshes()) {
    for (const unsigned first_index : {0u, 1u}) {
      const TriangleTable edges = parse_triangle_table(format_mesh_edge(*mesh, first_index), 2, 4, first_index);
      CHECK(edges.header == std::vector<std::int64_t>{static_cast<std::int64_t>(edges.rows.size()), 1});
      const auto uses = edge_uses(mesh->triangles);
      const auto boundary = expected_boundary(*mesh);
      const auto separators = separator_edges(*mesh);
      std::map<Edge, int> written;
      std::size_t marked = 0;
      for (const auto& row : edges.rows) {
        const std::uint32_t a = index_of(row[0], first_index), b = index_of(row[1], first_index);
        const int marker = static_cast<int>(integer_of(row[2]));
        CHECK(written.emplace(undirected(a, b), marker).second);  // once
        marked += marker != 0 ? 1 : 0;
      }
      CHECK(written.size() == uses.size());
      CHECK(2 * written.size() == 3 * mesh->triangles.size() + boundary.size());
      for (const auto& [edge, count] : uses) {
        REQUIRE(written.count(edge) == 1);
        if (count == 1) {
          REQUIRE(boundary.count(edge) == 1);
          CHECK(written.at(edge) == boundary.at(edge));
        } else {
          CHECK(written.at(edge) == 0);
        }
      }
      // Every boundary mesh segment is a marked edge (these domains have no
      // marker 0), and every separator edge is an unmarked one.
      CHECK(marked == boundary.size());
      for (const Edge& e : separators) CHECK(written.at(e) == 0);
      CHECK(!separators.empty());
    }
  }
}

TEST_CASE("mesh .msh 4.1: nodes exact, triangles in order, physical groups cover each subdomain and marker") {
  for (const Mesh* mesh : meshes()) {
    const Msh41 m = parse_msh41(format_mesh_msh(*mesh));
    REQUIRE(m.nodes.size() == mesh->points.size());
    for (std::size_t v = 0; v < mesh->points.size(); ++v)
      CHECK(m.nodes.at(static_cast<std::int64_t>(v) + 1) == mesh->points[v]);
    // Physical groups by name.
    std::map<std::string, std::pair<int, std::int64_t>> group;
    for (const auto& [key, name] : m.physical_names) CHECK(group.emplace(name, key).second);
    const auto boundary = expected_boundary(*mesh);
    std::set<int> markers;
    for (const auto& [edge, marker] : boundary) markers.insert(marker);
    CHECK(m.physical_names.size() == mesh->subdomain_count() + markers.size());
    // Which physical groups each element is in, through its entity.
    const auto physicals_of = [&](const Msh41Element& e) {
      return m.entities.at({e.entity_dim, e.entity_tag}).physical_tags;
    };
    std::vector<std::size_t> per_subdomain(mesh->subdomain_count(), 0);
    std::map<int, std::set<Edge>> lines_of_marker;
    std::set<std::pair<std::uint32_t, std::uint32_t>> directed;  // every triangle's directed edges
    for (const auto& t : mesh->triangles)
      for (std::size_t i = 0; i < 3; ++i) directed.insert({t[i], t[(i + 1) % 3]});
    std::size_t triangles = 0;
    for (const Msh41Element& e : m.elements) {
      const auto physicals = physicals_of(e);
      REQUIRE(physicals.size() == 1);
      if (e.type == 2) {
        ++triangles;
        REQUIRE(e.tag >= 1);
        const auto t = static_cast<std::size_t>(e.tag - 1);
        REQUIRE(t < mesh->triangles.size());
        for (std::size_t i = 0; i < 3; ++i) CHECK(e.nodes[i] == std::int64_t{mesh->triangles[t][i]} + 1);
        const std::uint32_t k = mesh->triangle_subdomain[t];
        CHECK(group.at("subdomain_" + std::to_string(k)) == std::pair{2, physicals[0]});
        ++per_subdomain[k];
      } else {
        const auto a = static_cast<std::uint32_t>(e.nodes[0] - 1), b = static_cast<std::uint32_t>(e.nodes[1] - 1);
        CHECK(directed.count({a, b}) == 1);  // oriented as its triangle runs it: the domain on its left
        const auto edge = undirected(a, b);
        REQUIRE(boundary.count(edge) == 1);
        const int marker = boundary.at(edge);
        CHECK(group.at("boundary_" + std::to_string(marker)) == std::pair{1, physicals[0]});
        if (marker > 0) CHECK(physicals[0] == marker);
        CHECK(lines_of_marker[marker].insert(edge).second);
      }
    }
    CHECK(triangles == mesh->triangles.size());
    // With regions, one element data view of every triangle's region attribute.
    CHECK(m.element_data.size() == (mesh->decomposition.regions.empty() ? 0u : 1u));
    if (!mesh->decomposition.regions.empty()) {
      const auto& view = m.element_data.at("region_attribute");
      REQUIRE(view.size() == mesh->triangles.size());
      for (std::size_t t = 0; t < mesh->triangles.size(); ++t)
        CHECK(view.at(static_cast<std::int64_t>(t) + 1) == mesh->triangle_attribute[t]);
    }
    for (std::uint32_t k = 0; k < mesh->subdomain_count(); ++k)
      CHECK(per_subdomain[k] == mesh->subdomain_first_triangle[k + 1] - mesh->subdomain_first_triangle[k]);
    // The lines of each marker are exactly its boundary edges.
    std::map<int, std::set<Edge>> expected;
    for (const auto& [edge, marker] : boundary) expected[marker].insert(edge);
    CHECK(lines_of_marker == expected);
    // Each node on the entity it lies on: boundary nodes on a curve, the others on a surface of theirs.
    std::set<std::uint32_t> on_boundary;
    for (const auto& [edge, marker] : boundary) on_boundary.insert({edge.first, edge.second});
    std::vector<std::set<std::int64_t>> surfaces_of(mesh->points.size());
    for (std::size_t t = 0; t < mesh->triangles.size(); ++t)
      for (const std::uint32_t v : mesh->triangles[t]) surfaces_of[v].insert(mesh->triangle_subdomain[t] + 1);
    for (const auto& [tag, entity] : m.node_entity) {
      const auto v = static_cast<std::size_t>(tag - 1);
      CHECK(entity.first == (on_boundary.count(static_cast<std::uint32_t>(v)) ? 1 : 2));
      if (entity.first == 2) CHECK(surfaces_of[v].count(entity.second) == 1);
    }
  }
  // A negative marker gets the tag after the largest positive one.
  const Msh41 square = parse_msh41(format_mesh_msh(square_mesh()));
  CHECK(square.physical_names.at({1, 5}) == "boundary_-7");
  CHECK(square.physical_names.at({1, 2}) == "boundary_2");
  CHECK(square.physical_names.at({2, 4}) == "subdomain_3");
}

TEST_CASE("mesh .vtu: points exact, connectivity, offsets, types, subdomain and marker arrays") {
  for (const Mesh* mesh : meshes()) {
    const Vtu v = parse_vtu(format_mesh_vtu(*mesh));
    CHECK(v.piece.at("NumberOfPoints") == std::to_string(mesh->points.size()));
    CHECK(v.piece.at("NumberOfCells") == std::to_string(mesh->triangles.size()));
    const XmlArray& points = v.array("Points", "");
    CHECK(points.attributes.at("type") == "Float64");
    CHECK(points.attributes.at("NumberOfComponents") == "3");
    REQUIRE(points.values.size() == 3 * mesh->points.size());
    for (std::size_t p = 0; p < mesh->points.size(); ++p) {
      CHECK(Point{real_of(points.values[3 * p]), real_of(points.values[3 * p + 1])} == mesh->points[p]);
      CHECK(real_of(points.values[3 * p + 2]) == 0.0);
    }
    const auto& connectivity = v.array("Cells", "connectivity").values;
    const auto& offsets = v.array("Cells", "offsets").values;
    const auto& types = v.array("Cells", "types").values;
    REQUIRE(connectivity.size() == 3 * mesh->triangles.size());
    REQUIRE(offsets.size() == mesh->triangles.size());
    REQUIRE(types.size() == mesh->triangles.size());
    for (std::size_t t = 0; t < mesh->triangles.size(); ++t) {
      for (std::size_t i = 0; i < 3; ++i) CHECK(integer_of(connectivity[3 * t + i]) == mesh->triangles[t][i]);
      CHECK(integer_of(offsets[t]) == static_cast<std::int64_t>(3 * t + 3));
      CHECK(types[t] == "5");
    }
    const XmlArray& subdomain = v.array("CellData", "subdomain");
    CHECK(subdomain.attributes.at("type") == "Int32");
    REQUIRE(subdomain.values.size() == mesh->triangles.size());
    for (std::size_t t = 0; t < mesh->triangles.size(); ++t)
      CHECK(integer_of(subdomain.values[t]) == mesh->triangle_subdomain[t]);
    if (!mesh->decomposition.regions.empty()) {  // the pipe has a region
      const XmlArray& region = v.array("CellData", "region_attribute");
      CHECK(region.attributes.at("type") == "Float64");
      REQUIRE(region.values.size() == mesh->triangles.size());
      for (std::size_t t = 0; t < mesh->triangles.size(); ++t)
        CHECK(real_of(region.values[t]) == mesh->triangle_attribute[t]);
    } else {
      CHECK_THROWS(v.array("CellData", "region_attribute"));
    }
    const XmlArray& marker = v.array("PointData", "marker");
    CHECK(marker.attributes.at("type") == "Int32");
    REQUIRE(marker.values.size() == mesh->points.size());
    for (std::size_t p = 0; p < mesh->points.size(); ++p) CHECK(integer_of(marker.values[p]) == mesh->point_markers[p]);
  }
}

TEST_CASE("split mesh: the pieces' local-to-global maps give back the mesh, separators agree to the text") {
  for (const Mesh* mesh : meshes()) {
    for (const unsigned first_index : {0u, 1u}) {
      CAPTURE(first_index);
      TempDir tmp("mesh-output");
      const std::uint32_t n = mesh->subdomain_count();
      write_split_mesh(*mesh, (tmp.path / "parts").string(), "m", first_index);
      std::set<std::string> expected_names;
      for (std::uint32_t k = 0; k < n; ++k)
        for (const char* ext : {".node", ".ele"}) expected_names.insert(split_mesh_file_name("m", k, n, ext));
      CHECK(tmp.names(tmp.path / "parts") == expected_names);
      // The whole mesh's coordinate text, to compare the pieces' with.
      const bool regions = !mesh->decomposition.regions.empty();
      const TriangleMesh whole = read_triangle_mesh(format_mesh_node(*mesh, first_index),
                                                    format_mesh_ele(*mesh, first_index), first_index, false, regions);
      std::map<std::int64_t, std::set<std::uint32_t>> pieces_of;  // global vertex -> pieces holding it
      std::vector<std::array<std::uint32_t, 3>> all;
      for (std::uint32_t k = 0; k < n; ++k) {
        const fs::path dir = tmp.path / "parts";
        const TriangleMesh piece =
            read_triangle_mesh(read_text(dir / split_mesh_file_name("m", k, n, ".node")),
                               read_text(dir / split_mesh_file_name("m", k, n, ".ele")), first_index, true, regions);
        std::vector<std::uint32_t> to_global;
        for (std::size_t i = 0; i < piece.points.size(); ++i) {
          const std::uint32_t g = index_of(std::to_string(piece.point_attribute[i]), first_index);
          REQUIRE(g < mesh->points.size());
          to_global.push_back(g);
          CHECK(piece.coordinate_text[i] == whole.coordinate_text[g]);  // the same text in every file
          CHECK(piece.points[i] == mesh->points[g]);
          CHECK(piece.markers[i] == mesh->point_markers[g]);
          CHECK(pieces_of[g].insert(k).second);
        }
        CHECK(std::is_sorted(to_global.begin(), to_global.end()));
        const std::uint32_t first = mesh->subdomain_first_triangle[k];
        REQUIRE(piece.triangles.size() == mesh->subdomain_first_triangle[k + 1] - first);
        for (std::size_t t = 0; t < piece.triangles.size(); ++t) {
          const auto& local = piece.triangles[t];
          const std::array<std::uint32_t, 3> global{to_global[local[0]], to_global[local[1]], to_global[local[2]]};
          CHECK(global == mesh->triangles[first + t]);
          CHECK(piece.triangle_attribute[t] == k);
          if (regions) CHECK(piece.region_attribute[t] == mesh->triangle_attribute[first + t]);
          all.push_back(global);
        }
      }
      CHECK(all == mesh->triangles);
      // A separator's vertices are in the pieces of both its subdomains.
      std::vector<std::set<std::uint32_t>> sides(mesh->decomposition.segments.size());
      for (std::uint32_t k = 0; k < n; ++k)
        for (const auto& ring : mesh->decomposition.subdomains[k].ring_segments)
          for (const std::uint32_t s : ring) sides[s].insert(k);
      std::size_t shared = 0;
      for (const MeshSegment& s : mesh->segments) {
        if (!mesh->decomposition.is_separator(s.piece)) continue;
        REQUIRE(sides[s.piece].size() == 2);
        for (const std::uint32_t v : {s.a, s.b}) {
          for (const std::uint32_t k : sides[s.piece]) CHECK(pieces_of[v].count(k) == 1);
          ++shared;
        }
      }
      CHECK(shared > 0);
    }
  }
}

TEST_CASE("split mesh: names are padded, an older run's pieces are removed, other files kept") {
  CHECK(split_mesh_file_name("m", 0, 1, ".node") == "m-0.node");
  CHECK(split_mesh_file_name("m", 7, 11, ".ele") == "m-07.ele");
  CHECK(split_mesh_file_name("pipe", 42, 1000, ".node") == "pipe-042.node");
  TempDir tmp("mesh-output");
  const fs::path dir = tmp.path / "parts";
  write_split_mesh(pipe_mesh(), dir.string(), "m");
  CHECK(tmp.names(dir).size() == 12);
  std::ofstream(dir / "notes.txt") << "kept";
  std::ofstream(dir / "other-1.node") << "kept";
  write_split_mesh(square_mesh(), dir.string(), "m");
  CHECK(tmp.names(dir) == std::set<std::string>{"m-0.ele", "m-0.node", "m-1.ele", "m-1.node", "m-2.ele", "m-2.node",
                                                "m-3.ele", "m-3.node", "notes.txt", "other-1.node"});
  CHECK(read_text(dir / "m-2.ele") == format_subdomain_mesh_ele(square_mesh(), 2));
  CHECK(tmp.names(tmp.path) == std::set<std::string>{"parts"});  // no staging directory left behind
}

// The Triangle files and the .vtu are made in pieces of 65,536 lines on the threads
// while they are written (src/output/mesh_text.hpp): a mesh of several
// pieces gives the same bytes on 1, 2 and 3 threads, those of format_mesh_*;
// the split mesh's files, formatted on threads, those of format_subdomain_mesh_*.
TEST_CASE("write_mesh on threads: the same bytes, piece after piece") {
  TempDir tmp("mesh-output-pieces");
  MeshOptions o;
  o.decomposition.subdomains = 8;
  o.decomposition.threads = 2;
  o.size.max_triangle_area = 0.002;
  const Mesh m = mesh(read_domain(MADD_DATA_DIR "/pipe.poly"), o);
  REQUIRE(m.triangles.size() > 2 * detail::mesh_lines_per_piece);  // three pieces of .ele at least
  MeshFormats formats;
  formats.neigh = formats.vtu = true;
  const std::string node = format_mesh_node(m), ele = format_mesh_ele(m), neigh = format_mesh_neigh(m);
  const std::string vtu = format_mesh_vtu(m);
  for (const unsigned threads : {1u, 2u, 3u}) {
    CAPTURE(threads);
    std::string name = "t";  // appended: GCC 12 warns (-Wrestrict, a false positive) on "t" + a temporary
    name += std::to_string(threads);
    const std::string prefix = (tmp.path / name).string();
    write_mesh(m, prefix, formats, threads);
    CHECK(read_text(prefix + ".node") == node);
    CHECK(read_text(prefix + ".ele") == ele);
    CHECK(read_text(prefix + ".neigh") == neigh);
    CHECK(read_text(prefix + ".vtu") == vtu);
  }
  // --split-mesh formats the subdomains' files on the threads.
  const fs::path dir = tmp.path / "parts";
  write_split_mesh(m, dir.string(), "s", 1, 3);
  for (std::uint32_t k = 0; k < m.subdomain_count(); ++k) {
    CAPTURE(k);
    CHECK(read_text(dir / split_mesh_file_name("s", k, m.subdomain_count(), ".node")) ==
          format_subdomain_mesh_node(m, k));
    CHECK(read_text(dir / split_mesh_file_name("s", k, m.subdomain_count(), ".ele")) ==
          format_subdomain_mesh_ele(m, k));
  }
}

TEST_CASE("write_mesh writes the chosen formats; a missing directory fails and leaves nothing") {
  TempDir tmp("mesh-output");
  MeshFormats all;
  all.msh = all.vtu = all.neigh = all.edge = true;
  all.first_index = 0;
  write_mesh(square_mesh(), (tmp.path / "sq").string(), all);
  CHECK(tmp.names(tmp.path) == std::set<std::string>{"sq.edge", "sq.ele", "sq.msh", "sq.neigh", "sq.node", "sq.vtu"});
  CHECK(read_text(tmp.path / "sq.node") == format_mesh_node(square_mesh(), 0));
  CHECK(read_text(tmp.path / "sq.edge") == format_mesh_edge(square_mesh(), 0));
  CHECK(read_text(tmp.path / "sq.msh") == format_mesh_msh(square_mesh()));
  CHECK(read_text(tmp.path / "sq.vtu") == format_mesh_vtu(square_mesh()));

  MeshFormats only_msh;
  only_msh.triangle = false;
  only_msh.msh = true;
  write_mesh(square_mesh(), (tmp.path / "g").string(), only_msh);
  CHECK(tmp.names(tmp.path).count("g.msh") == 1);
  CHECK(tmp.names(tmp.path).count("g.node") == 0);

  // By default .node and .ele only, as Triangle writes without -n and -e.
  write_mesh(square_mesh(), (tmp.path / "d").string());
  CHECK(tmp.names(tmp.path).count("d.node") == 1);
  CHECK(tmp.names(tmp.path).count("d.ele") == 1);
  CHECK(tmp.names(tmp.path).count("d.neigh") == 0);
  CHECK(tmp.names(tmp.path).count("d.edge") == 0);

  // One output into a directory that does not exist: the whole set fails,
  // the split directory that could have been written is not created either.
  const fs::path fresh = tmp.path / "fresh";
  fs::create_directories(fresh);
  OutputSet outputs;
  add_split_mesh(outputs, pipe_mesh(), (fresh / "parts").string(), "pipe");
  add_mesh(outputs, pipe_mesh(), (fresh / "missing" / "pipe").string(), all);
  CHECK_THROWS_AS(outputs.write(), OutputError);
  CHECK(tmp.names(fresh).empty());
  CHECK_THROWS_AS(write_mesh(pipe_mesh(), (fresh / "missing" / "pipe").string()), OutputError);
  CHECK(tmp.names(fresh).empty());
}

TEST_CASE("mesh outputs refuse a first index other than 0 or 1") {
  CHECK_THROWS_AS(format_mesh_node(square_mesh(), 2), OptionError);
  CHECK_THROWS_AS(format_mesh_edge(square_mesh(), 7), OptionError);
  CHECK_THROWS_AS(format_subdomain_mesh_node(square_mesh(), 0, 2), OptionError);
  OutputSet outputs;
  MeshFormats bad;
  bad.first_index = 2;
  CHECK_THROWS_AS(add_mesh(outputs, square_mesh(), "never", bad), OptionError);
  CHECK_THROWS_AS(add_split_mesh(outputs, square_mesh(), "never", "m", 3), OptionError);
  CHECK(outputs.empty());
}

TEST_CASE("gmsh reads the .msh back with the same groups (skipped without gmsh)") {
  if (std::system("command -v gmsh >/dev/null 2>&1") != 0) {
    MESSAGE("skipped: gmsh is not installed (apt-get install gmsh to run this check)");
    return;
  }
  TempDir tmp("mesh-output");
  for (const Mesh* mesh : meshes()) {
    const fs::path in = tmp.path / "in.msh", out = tmp.path / "out.msh";
    std::ofstream(in) << format_mesh_msh(*mesh);
    const std::string command = "gmsh -0 '" + in.string() + "' -format msh41 -o '" + out.string() + "' > '" +
                                (tmp.path / "gmsh.log").string() + "' 2>&1";
    REQUIRE_MESSAGE(std::system(command.c_str()) == 0, read_text(tmp.path / "gmsh.log"));
    const Msh41 back = parse_msh41(read_text(out));
    const Msh41 mine = parse_msh41(read_text(in));
    CHECK(back.physical_names == mine.physical_names);
    // gmsh writes 16 significant digits: the same nodes, coordinates within that.
    REQUIRE(back.nodes.size() == mine.nodes.size());
    for (const auto& [tag, p] : mine.nodes) {
      REQUIRE(back.nodes.count(tag) == 1);
      CHECK(back.nodes.at(tag).x == doctest::Approx(p.x).epsilon(1e-15));
      CHECK(back.nodes.at(tag).y == doctest::Approx(p.y).epsilon(1e-15));
    }
    // Elements per physical group (gmsh may renumber elements, not nodes).
    const auto per_group = [](const Msh41& m) {
      std::map<std::pair<int, std::int64_t>, std::multiset<std::vector<std::int64_t>>> groups;
      for (const Msh41Element& e : m.elements)
        for (const std::int64_t p : m.entities.at({e.entity_dim, e.entity_tag}).physical_tags)
          groups[{e.entity_dim, p}].insert(e.nodes);
      return groups;
    };
    CHECK(per_group(back) == per_group(mine));
  }
}

}  // TEST_SUITE("mesh_output")

}  // namespace
