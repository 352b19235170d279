#pragma once
// Meshing the subdomains (docs/mesh.md): the Delaunay decoupling of
// Linardakis and Chrisochoides (SIAM J. Sci. Comput. 27(4), 2006), which the
// MADD decomposition exists for. Every separator, boundary and interior
// piece is split once, globally, to the local target size (discretise), then each subdomain
// is refined on its own, with no communication, by Ruppert/Chew Delaunay
// refinement with Ungor's off-centres, never splitting a separator; the
// subdomain meshes share their separator vertices by construction, so their
// union conforms.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd {

// The size bounds and the angle bound of a mesh's triangles (not the
// decomposition's subdomains: DecomposeOptions has their own). A triangle is
// too large when its area exceeds the smallest of max_triangle_area,
// triangle_area_function at its centroid and the nearest triangle area
// sample (each when set), and the max_area of the input region it lies in
// (Region::max_area > 0; Triangle's -a with regional constraints).
struct MeshSizeOptions {
  double min_triangle_angle_deg =
      30.0;                        // -q: every triangle's smallest angle at least this, away from small input angles
  double max_triangle_area = 0.0;  // -a: 0 = no bound
  // --size-fn: the largest allowed triangle area at (x, y); values <= 0 or
  // NaN are ignored there (no bound).
  std::function<double(double x, double y)> triangle_area_function;
  // --sizes, a background size file: samples of the largest allowed triangle
  // area; the bound at a point is the value of the nearest sample (ties: the
  // lowest index).
  std::vector<ValuedPoint> triangle_area_samples;
  // How a point between the samples reads them: linearly over the samples'
  // Delaunay triangulation (the value of the nearest sample outside its hull),
  // or the nearest sample's value (ties: the lowest index).
  enum class SampleInterpolation { linear, nearest };
  SampleInterpolation sample_interpolation = SampleInterpolation::linear;

  // The size field (docs/mesh.md, "Size field"), in edge lengths h(x): a
  // triangle's area bound is that of the equilateral triangle of side h,
  // sqrt(3)/4 h^2, and the field is the smallest of the terms that are set
  // (each 0 = off), then limited by size_gradation:
  double min_edge_length = 0.0;  // --hmin: the distance term's h at the coast, and a floor of the feature-size term
  double max_edge_length = 0.0;  // --hmax: h <= hmax everywhere
  double distance_rate = 0.0;    // --distance-rate G: h <= hmin + G d, d the distance to the coast
  double cells_across = 0.0;     // --cells-across R: h <= 2 width / R, width the local half-width of the water
  double size_gradation = 0.0;   // --gradation G: the field satisfies h(x) <= h(y) + G |x - y|
  // The boundary markers that count as coast for the distance and the
  // feature size (empty: every boundary segment is coast).
  std::vector<int> coast_markers;
  // The depth rules of coastal models (docs/coastal.md, "Depth"), on the
  // water depth (positive below the datum, in the domain's units) and its
  // gradient, e.g. a DepthField's (madd/bathymetry.hpp) read through
  // madd/coast.hpp's set_depth; where the depth is <= 0 (land, drying
  // banks) they do not bind. Each term is floored at min_edge_length, like
  // the feature-size term.
  std::function<double(double x, double y)> depth;
  std::function<Point(double x, double y)> depth_gradient;
  double wavelength_cells = 0.0;  // --wavelength-cells K: h <= T_M2 sqrt(g depth) / K (needs depth)
  double slope_cells = 0.0;       // --slope-cells K: h <= 2 pi depth / (K |grad depth|) (needs depth, depth_gradient)

  // A field term that needs the domain: distance, feature size, depth rules, gradation.
  bool has_field_terms() const noexcept {
    return distance_rate > 0.0 || cells_across > 0.0 || size_gradation > 0.0 || has_depth_terms();
  }
  bool has_depth_terms() const noexcept { return wavelength_cells > 0.0 || slope_cells > 0.0; }
  bool has_size_bound() const noexcept {
    return max_triangle_area > 0.0 || triangle_area_function || !triangle_area_samples.empty() ||
           max_edge_length > 0.0 || has_field_terms();
  }
};

struct MeshOptions {
  // How the domain is decomposed first (N, Phi0, threads, limits...).
  // decomposition.threads is also the number of meshing threads (-j), and
  // its time and memory limits apply to meshing as well (checked every few
  // thousand new vertices of each subdomain; LimitError, nothing returned).
  // Its balance repair starts at 1.1 x the mean here (1.2 for a bare
  // decomposition): a thread's time is its subdomains' triangles.
  DecomposeOptions decomposition = [] {
    DecomposeOptions d;
    d.repair_balance_above = 1.1;
    return d;
  }();
  MeshSizeOptions size;
  // Balance by work (docs/mesh.md, "Balance by work"): decompose by the expected
  // triangle count of each subdomain rather than its area. Only when the
  // decomposition options give no weights of their own.
  bool balance_by_work = true;
  // Insert Ungor's off-centre instead of a far circumcentre (fewer triangles,
  // the same guarantee).
  bool off_centres = true;
  // Run verify_mesh before returning (a quarter of the time or more; off
  // only when the caller checks the mesh itself).
  bool verify = true;
  // Progress: called on the calling thread with the number of subdomains
  // meshed so far and N. Like DecomposeOptions::progress it cannot change
  // the result; if it throws, mesh() stops and rethrows.
  std::function<void(std::uint32_t done, std::uint32_t total)> progress;
};

// One mesh edge on a segment of the discretised decomposition: a boundary
// edge (in one triangle; the input's marker, never 0), an interior-segment
// edge (in two triangles of the one subdomain the piece is interior to; the
// input's marker, never 0) or a separator edge (in one triangle of each of
// its two subdomains; marker 0).
struct MeshSegment {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  int marker = 0;
  std::uint32_t piece = 0;  // the segment of Mesh::decomposition it lies on
  friend bool operator==(const MeshSegment&, const MeshSegment&) = default;
};

// Why triangles stayed below the angle bound (docs/mesh.md, "Guarantee").
struct MeshShortfall {
  std::size_t input_angle = 0;  // the small angle is an input angle (two segments meeting below the bound), or
                                // its short edge joins two segments at one apex (concentric shells)
  std::size_t separator = 0;    // fixing it would split a separator (the decoupling was not enough there)
  std::size_t precision = 0;    // the new point would be closer to a vertex than coordinates resolve
  std::size_t limit = 0;        // the Steiner point budget of the subdomain was spent
  std::size_t total() const noexcept { return input_angle + separator + precision + limit; }
  friend bool operator==(const MeshShortfall&, const MeshShortfall&) = default;
};

// The merged mesh: one conforming triangulation of the domain.
struct Mesh {
  // The discretised decomposition the mesh was made on (its points are the
  // mesh's first points, same indices).
  Decomposition decomposition;
  std::vector<Point> points;
  // Triangle's rule: the marker of the boundary or interior segment a point
  // lies on (the larger where several meet), 0 for points inside the domain
  // (isolated input vertices included) or only on separators.
  std::vector<int> point_markers;
  // Counter-clockwise, grouped by subdomain: the triangles of subdomain k are
  // [subdomain_first_triangle[k], subdomain_first_triangle[k + 1]).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // neighbours[t][i]: the triangle across edge i (opposite vertex i), across
  // separators too; no_index on the domain boundary.
  std::vector<std::array<std::uint32_t, 3>> neighbours;
  std::vector<std::uint32_t> triangle_subdomain;
  // Triangle's -A (docs/mesh.md, "Interior constraints and regions"): with
  // regions in the input (decomposition.regions not empty), per triangle the
  // attribute of the region whose face holds it (the face flooded from the
  // region point without crossing a boundary or interior segment; separators
  // are crossed; of two region points in one face the later wins), 0 in no
  // region. Empty when the input has no regions.
  std::vector<double> triangle_attribute;
  std::vector<std::uint32_t> subdomain_first_triangle;  // N + 1 offsets
  // Every mesh edge on a boundary piece, interior piece or separator, by
  // piece, then along it.
  std::vector<MeshSegment> segments;
  MeshShortfall shortfall;
  double min_triangle_angle_deg = 30.0;  // the bound it was refined to

  std::size_t triangle_count() const noexcept { return triangles.size(); }
  std::uint32_t subdomain_count() const noexcept {
    return subdomain_first_triangle.empty() ? 0 : static_cast<std::uint32_t>(subdomain_first_triangle.size() - 1);
  }
  friend bool operator==(const Mesh&, const Mesh&) = default;
};

// Timings and work figures of one run (not part of the result: they vary
// from run to run).
struct MeshReport {
  std::vector<PhaseTime> phases;           // "decompose", "discretise", "refine", "merge", "verify"
  std::vector<double> thread_seconds;      // busy time of each meshing thread
  std::vector<double> subdomain_seconds;   // time to mesh each subdomain
  std::vector<double> expected_triangles;  // the work estimate of each subdomain (docs/mesh.md, "Balance by work")
  friend bool operator==(const MeshReport&, const MeshReport&) = default;
};

// A mesh and the report of the run that made it.
struct MeshRun {
  Mesh mesh;
  MeshReport report;
  friend bool operator==(const MeshRun&, const MeshRun&) = default;
};

// The ranges of the mesh options (min_triangle_angle_deg in [0, 60),
// max_triangle_area finite and >= 0, area samples finite with areas > 0, the
// size field's terms finite and >= 0, max_edge_length >= min_edge_length when
// both are set) and their combinations (distance_rate needs min_edge_length,
// size_gradation another size bound); throws OptionError naming the field.
// mesh() calls it; the decomposition options are checked by decompose(), the
// coast markers against the domain by the size field.
void check_options(const MeshOptions& options);

// The largest allowed area at p under `size` (+infinity when unbounded).
// The size field's terms (distance, feature size, gradation) need the
// domain: without it they throw OptionError.
double area_bound_at(const MeshSizeOptions& size, Point p);
double area_bound_at(const MeshSizeOptions& size, const Pslg& domain, Point p);

// Decomposes the domain, discretises it and meshes every subdomain on
// options.decomposition.threads threads. Deterministic: byte-identical for
// any thread count. Throws OptionError on bad options, what decompose()
// throws, LimitError on a resource limit, and InternalError when the self-check
// (verify_mesh) fails; never returns a partial mesh.
Mesh mesh(const Pslg& domain, const MeshOptions& options = {});
// mesh(), with the times of its phases, threads and subdomains: the same mesh.
MeshRun mesh_with_report(const Pslg& domain, const MeshOptions& options = {});

// Meshes an existing decomposition of `domain` (decompose() output), with
// its report (no "decompose" phase).
MeshRun mesh_decomposition(const Decomposition& decomposition, const Pslg& domain, const MeshOptions& options);

// The decoupling step alone: every segment of the decomposition split into
// pieces short enough for the size bound and the local feature size, the
// split points computed once from each segment's endpoints in index order,
// so both subdomains of a separator get the same points. Each subdomain of
// the result, meshed by any mesher that keeps its boundary segments
// (`triangle -pq30Y`), joins its neighbours conformingly. The size field's
// terms need the decomposed domain (the second form; the first throws
// OptionError when they are set).
Decomposition discretise(const Decomposition& decomposition, const MeshSizeOptions& size);
Decomposition discretise(const Decomposition& decomposition, const Pslg& domain, const MeshSizeOptions& size);
// The same within `limits`' time_limit_seconds and max_memory_bytes (from
// this call; 0: none): a size bound far below the segments' lengths asks for
// millions of points a segment, and past a limit this throws
// LimitError instead.
Decomposition discretise(const Decomposition& decomposition, const Pslg& domain, const MeshSizeOptions& size,
                         const DecomposeOptions& limits);

// Checks, independently of how the mesh was made: every triangle CCW and
// non-degenerate, adjacency symmetric and matching shared edges; the
// triangles cover the domain exactly (areas summed exactly); conforming (every
// interior edge in two triangles, no vertex inside another triangle's edge, each
// separator matched edge for edge by its two subdomains, each boundary piece
// covered by boundary edges, each interior piece by a chain of edges with
// triangles of its subdomain on both sides); every isolated input vertex a
// mesh vertex of its subdomain; each subdomain's triangulation constrained
// Delaunay (exact incircle across every unconstrained edge); the region
// attributes those of a flood from the region points; every triangle within
// the size bound and its region's area bound; and every triangle's smallest angle at least the
// bound minus 1e-9 degrees, except those counted in mesh.shortfall (their
// number must match). Never throws on a malformed mesh: it reports problems.
Verification verify_mesh(const Mesh& mesh, const Pslg& domain, const MeshSizeOptions& size);

}  // namespace madd
