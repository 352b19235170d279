#include "results.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "../model_files.hpp"
#include "../triangulation_files.hpp"
#include "arrays.hpp"
#include "values.hpp"
#include "madd/atomic_write.hpp"
#include "madd/bisect.hpp"
#include "madd/mesh_metrics.hpp"
#include "madd/mesh_output.hpp"
#include "madd/metrics.hpp"
#include "madd/model_output.hpp"
#include "madd/output.hpp"
#include "madd/output_formats.hpp"

namespace madd::python {

namespace {

std::string fspath(py::handle path) { return py::module_::import("os").attr("fspath")(path).cast<std::string>(); }

// Writes `outputs` (all or nothing) with the GIL released.
void write_all(OutputSet& outputs) {
  py::gil_scoped_release release;
  outputs.write();
}

// One file whose contents `make()` formats, with the GIL released.
template <class Make>
void write_one(py::handle path, Make&& make) {
  const std::string file = fspath(path);
  py::gil_scoped_release release;
  OutputSet outputs;
  outputs.add_file(file, make());
  outputs.write();
}

py::object json_dict(const std::string& json) { return py::module_::import("json").attr("loads")(json); }

py::list problems_of(const Verification& check) { return py::cast(check.problems); }

// The file name without directories and a .poly/.node extension (madd
// decompose's stem of the split files).
std::string stem_of(const std::string& path, const char* fallback) {
  if (path.empty()) return fallback;
  std::filesystem::path p(path);
  const std::string ext = p.extension().string();
  return ext == ".poly" || ext == ".node" ? p.stem().string() : p.filename().string();
}

// ---- Decomposition ----

const Decomposition& decomposition_of(py::handle self) { return self.cast<const DecompositionValue&>().decomposition; }

py::dict subdomain_dict(const Subdomain& s) {
  py::dict d;
  py::list rings;
  for (const auto& ring : s.rings)
    rings.append(py::array_t<std::uint32_t>(static_cast<py::ssize_t>(ring.size()), ring.data()));
  d["rings"] = rings;
  d["area"] = s.area;
  d["weight"] = s.weight;
  d["required_area"] = s.required_area;
  d["interior_point"] = py::make_tuple(s.interior_point.x, s.interior_point.y);
  py::list holes;
  for (const Point p : s.hole_points) holes.append(py::make_tuple(p.x, p.y));
  d["hole_points"] = holes;
  d["interior_segments"] = py::cast(s.interior_segments);
  d["interior_points"] = py::cast(s.interior_points);
  return d;
}

SvgOptions svg_options(double width, bool numbers, double mark_angles_below_deg) {
  SvgOptions o;
  o.width = width;
  o.numbers = numbers;
  o.mark_angles_below_deg = mark_angles_below_deg;
  return o;
}

void bind_decomposition(py::module_& m) {
  py::class_<DecompositionValue, std::shared_ptr<DecompositionValue>>(
      m, "Decomposition",
      "A conforming subdivision of the domain into subdomains (paper Sec. 3-5): shared points and segments "
      "(marker 0: a separator), each subdomain's rings (outer counter-clockwise, then holes).")
      .def_property_readonly("points", [](py::object self) { return points_view(self, decomposition_of(self).points); })
      .def_property_readonly("segments",
                             [](py::object self) { return index_view(self, decomposition_of(self).segments, 2); })
      .def_property_readonly(
          "markers",
          [](py::object self) {
            return field_view<std::int32_t>(self, decomposition_of(self).segments, offsetof(Segment, marker));
          },
          "Per segment: 0 for a separator, else the input segment's marker (1 where it had none).")
      .def_property_readonly(
          "segment_origin",
          [](py::object self) {
            return vector_view<std::int32_t, std::uint32_t>(self, decomposition_of(self).segment_origin);
          },
          "Per segment: the input segment it is a piece of, -1 for a separator.")
      .def_property_readonly(
          "separators",
          [](const DecompositionValue& v) {
            std::vector<std::int32_t> out;
            for (std::uint32_t s = 0; s < v.decomposition.segments.size(); ++s)
              if (v.decomposition.is_separator(s)) out.push_back(static_cast<std::int32_t>(s));
            return py::array_t<std::int32_t>(static_cast<py::ssize_t>(out.size()), out.data());
          },
          "The indices of the separator segments.")
      .def_property_readonly("subdomain_count",
                             [](const DecompositionValue& v) { return v.decomposition.subdomains.size(); })
      .def("__len__", [](const DecompositionValue& v) { return v.decomposition.subdomains.size(); })
      .def_property_readonly("areas",
                             [](const DecompositionValue& v) {
                               std::vector<double> a;
                               for (const Subdomain& s : v.decomposition.subdomains) a.push_back(s.area);
                               return py::array_t<double>(static_cast<py::ssize_t>(a.size()), a.data());
                             })
      .def_property_readonly(
          "subdomains",
          [](const DecompositionValue& v) {
            py::list out;
            for (const Subdomain& s : v.decomposition.subdomains) out.append(subdomain_dict(s));
            return out;
          },
          "Per subdomain a dict: rings (index arrays into points), area, weight, required_area, "
          "interior_point, hole_points, interior_segments, interior_points.")
      .def_property_readonly("separator_angle_deg",
                             [](const DecompositionValue& v) { return v.decomposition.separator_angle_deg; })
      .def_property_readonly("domain", [](const DecompositionValue& v) { return v.domain; })
      .def(
          "metrics",
          [](const DecompositionValue& v) { return json_dict(format_report_json(metrics(v.decomposition, v.times))); },
          "Every figure of docs/quality.md (C1 angles, C2 separators, C3 balance) and the phase times, as "
          "`madd --report` prints them.")
      .def(
          "verify",
          [](const DecompositionValue& v) {
            Verification check;
            {
              py::gil_scoped_release release;
              check = verify_decomposition(v.decomposition, v.domain->pslg(),
                                           expected_subdomain_count(v.decomposition, v.requested));
            }
            return problems_of(check);
          },
          "The independent check (verify_decomposition): a list of problems, empty when valid.")
      .def(
          "to_svg",
          [](const DecompositionValue& v, double width, bool numbers, double mark) {
            return format_svg(v.decomposition, svg_options(width, numbers, mark));
          },
          py::arg("width") = 1000.0, py::arg("numbers") = false, py::arg("mark_angles_below_deg") = 0.0,
          "The picture of `madd --svg` as text.")
      .def("_repr_svg_",
           [](const DecompositionValue& v) { return format_svg(v.decomposition, svg_options(600, false, 0)); })
      .def(
          "write_poly",
          [](const DecompositionValue& v, py::handle path) {
            const std::string header =
                v.domain->path.empty() ? std::string("made by madd") : "made by madd from " + v.domain->path;
            write_one(path, [&] { return format_decomposition_poly(v.decomposition, header); });
          },
          py::arg("path"), "The whole subdivision as one .poly, one region per subdomain (`madd -o`).")
      .def(
          "write_svg",
          [](const DecompositionValue& v, py::handle path, double width, bool numbers, double mark) {
            write_one(path, [&] { return format_svg(v.decomposition, svg_options(width, numbers, mark)); });
          },
          py::arg("path"), py::arg("width") = 1000.0, py::arg("numbers") = false,
          py::arg("mark_angles_below_deg") = 0.0, "`madd --svg` (--svg-numbers, --svg-mark-angles).")
      .def(
          "write_geo",
          [](const DecompositionValue& v, py::handle path, double mesh_size) {
            GeoOptions o;
            o.mesh_size = mesh_size;
            write_one(path, [&] { return format_geo(v.decomposition, o); });
          },
          py::arg("path"), py::arg("mesh_size") = 0.0, "A gmsh .geo model (`madd --geo`).")
      .def(
          "write_vtk",
          [](const DecompositionValue& v, py::handle path) {
            write_one(path, [&] { return format_vtk(v.decomposition); });
          },
          py::arg("path"), "Legacy VTK (`madd --vtk`).")
      .def(
          "write_geojson",
          [](const DecompositionValue& v, py::handle path) {
            write_one(path, [&] { return format_geojson(v.decomposition); });
          },
          py::arg("path"), "GeoJSON, a Polygon feature per subdomain (`madd --geojson`).")
      .def(
          "write_subdomains",
          [](const DecompositionValue& v, py::handle path) {
            write_one(path, [&] { return format_subdomain_file(v.decomposition); });
          },
          py::arg("path"), "The paper's subdomain file (`madd --subdomains-file`).")
      .def(
          "write_split",
          [](const DecompositionValue& v, py::handle dir, py::object stem) {
            OutputSet outputs;
            add_split(outputs, v.decomposition, fspath(dir),
                      stem.is_none() ? stem_of(v.domain->path, "domain") : stem.cast<std::string>());
            write_all(outputs);
          },
          py::arg("dir"), py::arg("stem") = py::none(),
          "One .poly per subdomain, DIR/STEM-K.poly (`madd --split DIR`; STEM: the input's name).")
      .def("__repr__", [](const DecompositionValue& v) {
        return "<madd.Decomposition: " + std::to_string(v.decomposition.subdomains.size()) + " subdomains, " +
               std::to_string(v.decomposition.points.size()) + " points, " +
               std::to_string(v.decomposition.segments.size()) + " segments>";
      });
}

// ---- Mesh ----

const Mesh& mesh_of(py::handle self) { return self.cast<const MeshValue&>().mesh; }

// The boundary edges of a mesh (pieces of boundary segments: not separators,
// not interior constraints), as (E, 2) ends and (E,) markers.
py::tuple boundary_edges(const MeshValue& v) {
  const Decomposition& d = v.mesh.decomposition;
  const std::vector<std::uint32_t> owner = interior_segment_owners(d);
  std::vector<std::int32_t> ends, markers;
  for (const MeshSegment& s : v.mesh.segments) {
    if (d.is_separator(s.piece) || owner[s.piece] != no_index) continue;
    ends.push_back(static_cast<std::int32_t>(s.a));
    ends.push_back(static_cast<std::int32_t>(s.b));
    markers.push_back(s.marker);
  }
  py::array_t<std::int32_t> e(std::vector<py::ssize_t>{static_cast<py::ssize_t>(markers.size()), 2}, ends.data());
  return py::make_tuple(e, py::array_t<std::int32_t>(static_cast<py::ssize_t>(markers.size()), markers.data()));
}

// The files of `madd mesh -o PREFIX` that `line` names, made as it makes them.
void write_mesh_files(const MeshValue& v, const cli::CommandLine& line, const std::string& prefix,
                      const std::string& title = {}) {
  OutputSet outputs;
  cli::ModelFiles model_files;
  const std::optional<DepthField>& depth = v.depth;
  if (!cli::add_model_files(outputs, model_files, v.mesh, line, prefix, v.domain->coast.projection, depth, v.threads,
                            title)) {
    if (line.formats.triangle || line.formats.neigh || line.formats.edge || line.formats.msh || line.formats.vtu)
      add_mesh(outputs, v.mesh, prefix, line.formats, v.threads);
  }
  if (!line.split_mesh_dir.empty()) {
    const std::string stem = std::filesystem::path(prefix).filename().string();
    add_split_mesh(outputs, v.mesh, line.split_mesh_dir, stem, line.formats.first_index, v.threads);
  }
  write_all(outputs);
}

void write_single(const MeshValue& v, py::handle path, bool MeshFormats::*format) {
  // PREFIX.ext through add_mesh, so that the bytes are the CLI's.
  std::filesystem::path p(fspath(path));
  cli::CommandLine line;
  line.formats.triangle = false;
  line.formats.*format = true;
  write_mesh_files(v, line, (p.parent_path() / p.stem()).string());
}

void write_model(const MeshValue& v, py::handle path, std::string cli::CommandLine::*file, py::object title,
                 bool lonlat) {
  cli::CommandLine line;
  line.formats.triangle = false;
  line.*file = fspath(path);
  line.lonlat = lonlat;
  write_mesh_files(v, line, std::filesystem::path(line.*file).stem().string(),
                   title.is_none() ? std::filesystem::path(line.*file).stem().string() + " (madd)"
                                   : title.cast<std::string>());
}

void bind_mesh(py::module_& m) {
  py::class_<MeshValue, std::shared_ptr<MeshValue>>(
      m, "Mesh",
      "One conforming quality triangle mesh of the domain, the union of every subdomain's mesh. Arrays are "
      "read-only views of the result (no copy); .copy() one to change it.")
      .def_property_readonly(
          "points", [](py::object self) { return points_view(self, mesh_of(self).points); },
          "(N, 2) float64: the vertices (the decomposition's points first).")
      .def_property_readonly(
          "triangles", [](py::object self) { return index_view(self, mesh_of(self).triangles, 3); },
          "(M, 3) int32: counter-clockwise, grouped by subdomain.")
      .def_property_readonly(
          "subdomain",
          [](py::object self) {
            return vector_view<std::int32_t, std::uint32_t>(self, mesh_of(self).triangle_subdomain);
          },
          "(M,) int32: each triangle's subdomain.")
      .def_property_readonly(
          "neighbours", [](py::object self) { return index_view(self, mesh_of(self).neighbours, 3); },
          "(M, 3) int32: the triangle across the edge opposite each corner, -1 on the boundary.")
      .def_property_readonly(
          "point_markers",
          [](py::object self) { return vector_view<std::int32_t, int>(self, mesh_of(self).point_markers); },
          "(N,) int32: the marker of the boundary or interior segment a point lies on, else 0.")
      .def_property_readonly(
          "attributes",
          [](py::object self) {
            const Mesh& mesh = mesh_of(self);
            return mesh.triangle_attribute.empty() ? py::object(py::none())
                                                   : py::object(vector_view<double>(self, mesh.triangle_attribute));
          },
          "(M,) float64: the region attribute of each triangle (None without regions).")
      .def_property_readonly(
          "subdomain_first_triangle",
          [](py::object self) {
            return vector_view<std::int32_t, std::uint32_t>(self, mesh_of(self).subdomain_first_triangle);
          },
          "(N + 1,) int32: subdomain k's triangles are [first[k], first[k + 1]).")
      .def_property_readonly(
          "edges", [](py::object self) { return index_view(self, mesh_of(self).segments, 2); },
          "(S, 2) int32: every mesh edge on a boundary, interior or separator segment.")
      .def_property_readonly(
          "edge_markers",
          [](py::object self) {
            return field_view<std::int32_t>(self, mesh_of(self).segments, offsetof(MeshSegment, marker));
          },
          "(S,) int32: the input segment's marker; 0 on separators.")
      .def_property_readonly(
          "boundary_edges", [](const MeshValue& v) { return py::object(boundary_edges(v)[0]); },
          "(E, 2) int32: the edges on the domain's boundary (a copy).")
      .def_property_readonly(
          "boundary_markers", [](const MeshValue& v) { return py::object(boundary_edges(v)[1]); },
          "(E,) int32: their markers.")
      .def_property_readonly("triangle_count", [](const MeshValue& v) { return v.mesh.triangle_count(); })
      .def_property_readonly("subdomain_count", [](const MeshValue& v) { return v.mesh.subdomain_count(); })
      .def("__len__", [](const MeshValue& v) { return v.mesh.triangle_count(); })
      .def_property_readonly("min_triangle_angle_deg", [](const MeshValue& v) { return v.mesh.min_triangle_angle_deg; })
      .def_property_readonly(
          "shortfall",
          [](const MeshValue& v) {
            py::dict d;
            d["input_angle"] = v.mesh.shortfall.input_angle;
            d["separator"] = v.mesh.shortfall.separator;
            d["precision"] = v.mesh.shortfall.precision;
            d["limit"] = v.mesh.shortfall.limit;
            return d;
          },
          "Why triangles stayed below the angle bound (docs/mesh.md, \"Guarantee\").")
      .def_property_readonly(
          "decomposition",
          [](const MeshValue& v) {
            auto d = std::make_shared<DecompositionValue>();
            d->decomposition = v.mesh.decomposition;
            d->domain = v.domain;
            d->requested = v.mesh.subdomain_count();
            return d;
          },
          "The discretised decomposition the mesh was made on (a copy).")
      .def_property_readonly("domain", [](const MeshValue& v) { return v.domain; })
      .def_property_readonly(
          "report",
          [](const MeshValue& v) {
            const std::string json = format_mesh_report_json(MeshMetrics{}, run_figures(v.report));
            py::dict all = json_dict(json);
            py::dict run;
            for (const RunFigure& f : run_figures(v.report)) run[f.name.c_str()] = all[f.name.c_str()];
            return run;
          },
          "The run's figures (seconds by phase and thread, predicted triangles): vary run to run.")
      .def(
          "metrics",
          [](const MeshValue& v) {
            return json_dict(format_mesh_report_json(mesh_metrics(v.mesh, v.size, v.threads)));
          },
          "The mesh's figures, as `madd mesh --report` prints them (angles, histogram, balance).")
      .def(
          "verify",
          [](const MeshValue& v) {
            Verification check;
            {
              py::gil_scoped_release release;
              check = verify_mesh(v.mesh, v.domain->pslg(), v.size);
            }
            return problems_of(check);
          },
          "The independent check (verify_mesh): a list of problems, empty when valid.")
      .def(
          "write",
          [](const MeshValue& v, py::handle prefix, bool neigh, bool edge, bool msh, bool vtu, unsigned first_index,
             py::object fort14, py::object gr3, py::object sms2dm, bool lonlat, py::object split_mesh) {
            cli::CommandLine line;
            line.formats.neigh = neigh;
            line.formats.edge = edge;
            line.formats.msh = msh;
            line.formats.vtu = vtu;
            line.formats.first_index = first_index;
            if (!fort14.is_none()) line.fort14_file = fspath(fort14);
            if (!gr3.is_none()) line.gr3_file = fspath(gr3);
            if (!sms2dm.is_none()) line.sms_file = fspath(sms2dm);
            if (!split_mesh.is_none()) line.split_mesh_dir = fspath(split_mesh);
            line.lonlat = lonlat;
            write_mesh_files(v, line, fspath(prefix));
          },
          py::arg("prefix"), py::kw_only(), py::arg("neigh") = false, py::arg("edge") = false, py::arg("msh") = false,
          py::arg("vtu") = false, py::arg("first_index") = 1, py::arg("fort14") = py::none(),
          py::arg("gr3") = py::none(), py::arg("sms2dm") = py::none(), py::arg("lonlat") = false,
          py::arg("split_mesh") = py::none(),
          "What `madd mesh -o PREFIX` writes, byte for byte: PREFIX.node and PREFIX.ele, and with the keywords "
          "--neigh, --edge, --msh, --vtu, --fort14 FILE, --gr3 FILE, --2dm FILE, --lonlat, --split-mesh DIR. "
          "All or nothing (madd.OutputError).")
      .def(
          "write_node",
          [](const MeshValue& v, py::handle path, unsigned first) {
            write_one(path, [&] { return format_mesh_node(v.mesh, first); });
          },
          py::arg("path"), py::arg("first_index") = 1, "Triangle's .node.")
      .def(
          "write_ele",
          [](const MeshValue& v, py::handle path, unsigned first) {
            write_one(path, [&] { return format_mesh_ele(v.mesh, first); });
          },
          py::arg("path"), py::arg("first_index") = 1, "Triangle's .ele (the subdomain as attribute).")
      .def(
          "write_neigh",
          [](const MeshValue& v, py::handle path, unsigned first) {
            write_one(path, [&] { return format_mesh_neigh(v.mesh, first); });
          },
          py::arg("path"), py::arg("first_index") = 1, "Triangle's .neigh.")
      .def(
          "write_edge",
          [](const MeshValue& v, py::handle path, unsigned first) {
            write_one(path, [&] { return format_mesh_edge(v.mesh, first); });
          },
          py::arg("path"), py::arg("first_index") = 1, "Triangle's .edge.")
      .def(
          "write_msh", [](const MeshValue& v, py::handle path) { write_single(v, path, &MeshFormats::msh); },
          py::arg("path"), "gmsh 4.1, a physical surface per subdomain (PATH must end in .msh).")
      .def(
          "write_vtu", [](const MeshValue& v, py::handle path) { write_single(v, path, &MeshFormats::vtu); },
          py::arg("path"), "VTK XML, the subdomain as cell data (PATH must end in .vtu).")
      .def(
          "write_fort14",
          [](const MeshValue& v, py::handle path, py::object title) {
            write_model(v, path, &cli::CommandLine::fort14_file, title, false);
          },
          py::arg("path"), py::arg("title") = py::none(),
          "ADCIRC fort.14 (lon/lat for a lon/lat coast; depths from the mesh's `depth` file).")
      .def(
          "write_gr3",
          [](const MeshValue& v, py::handle path, py::object title) {
            write_model(v, path, &cli::CommandLine::gr3_file, title, false);
          },
          py::arg("path"), py::arg("title") = py::none(),
          "SCHISM hgrid.gr3 in metres, hgrid.ll beside it for a lon/lat coast.")
      .def(
          "write_2dm",
          [](const MeshValue& v, py::handle path, py::object title, bool lonlat) {
            write_model(v, path, &cli::CommandLine::sms_file, title, lonlat);
          },
          py::arg("path"), py::arg("title") = py::none(), py::arg("lonlat") = false, "SMS .2dm with nodestrings.")
      .def(
          "write_split",
          [](const MeshValue& v, py::handle dir, py::object stem, unsigned first) {
            OutputSet outputs;
            add_split_mesh(outputs, v.mesh, fspath(dir),
                           stem.is_none() ? stem_of(v.domain->path, "mesh") : stem.cast<std::string>(), first,
                           v.threads);
            write_all(outputs);
          },
          py::arg("dir"), py::arg("stem") = py::none(), py::arg("first_index") = 1,
          "One .node/.ele per subdomain in DIR with global vertex ids (`--split-mesh`).")
      .def("__repr__", [](const MeshValue& v) {
        return "<madd.Mesh: " + std::to_string(v.mesh.triangle_count()) + " triangles, " +
               std::to_string(v.mesh.points.size()) + " points, " + std::to_string(v.mesh.subdomain_count()) +
               " subdomains>";
      });
}

// ---- Triangulation, Partition ----

const Triangulation& triangulation_of(py::handle self) { return self.cast<const TriangulationValue&>().triangulation; }

void bind_triangulation(py::module_& m) {
  py::class_<TriangulationValue, std::shared_ptr<TriangulationValue>>(
      m, "Triangulation", "A constrained Delaunay triangulation of a PSLG (or the Delaunay triangulation of points).")
      .def_property_readonly("points", [](py::object self) { return points_view(self, triangulation_of(self).points); })
      .def_property_readonly("triangles",
                             [](py::object self) { return index_view(self, triangulation_of(self).triangles, 3); })
      .def_property_readonly("neighbours",
                             [](py::object self) { return index_view(self, triangulation_of(self).neighbours, 3); })
      .def_property_readonly(
          "segment_of", [](py::object self) { return index_view(self, triangulation_of(self).segment_of, 3); },
          "(M, 3) int32: the input segment each edge lies on, -1 when unconstrained.")
      .def_property_readonly("attributes",
                             [](py::object self) {
                               const Triangulation& t = triangulation_of(self);
                               return t.attributes.empty() ? py::object(py::none())
                                                           : py::object(vector_view<double>(self, t.attributes));
                             })
      .def_property_readonly("triangle_count",
                             [](const TriangulationValue& v) { return v.triangulation.triangle_count(); })
      .def("__len__", [](const TriangulationValue& v) { return v.triangulation.triangle_count(); })
      .def(
          "verify",
          [](const TriangulationValue& v) {
            Verification check;
            {
              py::gil_scoped_release release;
              check = verify_triangulation(v.triangulation, v.pslg.segments.empty() ? nullptr : &v.pslg, v.options);
            }
            return problems_of(check);
          },
          "The independent check (verify_triangulation): a list of problems, empty when valid.")
      .def(
          "write",
          [](const TriangulationValue& v, py::handle prefix) {
            const std::string p = fspath(prefix);
            OutputSet outputs;
            outputs.add_file(p + ".node", cli::triangulation_node_text(v.pslg, v.triangulation));
            outputs.add_file(p + ".ele", cli::triangulation_ele_text(v.pslg, v.triangulation));
            outputs.add_file(p + ".neigh", cli::triangulation_neigh_text(v.pslg, v.triangulation));
            outputs.add_file(p + ".edge", cli::triangulation_edge_text(v.pslg, v.triangulation));
            write_all(outputs);
          },
          py::arg("prefix"), "PREFIX.node, .ele, .neigh, .edge, as `madd triangulate -o PREFIX` writes them.")
      .def("__repr__", [](const TriangulationValue& v) {
        return "<madd.Triangulation: " + std::to_string(v.triangulation.triangle_count()) + " triangles, " +
               std::to_string(v.triangulation.points.size()) + " points>";
      });

  py::class_<Partition>(m, "Partition", "A k-way partition of a graph's vertices (`madd partition`).")
      .def_property_readonly(
          "part",
          [](const Partition& p) {
            return py::array_t<std::int32_t>(static_cast<py::ssize_t>(p.part.size()),
                                             reinterpret_cast<const std::int32_t*>(p.part.data()));
          },
          "(n,) int32: each vertex's part, 0..k-1.")
      .def_readonly("cut", &Partition::cut, "The weight of the edges between parts.")
      .def_property_readonly("part_weights", [](const Partition& p) {
        return py::array_t<double>(static_cast<py::ssize_t>(p.part_weights.size()), p.part_weights.data());
      });
}

}  // namespace

void bind_results(py::module_& m) {
  bind_decomposition(m);
  bind_mesh(m);
  bind_triangulation(m);
}

}  // namespace madd::python
