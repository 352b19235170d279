#pragma once
// The C++ values the Python objects hold (docs/python.md): a Domain, and the
// results of decompose, mesh and triangulate, each with what its writers and
// checks need (the domain it was made from, the size options it was made to).
// Python owns them through shared_ptr: an array view keeps its object alive.
#include <pybind11/pybind11.h>

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "madd/bathymetry.hpp"
#include "madd/coast.hpp"
#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

namespace madd::python {

namespace py = pybind11;

// madd.Domain: a PSLG that passed validate_pslg, and where it came from.
struct DomainValue {
  CoastDomain coast;           // the PSLG (coast.domain), its projection and what cleaning did
  SourceMap source;            // lines of the file it was read from (errors say path:line)
  std::string path;            // the file, "" when built from arrays or geometry
  bool from_polygons = false;  // a coastline (GIS file, shapely): the open marker is no coast by default
  // Whether validate() (a domain, not only a PSLG) passed; checked once.
  mutable std::atomic<bool> is_domain{false};

  const Pslg& pslg() const noexcept { return coast.domain; }
  // validate() once (BadInput otherwise); decompose and mesh call it.
  void check_domain(const ValidateOptions& options = {}) const;
};

struct DecompositionValue {
  Decomposition decomposition;
  std::shared_ptr<const DomainValue> domain;
  std::vector<PhaseTime> times;
  std::uint32_t requested = 0;  // N as asked (a maximum with a required area)
};

struct MeshValue {
  Mesh mesh;
  MeshReport report;
  std::shared_ptr<const DomainValue> domain;
  MeshSizeOptions size;             // the bound it was refined to, for verify() and metrics()
  std::optional<DepthField> depth;  // the depth file's field, for the model files' depths
  unsigned threads = 0;
};

struct TriangulationValue {
  Pslg pslg;  // as triangulated (crossings resolved)
  Triangulation triangulation;
  TriangulateOptions options;
};

// A Python callable as a std::function the library may call from any of
// its threads: each call takes the GIL; copies share one reference, freed
// under the GIL. The first exception the callable raises is kept (the call
// returns NaN, "no bound", so the run goes on to its end) and raised by
// rethrow_if_failed once the run is over.
class PythonFunction {
public:
  explicit PythonFunction(py::object f);
  double operator()(double x, double y) const;
  void rethrow_if_failed() const;

private:
  struct State;
  std::shared_ptr<State> state_;
};

}  // namespace madd::python
