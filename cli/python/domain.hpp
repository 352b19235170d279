#pragma once
// madd.Domain, madd.Projection and the readers (docs/python.md, "Domains").
#include <pybind11/pybind11.h>

#include <memory>

#include "../command_line.hpp"
#include "values.hpp"

namespace madd::python {

void bind_domain(pybind11::module_& m);

// The domain a function was given: a madd.Domain, or a path read as the CLI
// reads its INPUT (a .poly/.node, or a GeoJSON/shapefile coast cut and
// cleaned by `line`'s coast options). Coast options with a Domain raise
// madd.OptionError (they apply to a file only).
std::shared_ptr<const DomainValue> domain_argument(pybind11::handle argument, const cli::CommandLine& line);

}  // namespace madd::python
