// A mesh kept in pieces (include/madd/mesh_pieces.hpp): the same mesh as
// mesh() once joined, the same bytes in every file written from the pieces,
// the same figures; and its check, each piece alone then what crosses
// subdomains, catching every kind of defect the check of the merged mesh
// catches.
#include <doctest/doctest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "madd/mesh.hpp"
#include "madd/mesh_metrics.hpp"
#include "madd/mesh_output.hpp"
#include "madd/mesh_pieces.hpp"
#include "madd/model_output.hpp"
#include "madd/poly_io.hpp"
#include "mesh/mesh_pieces.hpp"
#include "mesh/pieces_check.hpp"
#include "mesh/subdomain_check.hpp"
#include "mesh/subdomain_regions.hpp"
#include "output/mesh_text.hpp"
#include "quality/area_bound.hpp"
#include "mesh_fixtures.hpp"
#include "scratch_files.hpp"

namespace {

struct Case {
  const char* file;
  std::uint32_t n;
  double q;
  double area_fraction;  // the area bound: the domain's area over this
};

// The key; the estuary (interior segments, survey points, a region); the
// archipelago at q 33 (separator pieces split between rounds).
const Case cases[] = {{"/key.poly", 8, 30, 3000}, {"/estuary.poly", 6, 30, 400}, {"/archipelago.poly", 12, 33, 20000}};

madd::MeshOptions options_of(const madd::Pslg& domain, const Case& c, unsigned threads) {
  madd::MeshOptions o = madd::test::options_for(c.n, c.q, madd::domain_area(domain) / c.area_fraction);
  o.decomposition.threads = threads;
  return o;
}

void check_same_files(const madd::Mesh& merged, const madd::MeshPieces& pieces, unsigned threads) {
  using madd::detail::joined;
  const madd::detail::MeshPiecesData& m = pieces.data();
  for (const unsigned first : {0u, 1u}) {
    CAPTURE(first);
    CHECK(joined(madd::detail::mesh_node_pieces(m, first, threads)) == madd::format_mesh_node(merged, first));
    CHECK(joined(madd::detail::mesh_ele_pieces(m, first, threads)) == madd::format_mesh_ele(merged, first));
    CHECK(joined(madd::detail::mesh_neigh_pieces(m, first, threads)) == madd::format_mesh_neigh(merged, first));
    CHECK(madd::detail::format_mesh_edge(m, first) == madd::format_mesh_edge(merged, first));
    if (first == 1) {
      CHECK(madd::detail::format_mesh_msh(m) == madd::format_mesh_msh(merged));
      CHECK(joined(madd::detail::mesh_vtu_pieces(m, threads)) == madd::format_mesh_vtu(merged));
    }
    for (std::uint32_t k = 0; k < merged.subdomain_count(); ++k) {
      CHECK(madd::detail::format_subdomain_mesh_node(m, k, first) ==
            madd::format_subdomain_mesh_node(merged, k, first));
      CHECK(madd::detail::format_subdomain_mesh_ele(m, k, first) == madd::format_subdomain_mesh_ele(merged, k, first));
    }
  }
}

}  // namespace

TEST_CASE("mesh_pieces_with_report: joined, mesh()'s mesh; its files and figures those of the merged mesh") {
  for (const Case& c : cases) {
    CAPTURE(c.file);
    const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + c.file);
    const madd::Mesh whole = madd::mesh(domain, options_of(domain, c, 1));
    const madd::MeshPieces one_thread = madd::mesh_pieces_with_report(domain, options_of(domain, c, 1)).mesh;
    for (const unsigned threads : {1u, 3u}) {
      CAPTURE(threads);
      const madd::MeshPiecesRun run = madd::mesh_pieces_with_report(domain, options_of(domain, c, threads));
      const madd::MeshPieces& pieces = run.mesh;
      CHECK(pieces == one_thread);  // the same pieces for any thread count
      REQUIRE(pieces.triangle_count() == whole.triangle_count());
      CHECK(pieces.point_count() == whole.points.size());
      CHECK(pieces.subdomain_count() == whole.subdomain_count());
      for (std::uint32_t k = 0; k < whole.subdomain_count(); ++k)
        CHECK(pieces.subdomain_triangle_count(k) ==
              whole.subdomain_first_triangle[k + 1] - whole.subdomain_first_triangle[k]);
      CHECK(pieces.shortfall() == whole.shortfall);
      check_same_files(whole, pieces, threads);
      CHECK(madd::mesh_metrics(pieces, {}, threads) == madd::mesh_metrics(whole, {}, threads));
      CHECK(madd::verify_mesh(pieces, domain, options_of(domain, c, 1).size, threads).ok());
      CHECK(madd::join(pieces, threads) == whole);
      // Its phases: the subdomains' checks inside refine, then the crossing ones.
      std::vector<std::string> names;
      for (const madd::PhaseTime& p : run.report.phases) names.push_back(p.name);
      CHECK(names == std::vector<std::string>{"decompose", "discretise", "estimate", "refine", "assemble", "verify"});
    }
  }
}

TEST_CASE("mesh_pieces_with_report: rings that touch at a vertex (an island on the coast) are checked right") {
  // Each subdomain is checked as a domain of its own; its local points list
  // a vertex where rings touch once, so its ring positions are no point ids
  // (a coastline's touching islands made every graded mesh of one bay fail
  // its check; the merged mesh's passed).
  madd::Pslg domain;
  domain.points = {{0, 0}, {5, 0}, {10, 0}, {10, 10}, {0, 10}, {6.5, 2.5}, {3.5, 2.5}, {8, 8}, {9, 8}, {8.5, 10}};
  // The square; an island touching its south side at (5, 0); another
  // touching its north side at (8.5, 10).
  domain.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 9, 1}, {9, 4, 1}, {4, 0, 1},
                     {1, 5, 1}, {5, 6, 1}, {6, 1, 1}, {9, 7, 1}, {7, 8, 1}, {8, 9, 1}};
  domain.holes = {{5, 1.5}, {8.5, 8.8}};
  for (const std::uint32_t n : {1u, 2u, 5u}) {
    CAPTURE(n);
    madd::MeshOptions o = madd::test::options_for(n, 30, 0.05);
    o.decomposition.threads = 2;
    const madd::MeshPiecesRun run = madd::mesh_pieces_with_report(domain, o);  // throws on a failed check
    CHECK(madd::verify_mesh(run.mesh, domain, o.size, 2).ok());
    CHECK(madd::join(run.mesh, 2) == madd::mesh(domain, o));
    // Every subdomain alone passes its check.
    const madd::detail::MeshPiecesData& m = run.mesh.data();
    const madd::detail::AreaBound bound(o.size, &domain);
    const std::vector<std::vector<madd::Region>> regions(m.subdomain_count());
    for (std::uint32_t k = 0; k < m.subdomain_count(); ++k)
      CHECK(madd::detail::check_subdomain(m.decomposition, k, regions[k], m.pieces[k], 30, bound).ok());
  }
}

TEST_CASE("model files from the pieces: fort.14, hgrid.gr3, .2dm and their boundary lists are the merged mesh's") {
  // The estuary with two boundary segments made open (marker 2): its loops
  // have open and land runs, and islands.
  madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/estuary.poly");
  REQUIRE(domain.segments.size() > 2);
  domain.has_segment_markers = true;
  for (madd::Segment& s : domain.segments) s.marker = 1;
  domain.segments[0].marker = domain.segments[1].marker = 2;
  const madd::test::TempDir dir("pieces-model");
  for (const unsigned threads : {1u, 3u}) {
    CAPTURE(threads);
    const madd::MeshPieces pieces = madd::mesh_pieces_with_report(domain, options_of(domain, cases[1], threads)).mesh;
    const madd::Mesh whole = madd::join(pieces, threads);
    const std::vector<madd::ModelBoundary> lists = madd::model_boundaries(pieces);
    CHECK(lists == madd::model_boundaries(whole));
    const auto has = [&](madd::BoundaryKind kind) {
      return std::any_of(lists.begin(), lists.end(), [&](const madd::ModelBoundary& l) { return l.kind == kind; });
    };
    CHECK(has(madd::BoundaryKind::open));
    CHECK(has(madd::BoundaryKind::mainland));
    CHECK(madd::model_boundaries(pieces, 1) == madd::model_boundaries(whole, 1));  // all open
    // Per-point columns in the merged numbering: the points themselves, and
    // other coordinates and depths made from them.
    const std::vector<madd::Point> points = madd::mesh_points(pieces, threads);
    REQUIRE(points == whole.points);
    madd::ModelGrid grid;
    grid.title = "estuary in pieces";
    for (const madd::Point p : points) {
      grid.coordinates.push_back({-70.0 + p.x / 100.0, 43.0 + p.y / 100.0});
      grid.depth.push_back(1.0 + 0.25 * p.x);
    }
    const std::string stem = (dir.path / ("e" + std::to_string(threads))).string();
    madd::OutputSet outputs;
    madd::add_fort14(outputs, stem + ".14", pieces, grid, threads);
    madd::add_gr3(outputs, stem + ".gr3", pieces, {}, threads);
    madd::add_2dm(outputs, stem + ".2dm", pieces, grid, threads);
    outputs.write();
    CHECK(madd::test::read_text(stem + ".14") == madd::format_fort14(whole, grid));
    CHECK(madd::test::read_text(stem + ".gr3") == madd::format_gr3(whole));
    CHECK(madd::test::read_text(stem + ".2dm") == madd::format_2dm(whole, grid));
    // The mesh in other coordinates (--lonlat): its files are the merged
    // mesh's with the points replaced.
    madd::Mesh moved = whole;
    moved.points = grid.coordinates;
    const madd::MeshPieces moved_pieces = madd::with_points(pieces, grid.coordinates, threads);
    check_same_files(moved, moved_pieces, threads);
    CHECK(madd::join(moved_pieces, threads).points == moved.points);
    CHECK_THROWS_AS(madd::with_points(pieces, std::vector<madd::Point>(points.size() - 1), threads), madd::OptionError);
  }
}

TEST_CASE("mesh_pieces_with_report: the estuary's region attributes and markers in the pieces' files") {
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/estuary.poly");
  const madd::MeshPiecesRun run = madd::mesh_pieces_with_report(domain, options_of(domain, cases[1], 2));
  REQUIRE(run.mesh.data().has_regions());
  const madd::Mesh whole = madd::join(run.mesh, 2);
  REQUIRE(whole.triangle_attribute.size() == whole.triangle_count());
  bool some_region = false;
  for (const double a : whole.triangle_attribute) some_region = some_region || a != 0.0;
  CHECK(some_region);
  // Two attributes a triangle in the pieces' .ele: the subdomain and the region's.
  const std::string ele = madd::detail::joined(madd::detail::mesh_ele_pieces(run.mesh.data(), 1, 2));
  CHECK(ele.substr(0, ele.find('\n')) == std::to_string(whole.triangle_count()) + " 3 2");
}

namespace {

// A defect made in a copy of the pieces, and whether the pieces' check and
// the merged mesh's check both report it.
struct Defect {
  const char* what;
  std::function<void(madd::detail::MeshPiecesData&)> make;
};

// The first triangle of piece k whose three links stay inside the piece.
std::uint32_t inner_triangle(const madd::detail::SubdomainMesh& p) {
  for (std::uint32_t t = 0; t < p.triangles.size(); ++t)
    if (p.neighbours[t][0] != madd::no_index && p.neighbours[t][1] != madd::no_index &&
        p.neighbours[t][2] != madd::no_index)
      return t;
  return madd::no_index;
}

// The first subdomain with a link across a separator.
std::uint32_t linked_subdomain(const madd::detail::MeshPiecesData& m) {
  for (std::uint32_t k = 0; k < m.across.size(); ++k)
    if (!m.across[k].empty()) return k;
  return madd::no_index;
}

}  // namespace

TEST_CASE("verify_pieces: every kind of defect is caught from the pieces, as the merged mesh's check catches it") {
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/estuary.poly");
  const madd::MeshOptions o = options_of(domain, cases[1], 2);
  const madd::MeshPiecesRun run = madd::mesh_pieces_with_report(domain, o);
  const madd::detail::MeshPiecesData& good = run.mesh.data();
  const madd::detail::AreaBound field(o.size, &domain);
  const std::vector<std::vector<madd::Region>> regions = madd::detail::region_view(good.decomposition).regions;
  REQUIRE(madd::detail::verify_pieces(good, domain, field, false, 2).ok());
  REQUIRE(madd::detail::verify_pieces(good, domain, field, true, 2).ok());
  // A subdomain with a region (its triangles carry attributes) and Steiner points.
  std::uint32_t k = 0;
  while (k < good.pieces.size() && (good.pieces[k].triangle_attribute.empty() ||
                                    good.pieces[k].points.size() < good.local[k].to_global.size() + 2))
    ++k;
  REQUIRE(k < good.pieces.size());
  const madd::detail::SubdomainMesh& piece = good.pieces[k];
  const std::uint32_t t = inner_triangle(piece);
  REQUIRE(t != madd::no_index);
  const std::uint32_t own = static_cast<std::uint32_t>(good.local[k].to_global.size());
  REQUIRE(piece.points.size() > own + 1);
  const std::uint32_t linked = linked_subdomain(good);
  REQUIRE(linked != madd::no_index);
  const std::vector<Defect> defects = {
      {"a triangle turned clockwise",
       [&](auto& m) { std::swap(m.pieces[k].triangles[t][0], m.pieces[k].triangles[t][1]); }},
      {"a Steiner point moved onto another", [&](auto& m) { m.pieces[k].points[own] = m.pieces[k].points[own + 1]; }},
      {"a link inside a piece cut",
       [&](auto& m) {
         const std::uint32_t u = m.pieces[k].neighbours[t][0];
         m.pieces[k].neighbours[t][0] = madd::no_index;
         for (auto& back : m.pieces[k].neighbours[u])
           if (back == t) back = madd::no_index;
       }},
      {"a triangle left out",
       [&](auto& m) {
         // The last triangle of the piece dropped, its neighbours' links to it cut.
         auto& p = m.pieces[k];
         const auto last = static_cast<std::uint32_t>(p.triangles.size() - 1);
         for (auto& links : p.neighbours)
           for (auto& u : links)
             if (u == last) u = madd::no_index;
         p.triangles.pop_back();
         p.neighbours.pop_back();
         if (!p.triangle_attribute.empty()) p.triangle_attribute.pop_back();
         for (std::size_t h = k + 1; h < m.first_triangle.size(); ++h) --m.first_triangle[h];
         for (auto& list : m.across)
           for (auto& [code, u] : list)
             if (u > m.first_triangle[k] + last) --u;
       }},
      {"a link across a separator pointed elsewhere", [&](auto& m) { m.across[linked][0].second += 1; }},
      {"a separator's two sides unlinked",
       [&](auto& m) {
         const auto [code, u] = m.across[linked][0];
         m.across[linked].erase(m.across[linked].begin());
         const std::uint32_t h = m.subdomain_of_triangle(u);
         std::erase_if(m.across[h], [&](const auto& e) { return e.second == m.first_triangle[linked] + code / 3; });
       }},
      {"a piece placed one point too far", [&](auto& m) { ++m.first_point[k]; }},
      {"a piece naming another decomposition point",
       [&](auto& m) { std::swap(m.local[k].to_global[0], m.local[k].to_global[1]); }},
      {"a mesh segment's marker changed", [&](auto& m) { m.segments.front().marker += 7; }},
      {"a decomposition point's marker changed", [&](auto& m) { m.point_markers[0] += 7; }},
      {"the shortfall miscounted",
       [&](auto& m) {
         m.pieces[k].shortfall.input_angle += 1;
         m.shortfall.input_angle += 1;
       }},
      {"the pieces' shortfall summed wrong", [&](auto& m) { m.shortfall.separator += 1; }},
      {"a region attribute changed",
       [&](auto& m) {
         REQUIRE(!m.pieces[k].triangle_attribute.empty());
         m.pieces[k].triangle_attribute[t] += 1;
       }},
  };
  for (const Defect& defect : defects) {
    const std::string what = defect.what;
    CAPTURE(what);
    madd::detail::MeshPiecesData bad = good;
    defect.make(bad);
    const madd::Verification from_pieces = madd::detail::verify_pieces(bad, domain, field, false, 2);
    CHECK_FALSE(from_pieces.ok());
    // The merged mesh of the same pieces fails its check too (the placement
    // defect aside: the merge would place the piece where it says).
    if (what != "a piece placed one point too far") {
      const madd::Mesh merged = madd::detail::join(madd::detail::MeshPiecesData(bad), 1);
      CHECK_FALSE(madd::verify_mesh(merged, domain, o.size).ok());
    }
  }
  // A subdomain given the wrong region (as if the decomposition's regions
  // were wrong): its triangles carry what its own check expects, but the
  // flood over the whole mesh, across the separators, says otherwise.
  {
    std::vector<std::vector<madd::Region>> wrong = regions;
    REQUIRE(!wrong[k].empty());
    madd::detail::MeshPiecesData bad = good;
    for (madd::Region& r : wrong[k]) r.attribute += 100;
    for (double& a : bad.pieces[k].triangle_attribute)
      for (const madd::Region& r : regions[k])
        if (a == r.attribute) a = r.attribute + 100;
    REQUIRE(
        madd::detail::check_subdomain(bad.decomposition, k, wrong[k], bad.pieces[k], bad.min_triangle_angle_deg, field)
            .ok());
    const madd::Verification v = madd::detail::verify_pieces(bad, domain, field, false, 2);
    CHECK_FALSE(v.ok());
    CHECK(std::any_of(v.problems.begin(), v.problems.end(),
                      [](const std::string& p) { return p.find("region attribute") != std::string::npos; }));
  }
  // A size bound below the one meshed to: caught piece by piece.
  madd::MeshSizeOptions finer = o.size;
  finer.max_triangle_area /= 2;
  const madd::detail::AreaBound finer_field(finer, &domain);
  CHECK_FALSE(madd::detail::verify_pieces(good, domain, finer_field, false, 2).ok());
  CHECK_FALSE(madd::verify_mesh(run.mesh, domain, finer, 2).ok());
}
