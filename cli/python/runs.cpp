#include "runs.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cstring>
#include <string>
#include <vector>

#include "../input_domain.hpp"
#include "../model_files.hpp"
#include "../point_set.hpp"
#include "arrays.hpp"
#include "domain.hpp"
#include "keywords.hpp"
#include "values.hpp"
#include "madd/bisect.hpp"
#include "madd/graph.hpp"

namespace madd::python {

namespace {

// ---- Keywords that are no text: samples as arrays, functions as callables ----

struct Special {
  std::vector<std::pair<const char*, std::vector<ValuedPoint>>> samples;
  std::vector<std::pair<const char*, PythonFunction>> functions;
  void rethrow_if_failed() const {
    for (const auto& f : functions) f.second.rethrow_if_failed();
  }
};

constexpr const char* sample_fields[] = {"triangle_area_samples", "weight_samples", "subdomain_area_samples"};
constexpr const char* function_fields[] = {"triangle_area_function", "weight_function", "subdomain_area_function"};

bool is_path(py::handle v) { return py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__"); }

std::vector<ValuedPoint> samples_of(py::handle value, const char* what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a || a.ndim() != 2 || a.shape(1) != 3)
    throw OptionError(what, "must be a path or an (n, 3) array of rows x, y, value");
  std::vector<ValuedPoint> out;
  for (py::ssize_t i = 0; i < a.shape(0); ++i) out.push_back({{a.at(i, 0), a.at(i, 1)}, a.at(i, 2)});
  return out;
}

// Takes the array and callable values out of `keywords` (the rest is text for the table).
Special take_special(py::dict& keywords) {
  Special special;
  for (const char* field : sample_fields)
    if (keywords.contains(field) && !is_path(keywords[field])) {
      special.samples.emplace_back(field, samples_of(keywords[field], field));
      PyDict_DelItemString(keywords.ptr(), field);
    }
  for (const char* field : function_fields)
    if (keywords.contains(field) && !py::isinstance<py::str>(keywords[field])) {
      const py::object f = keywords[field];
      if (!PyCallable_Check(f.ptr()))
        throw OptionError(field, "must be an expression in x and y, or a callable f(x, y)");
      special.functions.emplace_back(field, PythonFunction(f));
      PyDict_DelItemString(keywords.ptr(), field);
    }
  return special;
}

void apply_special(const Special& special, MeshOptions& options) {
  for (const auto& [field, samples] : special.samples) {
    if (std::strcmp(field, "triangle_area_samples") == 0) options.size.triangle_area_samples = samples;
    if (std::strcmp(field, "weight_samples") == 0) options.decomposition.weight_samples = samples;
    if (std::strcmp(field, "subdomain_area_samples") == 0) options.decomposition.subdomain_area_samples = samples;
  }
  for (const auto& [field, f] : special.functions) {
    if (std::strcmp(field, "triangle_area_function") == 0) options.size.triangle_area_function = f;
    if (std::strcmp(field, "weight_function") == 0) options.decomposition.weight_function = f;
    if (std::strcmp(field, "subdomain_area_function") == 0) options.decomposition.subdomain_area_function = f;
  }
}

// The decomposition's checks once the samples and functions of files,
// arrays and callables are in (two sources of weights contradict).
void check_decomposition(const MeshOptions& options, const cli::CommandLine& line, const cli::CommandOptions& command) {
  try {
    check_options(options.decomposition);
  } catch (const OptionError& e) {
    throw in_python_words(e, line, command);
  }
}

bool has_special(const Special& special, const char* field) {
  for (const auto& s : special.samples)
    if (std::strcmp(s.first, field) == 0) return true;
  return false;
}

// ---- Progress and interrupts ----

// Called on the thread that called the run, between its steps: takes the
// GIL, lets Python run its signal handlers (Ctrl-C raises KeyboardInterrupt
// here), then calls the user's callback; what either raises stops the run.
struct ProgressHook {
  py::object callback;  // None, or f(stage, done, total)
  void operator()(const char* stage, std::uint32_t done, std::uint32_t total) const {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!callback.is_none()) callback(stage, done, total);
  }
};

void hook_progress(MeshOptions& options, const std::shared_ptr<ProgressHook>& hook, bool meshing) {
  options.decomposition.progress = [hook](std::uint32_t done, std::uint32_t target) {
    (*hook)("decompose", done, target);
  };
  if (meshing) options.progress = [hook](std::uint32_t done, std::uint32_t total) { (*hook)("mesh", done, total); };
}

// The hook holds a Python object: freed with the GIL held, whoever drops it last.
std::shared_ptr<ProgressHook> make_hook(py::object callback) {
  return std::shared_ptr<ProgressHook>(new ProgressHook{std::move(callback)}, [](ProgressHook* h) {
    py::gil_scoped_acquire gil;
    delete h;
  });
}

// Runs `f` with the GIL released; an OptionError of a check that needs the
// domain (coast markers, an area function's values) is said in Python's words.
template <class F>
auto released(const cli::CommandLine& line, const cli::CommandOptions& command, F&& f) -> decltype(f()) {
  try {
    py::gil_scoped_release release;
    return f();
  } catch (const OptionError& e) {
    throw in_python_words(e, line, command);
  }
}

// ---- The runs ----

const cli::CommandOptions& mesh_command() { return cli::options_of("mesh"); }
const cli::CommandOptions& decompose_command() { return cli::options_of("decompose"); }

std::shared_ptr<MeshValue> run_mesh(py::handle domain_arg, py::handle n, py::handle q, py::handle max_area,
                                    py::handle threads, py::object progress, py::kwargs kw) {
  const Keywords keywords{"mesh", mesh_command(), &decompose_command()};
  cli::CommandLine line;
  py::dict values = kw;
  const Special special = take_special(values);
  apply_keyword(line, keywords, "n", n);
  if (!q.is_none()) apply_keyword(line, keywords, "q", q);
  if (!max_area.is_none()) apply_keyword(line, keywords, "max_area", max_area);
  apply_keyword(line, keywords, "threads", threads);
  apply_keywords(line, keywords, values);
  check_keywords(line, mesh_command(), has_special(special, "triangle_area_samples") || !line.sizes_file.empty(),
                 !line.depth_file.empty());
  auto result = std::make_shared<MeshValue>();
  result->domain = domain_argument(domain_arg, line);
  const DomainValue& domain = *result->domain;
  MeshOptions options;
  {
    py::gil_scoped_release release;
    options = cli::with_background_files(line);
    domain.check_domain();
    if (domain.from_polygons) cli::default_coast_markers(options.size, domain.coast, line.coast.open_marker);
    result->depth = cli::read_depth(line);
    if (result->depth) set_depth(options.size, *result->depth, domain.coast.projection);
  }
  apply_special(special, options);
  check_decomposition(options, line, mesh_command());
  hook_progress(options, make_hook(std::move(progress)), true);
  MeshRun run = released(line, mesh_command(), [&] { return mesh_with_report(domain.pslg(), options); });
  special.rethrow_if_failed();
  result->mesh = std::move(run.mesh);
  result->report = std::move(run.report);
  options.progress = nullptr;
  options.decomposition.progress = nullptr;
  result->size = std::move(options.size);
  result->threads = options.decomposition.threads;
  return result;
}

std::shared_ptr<DecompositionValue> run_decompose(py::handle domain_arg, py::handle n, py::object progress,
                                                  py::kwargs kw) {
  const Keywords keywords{"decompose", decompose_command()};
  cli::CommandLine line;
  line.mesh.decomposition = DecomposeOptions{};  // madd decompose's own defaults
  py::dict values = kw;
  const Special special = take_special(values);
  apply_keyword(line, keywords, "n", n);
  apply_keywords(line, keywords, values);
  check_keywords(line, decompose_command(), has_special(special, "triangle_area_samples") || !line.sizes_file.empty(),
                 false);
  auto result = std::make_shared<DecompositionValue>();
  result->domain = domain_argument(domain_arg, line);
  const DomainValue& domain = *result->domain;
  MeshOptions read;
  {
    py::gil_scoped_release release;
    read = cli::with_background_files(line);
  }
  apply_special(special, read);
  check_decomposition(read, line, decompose_command());
  hook_progress(read, make_hook(std::move(progress)), false);
  ValidateOptions validation;
  validation.check_weights = read.decomposition.gradation > 0;
  result->requested = read.decomposition.subdomains;
  result->decomposition = released(line, decompose_command(), [&] {
    const auto start = std::chrono::steady_clock::now();
    domain.check_domain(validation);
    DecomposeRun run = decompose_with_report(domain.pslg(), read.decomposition);
    result->times = run.report.phases;
    result->times.push_back(
        {"decompose", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    if (line.mesh.verify) {
      const Verification check = verify_decomposition(
          run.decomposition, domain.pslg(), expected_subdomain_count(run.decomposition, read.decomposition.subdomains));
      if (!check.ok()) throw InternalError("the decomposition failed its self-check: " + check.problems.front());
    }
    if (!read.size.has_size_bound()) return std::move(run.decomposition);
    MeshSizeOptions size = read.size;
    if (domain.from_polygons) cli::default_coast_markers(size, domain.coast, line.coast.open_marker);
    return discretise(run.decomposition, domain.pslg(), size, read.decomposition);
  });
  special.rethrow_if_failed();
  return result;
}

std::shared_ptr<TriangulationValue> run_triangulate(py::handle input, py::kwargs kw) {
  const Keywords keywords{"triangulate", cli::options_of("triangulate")};
  cli::CommandLine line;
  apply_keywords(line, keywords, kw);
  std::shared_ptr<const DomainValue> domain;
  if (py::isinstance<py::array>(input) || py::isinstance<py::list>(input) || py::isinstance<py::tuple>(input)) {
    auto points = std::make_shared<DomainValue>();
    points->coast.domain.first_index = 0;
    points->coast.domain.points = to_points(input, "points");
    domain = points;
  } else {
    domain = domain_argument(input, line);
  }
  auto result = std::make_shared<TriangulationValue>();
  result->options = line.triangulate;
  result->pslg = domain->pslg();
  py::gil_scoped_release release;
  Pslg& pslg = result->pslg;
  if (pslg.segments.empty()) {
    validate_pslg(pslg, domain->source);
    result->triangulation = cli::triangulate_points(pslg, domain->path.empty() ? "points" : domain->path);
    if (line.triangulate.region_attributes) result->triangulation = triangulate(pslg, line.triangulate);
  } else {
    result->triangulation = triangulate(pslg, line.triangulate);  // crossings were resolved as the file was read
  }
  const Verification check =
      verify_triangulation(result->triangulation, pslg.segments.empty() ? nullptr : &pslg, line.triangulate);
  if (!check.ok()) throw InternalError("the triangulation failed its check: " + check.problems.front());
  return result;
}

// A graph from CSR arrays (METIS's xadj/adjncy, scipy's indptr/indices).
Graph graph_of(py::handle indptr, py::handle indices, py::handle vertex_weights, py::handle edge_weights) {
  const auto offsets = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(indptr);
  const auto adjacency = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(indices);
  if (!offsets || !adjacency || offsets.ndim() != 1 || adjacency.ndim() != 1 || offsets.shape(0) < 1)
    throw InvalidInputError(InputProblem::other, "a graph needs indptr (n + 1,) and indices (m,) arrays");
  const auto n = static_cast<std::size_t>(offsets.shape(0) - 1);
  std::vector<double> vw(n, 1.0);
  if (!vertex_weights.is_none()) {
    const auto w = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vertex_weights);
    if (!w || w.ndim() != 1 || static_cast<std::size_t>(w.shape(0)) != n)
      throw InvalidInputError(InputProblem::bad_weight, "vertex_weights must hold one weight per vertex");
    vw.assign(w.data(), w.data() + n);
  }
  py::array_t<double, py::array::c_style | py::array::forcecast> ew;
  const bool weighted = !edge_weights.is_none();
  if (weighted) {
    ew = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(edge_weights);
    if (!ew || ew.ndim() != 1 || ew.shape(0) != adjacency.shape(0))
      throw InvalidInputError(InputProblem::bad_weight, "edge_weights must hold one weight per entry of indices");
  }
  std::vector<WeightedEdge> edges;
  const long long* o = offsets.data();
  const long long* a = adjacency.data();
  for (std::size_t v = 0; v < n; ++v) {
    if (o[v] < 0 || o[v] > o[v + 1] || o[v + 1] > adjacency.shape(0))
      throw InvalidInputError(InputProblem::other,
                              "indptr must rise from 0 to len(indices), at vertex " + std::to_string(v),
                              {static_cast<std::int64_t>(v)});
    for (long long k = o[v]; k < o[v + 1]; ++k) {
      if (a[k] < 0 || static_cast<std::size_t>(a[k]) >= n)
        throw InvalidInputError(InputProblem::other, "indices[" + std::to_string(k) + "] names no vertex",
                                {static_cast<std::int64_t>(k)});
      if (static_cast<std::size_t>(a[k]) > v)
        edges.push_back(
            {static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(a[k]), weighted ? ew.data()[k] : 1.0});
    }
  }
  return make_graph(std::move(vw), edges);
}

Partition run_partition(py::handle indptr, py::handle indices, std::uint32_t k, py::handle vertex_weights,
                        py::handle edge_weights, std::uint64_t seed, bool connected, double balance_tolerance) {
  if (k < 1) throw OptionError("k", "must be at least 1");
  PartitionOptions options;
  options.seed = seed;
  options.connected = connected;
  options.balance_tolerance = balance_tolerance;
  const Graph graph = graph_of(indptr, indices, vertex_weights, edge_weights);
  py::gil_scoped_release release;
  return partition(graph, k, options);
}

}  // namespace

void bind_runs(py::module_& m) {
  const std::string mesh_doc =
      "mesh(domain, n, q=None, max_area=None, threads=0, progress=None, **options) -> Mesh\n\n"
      "Decomposes the domain into n subdomains, splits every separator and boundary piece once to the local size "
      "(the Delaunay decoupling), refines every subdomain on its own thread and returns one conforming mesh, "
      "self-checked (verify_mesh). The same options give the same mesh, byte for byte, as `madd mesh`, for any "
      "thread count. The GIL is released while it works. domain: a madd.Domain, a path (.poly, .node, .geojson, "
      ".shp) or a shapely Polygon/MultiPolygon. progress(stage, done, total), stage 'decompose' or 'mesh', is "
      "called between steps and may raise to stop; Ctrl-C stops it too (KeyboardInterrupt).\n\n"
      "Options, as `madd mesh --help` gives them (the keyword is the C++ options field; the CLI flag follows). "
      "Sample options take a path or an (n, 3) array of x, y, value; function options an expression in x and y "
      "(fast) or a Python callable f(x, y) (called under the GIL).\n" +
      keywords_help(mesh_command(), &decompose_command());
  m.def("mesh", &run_mesh, py::arg("domain"), py::arg("n"), py::arg("q") = py::none(), py::arg("max_area") = py::none(),
        py::arg("threads") = 0, py::arg("progress") = py::none(), mesh_doc.c_str());
  const std::string decompose_doc =
      "decompose(domain, n, progress=None, **options) -> Decomposition\n\n"
      "The Medial Axis Domain Decomposition into n connected subdomains (paper Sec. 3-5): every new angle at "
      "least separator_angle_deg, short separators, balanced areas; self-checked (verify_decomposition). With a "
      "size option (max_triangle_area, triangle_area_function, the size field) every segment is split for "
      "meshes of that size, so that external meshers' pieces join up. The GIL is released while it works.\n\n"
      "Options, as `madd decompose --help` gives them:\n" +
      keywords_help(decompose_command());
  m.def("decompose", &run_decompose, py::arg("domain"), py::arg("n"), py::arg("progress") = py::none(),
        decompose_doc.c_str());
  const std::string triangulate_doc =
      "triangulate(domain_or_points, **options) -> Triangulation\n\n"
      "The constrained Delaunay triangulation of any PSLG (a madd.Domain or a path), as `triangle -p`; or the "
      "Delaunay triangulation of an (n, 2) array of points over their convex hull. Checked by "
      "verify_triangulation.\n\nOptions, as `madd triangulate --help` gives them:\n" +
      keywords_help(cli::options_of("triangulate"));
  m.def("triangulate", &run_triangulate, py::arg("domain_or_points"), triangulate_doc.c_str());
  m.def("partition", &run_partition, py::arg("indptr"), py::arg("indices"), py::arg("k"),
        py::arg("vertex_weights") = py::none(), py::arg("edge_weights") = py::none(), py::kw_only(),
        py::arg("seed") = 1, py::arg("connected") = false, py::arg("balance_tolerance") = 0.03,
        "partition(indptr, indices, k, vertex_weights=None, edge_weights=None, *, seed=1, connected=False, "
        "balance_tolerance=0.03) -> Partition\n\n"
        "A k-way partition of the graph given in CSR form (METIS's xadj/adjncy, or a scipy.sparse matrix's "
        "indptr/indices: each edge listed from both ends) by recursive multilevel bisection, as `madd "
        "partition` (gpmetis -ptype=rb). connected: make every part connected.");
}

}  // namespace madd::python
