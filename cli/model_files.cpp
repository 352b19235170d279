#include "model_files.hpp"

#include <filesystem>

#include "madd/mesh_output.hpp"

namespace madd::cli {

namespace {

// hgrid.ll beside hgrid.gr3: the same path with .ll for its extension.
std::string ll_path(const std::string& gr3) { return std::filesystem::path(gr3).replace_extension(".ll").string(); }

std::vector<Point> in_lonlat(const std::vector<Point>& points, const Projection& projection) {
  std::vector<Point> out;
  out.reserve(points.size());
  for (const Point p : points) out.push_back(projection.to_lonlat(p));
  return out;
}

}  // namespace

std::optional<DepthField> read_depth(const CommandLine& line) {
  if (line.depth_file.empty()) return std::nullopt;
  return DepthField(read_bathymetry(line.depth_file, line.depth_up));
}

bool wants_model_files(const CommandLine& line, const Projection& projection) {
  const bool model = !line.fort14_file.empty() || !line.gr3_file.empty() || !line.sms_file.empty();
  return model || (line.lonlat && projection.geographic);
}

namespace {

// The mesh's points in the merged numbering: a Mesh's own array; a mesh in
// pieces has none, so they are made into `made`.
const std::vector<Point>& points_of(const Mesh& mesh, std::vector<Point>&, unsigned) { return mesh.points; }
const std::vector<Point>& points_of(const MeshPieces& mesh, std::vector<Point>& made, unsigned threads) {
  made = mesh_points(mesh, threads);
  return made;
}

void keep_lonlat_mesh(const Mesh& mesh, const std::vector<Point>& lonlat, ModelFiles& files, unsigned) {
  files.lonlat_mesh = mesh;
  files.lonlat_mesh.points = lonlat;
}
void keep_lonlat_mesh(const MeshPieces& mesh, const std::vector<Point>& lonlat, ModelFiles& files, unsigned threads) {
  files.lonlat_pieces = with_points(mesh, lonlat, threads);
}
const Mesh& lonlat_mesh(const Mesh&, const ModelFiles& files) { return files.lonlat_mesh; }
const MeshPieces& lonlat_mesh(const MeshPieces&, const ModelFiles& files) { return files.lonlat_pieces; }

template <typename AnyMesh>
bool add_model_files_of(OutputSet& outputs, ModelFiles& files, const AnyMesh& mesh, const CommandLine& line,
                        const std::string& prefix, const Projection& projection, const std::optional<DepthField>& depth,
                        unsigned threads, const std::string& title) {
  if (!wants_model_files(line, projection)) return false;
  const bool model = !line.fort14_file.empty() || !line.gr3_file.empty() || !line.sms_file.empty();
  const bool columns = projection.geographic || (depth && model);
  std::vector<Point> made;  // (only while the columns are made)
  const std::vector<Point>& points = columns ? points_of(mesh, made, threads) : made;
  const std::vector<Point> lonlat = projection.geographic ? in_lonlat(points, projection) : std::vector<Point>{};
  files.metres.title = !title.empty() ? title : std::filesystem::path(prefix).filename().string() + " (madd mesh)";
  if (depth && model) files.metres.depth = depths_at(*depth, projection.geographic ? lonlat : points, threads);
  files.lonlat = files.metres;
  files.lonlat.coordinates = lonlat;
  const ModelGrid& written = projection.geographic ? files.lonlat : files.metres;
  if (!line.fort14_file.empty()) add_fort14(outputs, line.fort14_file, mesh, written, threads);
  if (!line.gr3_file.empty()) {
    add_gr3(outputs, line.gr3_file, mesh, files.metres, threads);
    if (projection.geographic) add_gr3(outputs, ll_path(line.gr3_file), mesh, files.lonlat, threads);
  }
  if (!line.sms_file.empty()) add_2dm(outputs, line.sms_file, mesh, line.lonlat ? written : files.metres, threads);
  if (!line.lonlat || !projection.geographic) return false;  // metres are the file's own units then
  keep_lonlat_mesh(mesh, lonlat, files, threads);
  add_mesh(outputs, lonlat_mesh(mesh, files), prefix, line.formats, threads);
  return true;
}

}  // namespace

bool add_model_files(OutputSet& outputs, ModelFiles& files, const Mesh& mesh, const CommandLine& line,
                     const std::string& prefix, const Projection& projection, const std::optional<DepthField>& depth,
                     unsigned threads, const std::string& title) {
  return add_model_files_of(outputs, files, mesh, line, prefix, projection, depth, threads, title);
}

bool add_model_files(OutputSet& outputs, ModelFiles& files, const MeshPieces& mesh, const CommandLine& line,
                     const std::string& prefix, const Projection& projection, const std::optional<DepthField>& depth,
                     unsigned threads, const std::string& title) {
  return add_model_files_of(outputs, files, mesh, line, prefix, projection, depth, threads, title);
}

}  // namespace madd::cli
