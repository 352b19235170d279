// MeshPieces (include/madd/mesh_pieces.hpp): a value holding the pieces'
// data (src/mesh/mesh_pieces.hpp), its join and its check.
#include "madd/mesh_pieces.hpp"

#include <algorithm>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "kernel/threads.hpp"
#include "madd/error.hpp"
#include "mesh/mesh_pieces.hpp"
#include "mesh/pieces_check.hpp"
#include "quality/area_bound.hpp"

namespace madd {

MeshPieces::MeshPieces() : data_(std::make_unique<detail::MeshPiecesData>()) {}
MeshPieces::MeshPieces(detail::MeshPiecesData data)
    : data_(std::make_unique<detail::MeshPiecesData>(std::move(data))) {}
MeshPieces::MeshPieces(const MeshPieces& other) : data_(std::make_unique<detail::MeshPiecesData>(*other.data_)) {}
MeshPieces::MeshPieces(MeshPieces&& other) noexcept : data_(std::move(other.data_)) {
  other.data_ = std::make_unique<detail::MeshPiecesData>();
}
MeshPieces& MeshPieces::operator=(const MeshPieces& other) {
  if (this != &other) *data_ = *other.data_;
  return *this;
}
MeshPieces& MeshPieces::operator=(MeshPieces&& other) noexcept {
  std::swap(data_, other.data_);
  return *this;
}
MeshPieces::~MeshPieces() = default;
bool operator==(const MeshPieces& a, const MeshPieces& b) { return *a.data_ == *b.data_; }

std::uint32_t MeshPieces::subdomain_count() const noexcept { return data_->subdomain_count(); }
std::uint64_t MeshPieces::point_count() const noexcept { return data_->point_count(); }
std::uint64_t MeshPieces::triangle_count() const noexcept { return data_->triangle_count(); }
std::uint64_t MeshPieces::subdomain_triangle_count(std::uint32_t k) const {
  return data_->first_triangle.at(k + 1) - data_->first_triangle.at(k);
}
const Decomposition& MeshPieces::decomposition() const noexcept { return data_->decomposition; }
MeshShortfall MeshPieces::shortfall() const noexcept { return data_->shortfall; }
double MeshPieces::min_triangle_angle_deg() const noexcept { return data_->min_triangle_angle_deg; }

Mesh join(MeshPieces pieces, unsigned threads) { return detail::join(std::move(*pieces.data_), threads); }

std::vector<Point> mesh_points(const MeshPieces& mesh, unsigned threads) {
  const detail::MeshPiecesData& m = mesh.data();
  std::vector<Point> out(m.point_count());
  std::copy(m.decomposition.points.begin(), m.decomposition.points.end(), out.begin());
  // Each subdomain's Steiner points are one run in the merged numbering.
  detail::for_each_on_threads(m.subdomain_count(), threads, [&](std::size_t i) {
    const auto k = static_cast<std::uint32_t>(i);
    const std::vector<Point>& local = m.pieces[k].points;
    const std::size_t own = m.local[k].to_global.size();
    if (local.size() > own)
      std::copy(local.begin() + static_cast<std::ptrdiff_t>(own), local.end(), out.begin() + m.first_point[k]);
  });
  return out;
}

MeshPieces with_points(MeshPieces mesh, const std::vector<Point>& points, unsigned threads) {
  detail::MeshPiecesData& m = *mesh.data_;
  if (points.size() != m.point_count())
    throw OptionError("points", "must hold one point per mesh point (" + std::to_string(m.point_count()) + "), not " +
                                    std::to_string(points.size()));
  std::copy(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(m.decomposition.points.size()),
            m.decomposition.points.begin());
  detail::for_each_on_threads(m.subdomain_count(), threads, [&](std::size_t i) {
    const auto k = static_cast<std::uint32_t>(i);
    std::vector<Point>& local = m.pieces[k].points;
    for (std::uint32_t v = 0; v < local.size(); ++v) local[v] = points[m.global_point(k, v)];
    Pslg& own = m.local[k].pslg;
    for (std::uint32_t v = 0; v < own.points.size(); ++v) own.points[v] = points[m.local[k].to_global[v]];
  });
  return mesh;
}

Verification verify_mesh(const MeshPieces& mesh, const Pslg& domain, const MeshSizeOptions& size, unsigned threads) {
  Verification result;
  std::optional<detail::AreaBound> bound;
  try {
    bound.emplace(size, &domain, threads);
  } catch (const std::exception& e) {
    result.add(std::string("the size bound could not be built: ") + e.what());
    return result;
  }
  return detail::verify_pieces(mesh.data(), domain, *bound, false, threads);
}

}  // namespace madd
