// Output 2 on disk: one .poly per subdomain, staged as one directory so that a
// failure never leaves a partial set of files (docs/formats.md).
#include <string>
#include <utility>
#include <vector>

#include "madd/atomic_write.hpp"
#include "madd/output.hpp"
#include "output/faces.hpp"
#include "output/subdomain_poly.hpp"

namespace madd {

namespace {

// "<stem>-<digits>.poly": a file an earlier run of write_split may have made.
bool is_split_name(const std::string& name, std::string_view stem) {
  const std::string prefix = std::string(stem) + "-";
  if (name.size() <= prefix.size() + 5 || name.compare(0, prefix.size(), prefix) != 0) return false;
  if (name.compare(name.size() - 5, 5, ".poly") != 0) return false;
  for (std::size_t i = prefix.size(); i + 5 < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

}  // namespace

void add_split(OutputSet& outputs, const Decomposition& d, const std::string& dir, std::string_view stem) {
  const auto count = static_cast<std::uint32_t>(d.subdomains.size());
  std::vector<std::pair<std::string, std::string>> files;
  files.reserve(count);
  // The faces (for the input's regions) once for all files.
  const std::vector<detail::DecompositionFace> faces =
      d.regions.empty() ? std::vector<detail::DecompositionFace>{} : detail::decomposition_faces(d);
  for (std::uint32_t k = 0; k < count; ++k)
    files.emplace_back(split_file_name(stem, k, count), detail::format_subdomain_poly(d, k, faces));
  outputs.add_directory(dir, std::move(files),
                        [stem = std::string(stem)](const std::string& name) { return is_split_name(name, stem); });
}

void write_split(const Decomposition& d, const std::string& dir, std::string_view stem) {
  OutputSet outputs;
  add_split(outputs, d, dir, stem);
  outputs.write();
}

}  // namespace madd
