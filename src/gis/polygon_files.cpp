// Reading a polygon file from disk by its extension (include/madd/polygons.hpp).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "madd/error.hpp"
#include "madd/polygons.hpp"

namespace madd {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The whole file, or nothing when it is missing and `optional`.
std::string slurp(const std::string& path, bool optional) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw InputFileError(path + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (optional && !std::filesystem::exists(path)) return {};
    throw InputFileError(path + ": cannot open file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputFileError(path + ": cannot read file");
  return text.str();
}

// The companion file of a shapefile: the same stem with `ext`, in the case
// the .shp was written in (FOO.SHP beside FOO.SHX).
std::string companion(const std::string& shp, const std::string& ext) {
  std::filesystem::path p(shp);
  const std::string own = p.extension().string();
  const bool upper = !own.empty() && std::isupper(static_cast<unsigned char>(own.back()));
  std::string e = ext;
  if (upper)
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  p.replace_extension(e);
  return p.string();
}

}  // namespace

bool is_polygon_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".geojson" || ext == ".json" || ext == ".shp";
}

PolygonSet read_polygons(const std::string& path) {
  if (lower_extension(path) == ".shp") {
    const std::string shp = slurp(path, false);
    const std::string shx = slurp(companion(path, ".shx"), true);
    const std::string prj = slurp(companion(path, ".prj"), true);
    return parse_shapefile(shp, shx, prj, path);
  }
  return parse_geojson(slurp(path, false), path);
}

}  // namespace madd
