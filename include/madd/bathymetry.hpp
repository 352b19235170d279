#pragma once
// Bathymetry: the depth of the water at every point of a coastal domain
// (positive below the datum), read from an Esri ASCII grid or an x y z
// scatter (docs/formats.md, "Bathymetry"), read between its samples, and the
// two rules by which depth bounds the edge length of a coastal mesh.
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "madd/geometry.hpp"

namespace madd {

namespace detail {
struct DepthModel;  // the interpolant (src/sizing/bathymetry.cpp)
}  // namespace detail

// A regular grid of depths at cell centres. Cell (col, row) has its centre at
// (x0 + col*dx, y0 + row*dy) and its depth at values[row*cols + col]: rows
// run from the south row (row 0) northwards, the reverse of the file's order.
// A cell whose value is the NODATA value has no depth (NaN matches NaN); a
// grid with a NaN nodata does not compare equal to itself, as doubles do not.
struct DepthGrid {
  std::size_t cols = 0, rows = 0;
  double x0 = 0.0, y0 = 0.0;  // the centre of the south-west cell
  double dx = 0.0, dy = 0.0;  // the cell's width and height (> 0)
  std::vector<double> values;
  bool has_nodata = false;
  double nodata = -9999.0;
  // Whether values[index] is a depth (not the NODATA value).
  bool has_value(std::size_t index) const noexcept {
    const double v = values[index];
    return !has_nodata || !(v == nodata || (v != v && nodata != nodata));
  }
  friend bool operator==(const DepthGrid&, const DepthGrid&) = default;
};

// Depths on a grid or at scattered points (each point's value its depth).
struct Bathymetry {
  std::variant<DepthGrid, std::vector<ValuedPoint>> data;
  friend bool operator==(const Bathymetry&, const Bathymetry&) = default;
};

// Parses Esri ASCII grid text (.asc): the header keys ncols, nrows,
// xllcorner and yllcorner (or xllcenter and yllcenter), cellsize (or dx and
// dy), and the optional NODATA_value (-9999 when absent, as Esri says), in
// any order and any case, then nrows*ncols numbers, the north row first,
// laid out on any lines. Throws ParseError ("path:line:column: message") on
// a malformed or non-finite token, a missing, repeated or contradictory key,
// a cell size <= 0, too few or too many values, a grid the text cannot hold
// (never allocates for it), or no depth at all (every value NODATA). The
// values are kept as written (depths, or elevations for read_bathymetry to
// turn round).
DepthGrid parse_esri_ascii_grid(std::string_view text, const std::string& path = "<memory>");

// Parses x y z scatter text: one point a line, its three numbers separated
// by whitespace or by a comma (with optional whitespace around it); '#'
// starts a comment, blank lines are skipped, and a first line of three names
// ("x,y,z", "lon lat depth") is a header and skipped. Throws ParseError on a
// malformed, missing, extra or non-finite field, on a point given twice, on
// fewer than 3 points and on points all on one line.
std::vector<ValuedPoint> parse_xyz(std::string_view text, const std::string& path = "<memory>");

// Reads a bathymetry file: an Esri ASCII grid when its name ends in .asc (any
// case), else an x y z scatter. With positive_up (the CLI's --depth-up) the
// file holds elevations, positive up, and the depth is minus the value (a
// grid's NODATA value is turned round too, so that the same cells have no
// depth). Throws InputFileError when the file cannot be read, ParseError as
// the parsers do.
Bathymetry read_bathymetry(const std::string& path, bool positive_up = false);

// The depth at any point of the plane, and its gradient, read between the
// samples of a Bathymetry:
// - grid: bilinear between the centres of the four cells around p, the
//   corners without a depth left out and the weights of the others
//   renormalised; outside the rectangle of the cell centres, the value at
//   the nearest point of that rectangle (so the field is continuous across
//   the grid's border); where none of the four corners has a depth (or those
//   that do have weight 0), the depth of the cell with a depth nearest to the
//   cell centre nearest p (found by a Euclidean distance transform of the
//   grid when the field is built: one table lookup per query);
// - scatter: linear over the Delaunay triangulation of the points; outside
//   their convex hull the depth of the nearest point (the smallest squared
//   distance, ties to the lowest index).
// gradient_at is the gradient of that interpolant: of the bilinear in the
// cell (its east and north cell on a cell border; zero along a direction in
// which p was moved onto the rectangle, and where the nearest cell decides),
// constant in a triangle (the lowest-numbered triangle holding p), zero
// outside the hull. A value type, cheap to copy (copies share the immutable
// interpolant), whose queries are safe from any number of threads.
class DepthField {
public:
  // No bathymetry: every depth and gradient is NaN.
  DepthField() = default;
  // Builds the interpolant. Throws InvalidInputError when `bathymetry` is not
  // one the readers could return: a grid whose sizes, spacing, origin or
  // values are not finite and consistent, or that has no depth at all; a
  // scatter with a non-finite point or value, fewer than 3 points, all on one
  // line, or a point given twice.
  explicit DepthField(Bathymetry bathymetry);

  // NaN when p is not finite (or the field is empty).
  double depth_at(Point p) const noexcept;
  Point gradient_at(Point p) const noexcept;

  // The bathymetry it reads (an empty scatter for an empty field).
  const Bathymetry& bathymetry() const noexcept;
  bool empty() const noexcept { return model_ == nullptr; }
  // The same bathymetry.
  friend bool operator==(const DepthField& a, const DepthField& b) noexcept;

private:
  friend std::vector<double> depths_at(const DepthField&, std::span<const Point>, unsigned);
  std::shared_ptr<const detail::DepthModel> model_;
};

// field.depth_at of every point, on `threads` threads (0: one per core); the
// same values for any thread count (a scatter's points are visited along a
// Hilbert curve, which changes no value). At most 2^32 - 2 points (else
// InvalidInputError).
std::vector<double> depths_at(const DepthField& field, std::span<const Point> points, unsigned threads = 1);

// The period of the M2 tide (12.4206 h) and the gravity of the two rules.
inline constexpr double m2_period_seconds = 44714.16;
inline constexpr double gravity = 9.81;

// The wavelength rule: `cells` edges per wavelength of the M2 tide in water
// of that depth, h = T*sqrt(g*depth)/cells with T = m2_period_seconds and
// g = gravity (depth in metres: h in metres). +infinity where it does not
// bind: depth <= 0 (land, the datum) or NaN, or cells not > 0.
double wavelength_edge(double depth, double cells) noexcept;

// The slope rule: `cells` edges across the distance over which the depth
// changes by 2*pi times itself, h = 2*pi*depth / (cells*|grad depth|), with
// gradient_length = |grad depth| in metres of depth per unit of the
// coordinates (h is then in those units). +infinity where it does not bind:
// depth <= 0 or NaN, gradient_length <= 0 or NaN, or cells not > 0.
double slope_edge(double depth, double gradient_length, double cells) noexcept;

}  // namespace madd
