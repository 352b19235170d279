// Reading the files a command line names (cli/command_line.hpp).
#include "command_line.hpp"

#include "madd/poly_io.hpp"

namespace madd::cli {

MeshOptions with_background_files(const CommandLine& line) {
  MeshOptions options = line.mesh;
  if (!line.weights_file.empty())
    options.decomposition.weight_samples = read_background_samples(line.weights_file, SampleValue::weight);
  if (!line.areas_file.empty())
    options.decomposition.subdomain_area_samples = read_background_samples(line.areas_file, SampleValue::area);
  if (!line.sizes_file.empty())
    options.size.triangle_area_samples = read_background_samples(line.sizes_file, SampleValue::area);
  return options;
}

}  // namespace madd::cli
