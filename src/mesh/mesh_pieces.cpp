// MeshPieces (include/madd/mesh_pieces.hpp): a value holding the pieces'
// data (src/mesh/mesh_pieces.hpp), its join and its check.
#include "madd/mesh_pieces.hpp"

#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <utility>

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
