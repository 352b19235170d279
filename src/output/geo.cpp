// The gmsh .geo view of a decomposition (include/madd/output_formats.hpp).
// Every segment becomes one Line used by the Curve Loops of both subdomains
// it separates, so gmsh meshes each Line once and the subdomain meshes meet
// node to node along the separators.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "madd/output_formats.hpp"
#include "kernel/number_format.hpp"

namespace madd {
namespace {

// The size written at each point: the fixed size, or the shortest segment at
// the point. An isolated point gets the shortest segment of its subdomain
// (the resolution there; the shortest of all would refine far from it), a
// point on no segment and in no subdomain the shortest of all.
std::vector<double> point_sizes(const Decomposition& d, double fixed) {
  if (fixed > 0.0) return std::vector<double>(d.points.size(), fixed);
  constexpr double unset = std::numeric_limits<double>::infinity();
  std::vector<double> size(d.points.size(), unset);
  double shortest = unset;
  for (const Segment& s : d.segments) {
    const double len = distance(d.points[s.a], d.points[s.b]);
    size[s.a] = std::min(size[s.a], len);
    size[s.b] = std::min(size[s.b], len);
    shortest = std::min(shortest, len);
  }
  if (shortest == unset) shortest = 1.0;
  for (const Subdomain& sub : d.subdomains) {
    if (sub.interior_points.empty()) continue;
    double local = unset;
    for (const auto& ring : sub.ring_segments)
      for (const std::uint32_t s : ring)
        local = std::min(local, distance(d.points[d.segments[s].a], d.points[d.segments[s].b]));
    for (const std::uint32_t s : sub.interior_segments)
      local = std::min(local, distance(d.points[d.segments[s].a], d.points[d.segments[s].b]));
    for (const std::uint32_t p : sub.interior_points)
      if (size[p] == unset) size[p] = local;
  }
  for (double& v : size)
    if (v == unset) v = shortest;
  return size;
}

// Writes "{a, b, c, ...};" with a line break every 16 items, for long lists.
void append_id_list(std::string& out, const std::vector<std::int64_t>& ids) {
  out += '{';
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (i > 0) out += (i % 16 == 0) ? ",\n  " : ", ";
    detail::append_int(out, ids[i]);
  }
  out += "};\n";
}

// Curve Loop ids of one ring, signed by the direction the ring walks each Line
// (a Line runs from its segment's a to b).
std::vector<std::int64_t> loop_lines(const Decomposition& d, const Subdomain& s, std::size_t r) {
  const auto& ring = s.rings[r];
  std::vector<std::int64_t> lines(ring.size());
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const std::uint32_t seg = s.ring_segments[r][k];
    const auto id = static_cast<std::int64_t>(seg) + 1;
    lines[k] = d.segments[seg].a == ring[k] ? id : -id;
  }
  return lines;
}

void append_points_and_lines(std::string& out, const Decomposition& d, const GeoOptions& options) {
  const std::vector<double> size = point_sizes(d, options.mesh_size);
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    out += "Point(";
    detail::append_int(out, static_cast<std::int64_t>(i) + 1);
    out += ") = {";
    detail::append_g17(out, d.points[i].x);
    out += ", ";
    detail::append_g17(out, d.points[i].y);
    out += ", 0, ";
    detail::append_g17(out, size[i]);
    out += "};\n";
  }
  for (std::size_t j = 0; j < d.segments.size(); ++j) {
    out += "Line(";
    detail::append_int(out, static_cast<std::int64_t>(j) + 1);
    out += ") = {";
    detail::append_int(out, static_cast<std::int64_t>(d.segments[j].a) + 1);
    out += ", ";
    detail::append_int(out, static_cast<std::int64_t>(d.segments[j].b) + 1);
    out += "};\n";
  }
}

// "Line{...} In Surface{tag};" (or Point): gmsh meshes the surface with
// these as edges (vertices) of its triangles, as Triangle keeps interior
// segments and isolated vertices of a .poly.
void append_embedded(std::string& out, const char* kind, const std::vector<std::uint32_t>& ids, std::int64_t tag) {
  if (ids.empty()) return;
  std::vector<std::int64_t> one_based(ids.begin(), ids.end());
  for (std::int64_t& id : one_based) ++id;
  out += kind;
  append_id_list(out, one_based);
  out.pop_back();  // the list's "};\n" becomes "} In Surface{tag};\n"
  out.pop_back();
  out += " In Surface{";
  detail::append_int(out, tag);
  out += "};\n";
}

// One Curve Loop per ring (numbered on from 1 over all subdomains) and one
// Plane Surface plus its Physical Surface per subdomain.
void append_surfaces(std::string& out, const Decomposition& d) {
  std::int64_t next_loop = 1;
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    const Subdomain& s = d.subdomains[k];
    std::vector<std::int64_t> loops;
    for (std::size_t r = 0; r < s.rings.size(); ++r) {
      out += "Curve Loop(";
      detail::append_int(out, next_loop);
      out += ") = ";
      append_id_list(out, loop_lines(d, s, r));
      loops.push_back(next_loop++);
    }
    const auto tag = static_cast<std::int64_t>(k) + 1;
    out += "Plane Surface(";
    detail::append_int(out, tag);
    out += ") = ";
    append_id_list(out, loops);
    append_embedded(out, "Line", s.interior_segments, tag);
    append_embedded(out, "Point", s.interior_points, tag);
    out += "Physical Surface(\"subdomain_";
    detail::append_int(out, static_cast<std::int64_t>(k));
    out += "\", ";
    detail::append_int(out, tag);
    out += ") = {";
    detail::append_int(out, tag);
    out += "};\n";
  }
}

// Physical Curves of the input's segments, one per marker: boundary and
// interior pieces alike, so that a marker is one physical tag, as in the
// mesh's .msh (docs/formats.md, "gmsh (`PREFIX.msh`)"). gmsh needs positive
// tags, so a marker m > 0 is tag m; the others are left to gmsh, which
// numbers them after every explicit tag written before them.
void append_curve_groups(std::string& out, const Decomposition& d) {
  std::map<int, std::vector<std::int64_t>> by_marker;
  for (std::uint32_t j = 0; j < d.segments.size(); ++j)
    if (!d.is_separator(j)) by_marker[d.segments[j].marker].push_back(static_cast<std::int64_t>(j) + 1);
  for (const bool positive : {true, false}) {
    for (const auto& [marker, lines] : by_marker) {
      if ((marker > 0) != positive) continue;
      out += "Physical Curve(\"boundary_";
      detail::append_int(out, marker);
      out += '"';
      if (positive) {
        out += ", ";
        detail::append_int(out, marker);
      }
      out += ") = ";
      append_id_list(out, lines);
    }
  }
}

}  // namespace

std::string format_geo(const Decomposition& decomposition, const GeoOptions& options) {
  std::string out = "// madd decomposition: ";
  detail::append_int(out, static_cast<std::int64_t>(decomposition.subdomains.size()));
  out += " subdomains; Plane Surface k+1 and Physical Surface \"subdomain_k\" (tag k+1) are subdomain k,\n"
         "// Physical Curve \"boundary_m\" holds the original boundary with marker m. Mesh: gmsh -2 FILE.geo\n";
  if (std::any_of(decomposition.subdomains.begin(), decomposition.subdomains.end(),
                  [](const Subdomain& s) { return !s.interior_segments.empty() || !s.interior_points.empty(); }))
    out += "// Interior segments are Lines In Surface (in \"boundary_m\" by their marker m), isolated points Points In "
           "Surface.\n";
  append_points_and_lines(out, decomposition, options);
  append_surfaces(out, decomposition);
  append_curve_groups(out, decomposition);
  return out;
}

}  // namespace madd
