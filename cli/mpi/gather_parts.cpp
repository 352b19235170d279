#include "gather_parts.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

#include "madd/error.hpp"

namespace madd::mpi {

namespace {

constexpr std::size_t chunk_bytes = std::size_t{1} << 30;

// A vector of trivially copyable values: its size, then its bytes.
class Packer {
public:
  template <typename T>
  void put(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put_value(static_cast<std::uint64_t>(values.size()));
    if (values.empty()) return;  // data() may be null
    text_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  template <typename T>
  void put_value(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    text_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  std::string take() { return std::move(text_); }

private:
  std::string text_;
};

class Unpacker {
public:
  explicit Unpacker(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  void get(std::vector<T>& values) {
    std::uint64_t n = 0;
    get_value(n);
    if (n > (bytes_.size() - at_) / std::max<std::size_t>(sizeof(T), 1))
      throw InternalError("madd-mpi: a gathered part is shorter than its sizes say");
    values.resize(n);
    if (n > 0) std::memcpy(values.data(), bytes_.data() + at_, n * sizeof(T));
    at_ += n * sizeof(T);
  }
  template <typename T>
  void get_value(T& value) {
    if (bytes_.size() - at_ < sizeof(T)) throw InternalError("madd-mpi: a gathered part is cut short");
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
  }

private:
  std::string_view bytes_;
  std::size_t at_ = 0;
};

std::string pack(const MeshPart& p) {
  Packer out;
  out.put_value(p.share), out.put_value(p.shares);
  out.put(p.owner), out.put(p.subdomains);
  const LocalMesh& m = p.mesh;
  out.put(m.points), out.put(m.point_markers), out.put(m.triangles), out.put(m.neighbours);
  out.put(m.triangle_subdomain), out.put(m.triangle_attribute), out.put(m.subdomain_first_triangle);
  out.put(m.segments);
  out.put_value(m.shortfall), out.put_value(m.min_triangle_angle_deg);
  out.put(p.point_ids), out.put(p.point_owner), out.put(p.triangle_ids);
  out.put_value(p.total_points), out.put_value(p.total_triangles);
  return out.take();
}

MeshPart unpack(std::string_view bytes, const Decomposition& decomposition) {
  Unpacker in(bytes);
  MeshPart p;
  in.get_value(p.share), in.get_value(p.shares);
  in.get(p.owner), in.get(p.subdomains);
  LocalMesh& m = p.mesh;
  in.get(m.points), in.get(m.point_markers), in.get(m.triangles), in.get(m.neighbours);
  in.get(m.triangle_subdomain), in.get(m.triangle_attribute), in.get(m.subdomain_first_triangle);
  in.get(m.segments);
  in.get_value(m.shortfall), in.get_value(m.min_triangle_angle_deg);
  in.get(p.point_ids), in.get(p.point_owner), in.get(p.triangle_ids);
  in.get_value(p.total_points), in.get_value(p.total_triangles);
  p.decomposition = decomposition;
  return p;
}

void send_bytes(const std::string& bytes) {
  std::uint64_t size = bytes.size();
  MPI_Send(&size, 1, MPI_UINT64_T, 0, 0, MPI_COMM_WORLD);
  for (std::size_t at = 0; at < bytes.size(); at += chunk_bytes) {
    const int n = static_cast<int>(std::min(chunk_bytes, bytes.size() - at));
    MPI_Send(bytes.data() + at, n, MPI_CHAR, 0, 1, MPI_COMM_WORLD);
  }
}

std::string receive_bytes(int from) {
  std::uint64_t size = 0;
  MPI_Recv(&size, 1, MPI_UINT64_T, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::string bytes(size, '\0');
  for (std::size_t at = 0; at < bytes.size(); at += chunk_bytes) {
    const int n = static_cast<int>(std::min<std::size_t>(chunk_bytes, bytes.size() - at));
    MPI_Recv(bytes.data() + at, n, MPI_CHAR, from, 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
  return bytes;
}

}  // namespace

std::vector<MeshPart> gather_parts(const MeshPart& own, int rank, int size) {
  if (rank != 0) {
    send_bytes(pack(own));
    return {};
  }
  std::vector<MeshPart> parts;
  parts.push_back(own);
  for (int r = 1; r < size; ++r) parts.push_back(unpack(receive_bytes(r), own.decomposition));
  return parts;
}

}  // namespace madd::mpi
