#include "domain.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

#include "../input_domain.hpp"
#include "arrays.hpp"
#include "keywords.hpp"
#include "madd/atomic_write.hpp"
#include "madd/intersections.hpp"
#include "madd/poly_io.hpp"
#include "madd/polygons.hpp"

namespace madd::python {

namespace {

[[noreturn]] void bad_array(const std::string& what) { throw InvalidInputError(InputProblem::other, what); }

// An (n, k) float64 array of `value` (None: n = 0), BadInput on another shape.
py::array_t<double, py::array::c_style | py::array::forcecast> rows_of(py::handle value, py::ssize_t k,
                                                                       const char* what) {
  if (value.is_none()) return py::array_t<double>(std::vector<py::ssize_t>{0, k});
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a) bad_array(std::string(what) + " must be an array of numbers");
  if (a.ndim() == 1 && a.shape(0) == 0) return py::array_t<double>(std::vector<py::ssize_t>{0, k});
  if (a.ndim() != 2 || a.shape(1) != k)
    bad_array(std::string(what) + " must have shape (n, " + std::to_string(k) + "), got " +
              py::str(py::handle(a).attr("shape")).cast<std::string>());
  return a;
}

// Integer rows: (m, k) of whole numbers within [0, limit).
std::vector<std::uint32_t> indices_of(py::handle value, py::ssize_t k, std::size_t limit, const char* what) {
  const auto a = rows_of(value, k, what);
  std::vector<std::uint32_t> out;
  out.reserve(static_cast<std::size_t>(a.size()));
  const double* d = a.data();
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    if (!(d[i] >= 0 && d[i] < static_cast<double>(limit) && std::floor(d[i]) == d[i]))
      throw InvalidInputError(InputProblem::other,
                              std::string(what) + " row " + std::to_string(i / k) + " names point " +
                                  py::repr(py::float_(d[i])).cast<std::string>() + ", not one of the " +
                                  std::to_string(limit) + " points",
                              {static_cast<std::int64_t>(i / k)});
    out.push_back(static_cast<std::uint32_t>(d[i]));
  }
  return out;
}

std::vector<int> ints_of(py::handle value, std::size_t n, const char* what) {
  std::vector<int> out;
  if (value.is_none()) return out;
  auto a = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n)
    bad_array(std::string(what) + " must be " + std::to_string(n) + " whole numbers, one per row");
  for (py::ssize_t i = 0; i < a.shape(0); ++i) out.push_back(static_cast<int>(a.data()[i]));
  return out;
}

// `pslg` checked as a PSLG (SourceMap `source` locating errors), its
// crossing and overlapping segments first split where they meet when
// `resolve_crossings` (the resolved PSLG's items no longer match the
// file's lines: `source` is cleared then).
void check_pslg(Pslg& pslg, SourceMap& source, bool resolve_crossings) {
  ValidatePslgOptions validation;
  validation.allow_intersections = resolve_crossings;
  validate_pslg(pslg, source, validation);
  if (!resolve_crossings) return;
  ResolvedPslg resolved = resolve_intersections(pslg);
  if (resolved.crossings + resolved.overlaps == 0) return;
  pslg = std::move(resolved.pslg);
  source = SourceMap{source.path};
}

std::shared_ptr<DomainValue> domain_from_arrays(py::handle points, py::handle segments, py::handle holes,
                                                py::handle markers, py::handle regions, py::handle point_markers,
                                                bool resolve_crossings) {
  auto value = std::make_shared<DomainValue>();
  Pslg& pslg = value->coast.domain;
  pslg.first_index = 0;  // ids in errors are numpy's
  pslg.points = to_points(points, "points");
  const std::vector<std::uint32_t> ends = indices_of(segments, 2, pslg.points.size(), "segments");
  const std::vector<int> marks = ints_of(markers, ends.size() / 2, "markers");
  for (std::size_t i = 0; i < ends.size() / 2; ++i)
    pslg.segments.push_back({ends[2 * i], ends[2 * i + 1], marks.empty() ? 0 : marks[i]});
  pslg.has_segment_markers = !marks.empty();
  pslg.holes = to_points(holes, "holes");
  const auto r = rows_of(regions, 4, "regions (x, y, attribute, max_area)");
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    pslg.regions.push_back({{r.at(i, 0), r.at(i, 1)}, r.at(i, 2), r.at(i, 3)});
  pslg.point_markers = ints_of(point_markers, pslg.points.size(), "point_markers");
  {
    py::gil_scoped_release release;
    check_pslg(pslg, value->source, resolve_crossings);
  }
  return value;
}

std::shared_ptr<DomainValue> domain_from_file(const std::string& path, const cli::CommandLine& line) {
  auto value = std::make_shared<DomainValue>();
  value->path = path;
  py::gil_scoped_release release;
  if (is_polygon_file(path)) {
    value->coast = cli::read_input_domain(path, line, nullptr);
    value->from_polygons = true;
    value->is_domain.store(true);
    return value;
  }
  if (line.coast.clip || line.coast.water_at || line.min_island_area_given) {
    (void)cli::read_input_domain(path, line, nullptr);  // refuses a coast option on a .poly, in the CLI's words
  }
  PolyFile file = read_poly_file(path);
  check_pslg(file.pslg, file.source, line.resolve_crossings);
  value->coast.domain = std::move(file.pslg);
  value->source = std::move(file.source);
  return value;
}

// Polygons in memory ([(outer, [holes...], marker), ...], rings as (n, 2)
// arrays, open or closed) as a coast: clipped, projected, cleaned.
std::shared_ptr<DomainValue> coast_from_polygons(const py::list& polygons, bool lonlat, const cli::CommandLine& line) {
  PolygonSet set;
  set.coordinates = lonlat ? Coordinates::lonlat : Coordinates::projected;
  auto ring_of = [](py::handle rows, std::uint32_t index) {
    GisRing ring{to_points(rows, "a ring"), index};
    if (ring.points.size() > 1 && ring.points.front() == ring.points.back()) ring.points.pop_back();
    return ring;
  };
  std::uint32_t feature = 0;
  for (const py::handle item : polygons) {
    const auto t = item.cast<py::tuple>();
    GisPolygon polygon;
    polygon.outer = ring_of(t[0], 0);
    std::uint32_t k = 1;
    for (const py::handle hole : t[1].cast<py::list>()) polygon.holes.push_back(ring_of(hole, k++));
    polygon.marker = t[2].cast<int>();
    polygon.feature = feature++;
    set.polygons.push_back(std::move(polygon));
  }
  auto value = std::make_shared<DomainValue>();
  value->from_polygons = true;
  py::gil_scoped_release release;
  value->coast = coast_domain(set, cli::coast_options(line), "<geometry>");
  value->is_domain.store(true);
  return value;
}

py::dict coast_report_dict(const CoastReport& r) {
  py::dict d;
  d["polygons_read"] = r.polygons_read;
  d["rings_read"] = r.rings_read;
  d["vertices_read"] = r.vertices_read;
  d["bodies"] = r.bodies;
  d["bodies_dropped"] = r.bodies_dropped;
  d["islands"] = r.islands;
  d["small_islands_removed"] = r.small_islands_removed;
  d["vertices_merged"] = r.vertices_merged;
  d["spikes_removed"] = r.spikes_removed;
  d["rings_collapsed"] = r.rings_collapsed;
  d["crossings_resolved"] = r.crossings_resolved;
  d["pinches"] = r.pinches;
  d["pockets_dropped"] = r.pockets_dropped;
  d["area_m2"] = r.area_m2;
  d["open_segments"] = r.open_segments;
  d["land_segments"] = r.land_segments;
  return d;
}

py::array map_points(const Projection& p, py::handle xy, bool to_lonlat) {
  const std::vector<Point> in = to_points(xy, "points");
  py::array_t<double> out(std::vector<py::ssize_t>{static_cast<py::ssize_t>(in.size()), 2});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Point q = to_lonlat ? p.to_lonlat(in[i]) : p.to_metres(in[i]);
    o(static_cast<py::ssize_t>(i), 0) = q.x;
    o(static_cast<py::ssize_t>(i), 1) = q.y;
  }
  return out;
}

// The coast keywords of a reader (madd check's: clip, water_at, min_island_area, hmin).
cli::CommandLine reader_line(const py::kwargs& keywords, const char* function) {
  cli::CommandLine line;
  apply_keywords(line, Keywords{function, cli::options_of("check")}, keywords);
  return line;
}

}  // namespace

std::vector<Point> to_points(py::handle array_like, const char* what) {
  const auto a = rows_of(array_like, 2, what);
  std::vector<Point> out(static_cast<std::size_t>(a.shape(0)));
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    out[static_cast<std::size_t>(i)] = {a.at(i, 0), a.at(i, 1)};
    if (!std::isfinite(out[static_cast<std::size_t>(i)].x) || !std::isfinite(out[static_cast<std::size_t>(i)].y))
      throw InvalidInputError(InputProblem::other, std::string(what) + " row " + std::to_string(i) + " is not finite",
                              {static_cast<std::int64_t>(i)});
  }
  return out;
}

std::shared_ptr<const DomainValue> domain_argument(py::handle argument, const cli::CommandLine& line) {
  if (py::isinstance<DomainValue>(argument)) {
    if (line.coast.clip || line.coast.water_at || line.min_island_area_given) {
      const char* field = line.coast.clip ? "clip" : line.coast.water_at ? "water_at" : "min_island_area";
      throw OptionError(field, "applies to reading a GeoJSON or shapefile (pass the path, or give it to read_domain)");
    }
    return argument.cast<std::shared_ptr<DomainValue>>();
  }
  if (py::isinstance<py::str>(argument) || py::hasattr(argument, "__fspath__"))
    return domain_from_file(py::module_::import("os").attr("fspath")(argument).cast<std::string>(), line);
  throw py::type_error("expected a madd.Domain, a path or a shapely geometry, got " +
                       py::repr(py::type::of(argument)).cast<std::string>());
}

void bind_domain(py::module_& m) {
  py::class_<Projection>(m, "Projection",
                         "The local projection of a coast (docs/coastal.md): equirectangular about (lon0_deg, "
                         "lat0_deg), in metres; `geographic` False is the identity.")
      .def_readonly("geographic", &Projection::geographic)
      .def_readonly("lon0_deg", &Projection::lon0_deg)
      .def_readonly("lat0_deg", &Projection::lat0_deg)
      .def(
          "to_lonlat", [](const Projection& p, py::handle xy) { return map_points(p, xy, true); }, py::arg("xy"),
          "Points (n, 2) in the projection's metres as (longitude, latitude) in degrees.")
      .def(
          "to_metres", [](const Projection& p, py::handle lonlat) { return map_points(p, lonlat, false); },
          py::arg("lonlat"), "Points (n, 2) in (longitude, latitude) degrees as the projection's metres.")
      .def("__repr__", [](const Projection& p) {
        return p.geographic ? "Projection(lon0_deg=" + py::repr(py::float_(p.lon0_deg)).cast<std::string>() +
                                  ", lat0_deg=" + py::repr(py::float_(p.lat0_deg)).cast<std::string>() + ")"
                            : std::string("Projection(identity)");
      });

  py::class_<DomainValue, std::shared_ptr<DomainValue>>(
      m, "Domain",
      "A planar straight line graph: points, segments (0-based index pairs) with markers, hole points and "
      "regions. Any PSLG triangulates; decompose and mesh take a domain (one connected region bounded by "
      "closed rings) and raise madd.BadInput naming the ids otherwise.")
      .def(py::init(&domain_from_arrays), py::arg("points"), py::arg("segments") = py::none(),
           py::arg("holes") = py::none(), py::arg("markers") = py::none(), py::arg("regions") = py::none(),
           py::arg("point_markers") = py::none(), py::arg("resolve_crossings") = false,
           "Domain(points, segments=None, holes=None, markers=None, regions=None, point_markers=None, "
           "resolve_crossings=False)\n\n"
           "points (n, 2) float; segments (m, 2) ints into points; holes (k, 2) points inside holes; markers (m,) "
           "segment markers; regions (r, 4) rows (x, y, attribute, max_area); point_markers (n,). Checked as a "
           "PSLG at once (madd.BadInput names the ids, 0-based); with resolve_crossings, crossing and overlapping "
           "segments are first split where they meet (as `madd triangulate -r`).")
      .def_property_readonly(
          "points", [](py::object self) { return points_view(self, self.cast<const DomainValue&>().pslg().points); })
      .def_property_readonly(
          "segments",
          [](py::object self) { return index_view(self, self.cast<const DomainValue&>().pslg().segments, 2); })
      .def_property_readonly("markers",
                             [](py::object self) {
                               return field_view<std::int32_t>(self, self.cast<const DomainValue&>().pslg().segments,
                                                               offsetof(Segment, marker));
                             })
      .def_property_readonly(
          "holes", [](py::object self) { return points_view(self, self.cast<const DomainValue&>().pslg().holes); })
      .def_property_readonly("regions",
                             [](py::object self) {
                               const auto& regions = self.cast<const DomainValue&>().pslg().regions;
                               static_assert(sizeof(Region) == 4 * sizeof(double));
                               return read_only_view<double>(self, regions.data(),
                                                             {static_cast<py::ssize_t>(regions.size()), 4},
                                                             {sizeof(Region), sizeof(double)});
                             })
      .def_property_readonly("point_markers",
                             [](py::object self) {
                               return vector_view<std::int32_t, int>(
                                   self, self.cast<const DomainValue&>().pslg().point_markers);
                             })
      .def_property_readonly(
          "path", [](const DomainValue& d) { return d.path.empty() ? py::object(py::none()) : py::cast(d.path); },
          "The file it was read from (None when built in memory).")
      .def_property_readonly(
          "projection", [](const DomainValue& d) { return d.coast.projection; },
          "How a coast was projected to metres (identity for other domains).")
      .def_property_readonly(
          "coast_report",
          [](const DomainValue& d) {
            return d.from_polygons ? py::object(coast_report_dict(d.coast.report)) : py::object(py::none());
          },
          "What cleaning a coastline did (None for other domains).")
      .def_property_readonly(
          "area",
          [](const DomainValue& d) {
            d.check_domain();
            return domain_area(d.pslg());
          },
          "The domain's area (raises madd.BadInput when it is no domain).")
      .def(
          "check",
          [](const DomainValue& d) {
            py::gil_scoped_release release;
            d.check_domain();
          },
          "Raises madd.BadInput unless the PSLG is a domain decompose and mesh take.")
      .def(
          "summary",
          [](const DomainValue& d) {
            const PslgSummary s = summarize_pslg(d.pslg());
            py::dict out;
            out["isolated_vertices"] = s.isolated_vertices;
            out["isolated_inside"] = s.isolated_inside;
            out["vertices_inside_segments"] = s.vertices_inside_segments;
            out["dangling_ends"] = s.dangling_ends;
            out["interior_segments"] = s.interior_segments;
            out["boundary_segments"] = s.boundary_segments;
            out["outside_segments"] = s.outside_segments;
            out["parts"] = s.parts;
            out["area"] = s.area;
            return out;
          },
          "What the PSLG holds, as `madd check` prints it.")
      .def(
          "write_poly",
          [](const DomainValue& d, const std::string& path) {
            OutputSet outputs;
            outputs.add_file(path, format_poly(d.pslg()));
            py::gil_scoped_release release;
            outputs.write();
          },
          py::arg("path"), "Writes the PSLG as a Triangle .poly (ids from the domain's first index).")
      .def("__repr__", [](const DomainValue& d) {
        return "<madd.Domain: " + std::to_string(d.pslg().points.size()) + " points, " +
               std::to_string(d.pslg().segments.size()) + " segments, " + std::to_string(d.pslg().holes.size()) +
               " holes" + (d.path.empty() ? std::string() : ", from " + d.path) + ">";
      });

  m.def(
      "read_domain",
      [](py::handle path, bool resolve_crossings, const py::kwargs& keywords) {
        cli::CommandLine line = reader_line(keywords, "read_domain");
        line.resolve_crossings = resolve_crossings;
        return domain_from_file(py::module_::import("os").attr("fspath")(path).cast<std::string>(), line);
      },
      py::arg("path"), py::arg("resolve_crossings") = false,
      ("read_domain(path, resolve_crossings=False, **coast_options)\n\n"
       "Reads a Triangle .poly or .node (any PSLG; checked as one), or a GeoJSON (.geojson, .json) or shapefile "
       "(.shp) of water polygons in lon/lat, cut, cleaned and projected to metres as `madd check` does it "
       "(docs/coastal.md). Raises madd.BadInput with path, line and column. With resolve_crossings, crossing and "
       "overlapping segments of a .poly are split where they meet (as `madd triangulate -r`).\n\nKeywords (as `madd "
       "check`):\n" +
       keywords_help(cli::options_of("check")))
          .c_str());
  m.def(
      "_coast_from_polygons",
      [](const py::list& polygons, bool lonlat, const py::kwargs& keywords) {
        return coast_from_polygons(polygons, lonlat, reader_line(keywords, "coast_domain"));
      },
      py::arg("polygons"), py::arg("lonlat"));
}

}  // namespace madd::python
