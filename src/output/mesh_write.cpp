// The mesh outputs on disk (include/madd/mesh_output.hpp): every file of a
// run goes into one OutputSet, so a failure leaves none of them half written
// and none of them written without the others.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kernel/threads.hpp"
#include "madd/error.hpp"
#include "madd/mesh_output.hpp"
#include "madd/mesh_pieces.hpp"
#include "madd/output.hpp"
#include "output/mesh_text.hpp"

namespace madd {

namespace {

bool ends_with(const std::string& s, std::string_view tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// "<stem>-<digits>.node" or ".ele": a piece an earlier run may have left.
bool is_split_mesh_name(const std::string& name, std::string_view stem) {
  const std::string prefix = std::string(stem) + "-";
  std::string_view extension;
  for (const std::string_view e : {std::string_view(".node"), std::string_view(".ele")})
    if (ends_with(name, e)) extension = e;
  if (extension.empty() || name.size() <= prefix.size() + extension.size()) return false;
  if (name.compare(0, prefix.size(), prefix) != 0) return false;
  for (std::size_t i = prefix.size(); i + extension.size() < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

}  // namespace

// The padding rule lives in split_file_name (output 2's names); only the
// extension differs.
std::string split_mesh_file_name(std::string_view stem, std::uint32_t k, std::uint32_t count,
                                 std::string_view extension) {
  std::string name = split_file_name(stem, k, count);
  name.resize(name.size() - std::string_view(".poly").size());
  name += extension;
  return name;
}

void add_mesh(OutputSet& outputs, const Mesh& mesh, const std::string& prefix, const MeshFormats& formats,
              unsigned threads) {
  detail::check_first_index(formats.first_index);
  if (formats.triangle) {
    outputs.add_file(prefix + ".node", detail::mesh_node_pieces(mesh, formats.first_index, threads));
    outputs.add_file(prefix + ".ele", detail::mesh_ele_pieces(mesh, formats.first_index, threads));
  }
  if (formats.neigh) outputs.add_file(prefix + ".neigh", detail::mesh_neigh_pieces(mesh, formats.first_index, threads));
  if (formats.edge) outputs.add_file(prefix + ".edge", format_mesh_edge(mesh, formats.first_index));
  if (formats.msh) outputs.add_file(prefix + ".msh", format_mesh_msh(mesh));
  if (formats.vtu) outputs.add_file(prefix + ".vtu", detail::mesh_vtu_pieces(mesh, threads));
}

void add_mesh(OutputSet& outputs, const MeshPieces& mesh, const std::string& prefix, const MeshFormats& formats,
              unsigned threads) {
  detail::check_first_index(formats.first_index);
  const detail::MeshPiecesData& m = mesh.data();
  if (formats.triangle) {
    outputs.add_file(prefix + ".node", detail::mesh_node_pieces(m, formats.first_index, threads));
    outputs.add_file(prefix + ".ele", detail::mesh_ele_pieces(m, formats.first_index, threads));
  }
  if (formats.neigh) outputs.add_file(prefix + ".neigh", detail::mesh_neigh_pieces(m, formats.first_index, threads));
  if (formats.edge) outputs.add_file(prefix + ".edge", detail::format_mesh_edge(m, formats.first_index));
  if (formats.msh) outputs.add_file(prefix + ".msh", detail::format_mesh_msh(m));
  if (formats.vtu) outputs.add_file(prefix + ".vtu", detail::mesh_vtu_pieces(m, threads));
}

void write_mesh(const Mesh& mesh, const std::string& prefix, const MeshFormats& formats, unsigned threads) {
  OutputSet outputs;
  add_mesh(outputs, mesh, prefix, formats, threads);
  outputs.write();
}

void add_split_mesh(OutputSet& outputs, const Mesh& mesh, const std::string& dir, std::string_view stem,
                    unsigned first_index, unsigned threads) {
  detail::check_first_index(first_index);
  const std::uint32_t count = mesh.subdomain_count();
  // Each subdomain's two files on the threads, into their own slots.
  std::vector<std::pair<std::string, std::string>> files(2 * std::size_t{count});
  detail::for_each_on_threads(count, threads, [&](std::size_t i) {
    const auto k = static_cast<std::uint32_t>(i);
    files[2 * i] = {split_mesh_file_name(stem, k, count, ".node"), format_subdomain_mesh_node(mesh, k, first_index)};
    files[2 * i + 1] = {split_mesh_file_name(stem, k, count, ".ele"), format_subdomain_mesh_ele(mesh, k, first_index)};
  });
  outputs.add_directory(dir, std::move(files),
                        [stem = std::string(stem)](const std::string& name) { return is_split_mesh_name(name, stem); });
}

void add_split_mesh(OutputSet& outputs, const MeshPieces& mesh, const std::string& dir, std::string_view stem,
                    unsigned first_index, unsigned threads) {
  detail::check_first_index(first_index);
  const detail::MeshPiecesData& m = mesh.data();
  const std::uint32_t count = m.subdomain_count();
  std::vector<std::pair<std::string, std::string>> files(2 * std::size_t{count});
  detail::for_each_on_threads(count, threads, [&](std::size_t i) {
    const auto k = static_cast<std::uint32_t>(i);
    files[2 * i] = {split_mesh_file_name(stem, k, count, ".node"),
                    detail::format_subdomain_mesh_node(m, k, first_index)};
    files[2 * i + 1] = {split_mesh_file_name(stem, k, count, ".ele"),
                        detail::format_subdomain_mesh_ele(m, k, first_index)};
  });
  outputs.add_directory(dir, std::move(files),
                        [stem = std::string(stem)](const std::string& name) { return is_split_mesh_name(name, stem); });
}

void write_split_mesh(const Mesh& mesh, const std::string& dir, std::string_view stem, unsigned first_index,
                      unsigned threads) {
  OutputSet outputs;
  add_split_mesh(outputs, mesh, dir, stem, first_index, threads);
  outputs.write();
}

}  // namespace madd
