#pragma once
// Readers for output_formats_test.cpp: just enough of gmsh's .geo and .msh
// 2.2, legacy VTK and JSON to read madd's own outputs back, strictly (any
// surprise throws), plus the conformity check of a gmsh mesh, and the marked
// square domain the output tests (decomposition and mesh) share.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/pslg.hpp"

namespace madd::test {

// A square with a square hole; the four outer sides and the hole carry
// different markers (one negative, which gmsh cannot use as a tag).
inline Pslg marked_square_domain() {
  Pslg p;
  p.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1.5, 1.5}, {2.5, 1.5}, {2.5, 2.5}, {1.5, 2.5}};
  p.segments = {{0, 1, 1}, {1, 2, 2}, {2, 3, 3}, {3, 0, 4}, {4, 5, -7}, {5, 6, -7}, {6, 7, -7}, {7, 4, -7}};
  p.has_segment_markers = true;
  p.holes = {{2, 2}};
  validate(p);
  return p;
}

inline std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// Twice the signed area of a ring given as positions (closed or not).
inline double ring_area(const std::vector<Point>& ring) {
  double a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) a += cross(ring[i], ring[(i + 1) % ring.size()]);
  return a;
}

inline double to_number(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0') throw std::runtime_error("not a number: '" + s + "'");
  return v;
}

inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\n\r");
  return b == std::string::npos ? std::string() : s.substr(b, s.find_last_not_of(" \t\n\r") - b + 1);
}

// ---- gmsh .geo (the statements format_geo writes) ----
struct GeoModel {
  std::vector<Point> points;                                           // Point(i) at [i-1]
  std::vector<std::pair<std::uint32_t, std::uint32_t>> lines;          // 0-based point indices
  std::vector<std::vector<std::int64_t>> loops;                        // signed 1-based Line ids
  std::vector<std::vector<std::int64_t>> surfaces;                     // Curve Loop ids
  std::map<std::int64_t, std::string> physical_surfaces;               // tag -> name
  std::map<std::string, std::multiset<std::int64_t>> physical_curves;  // name -> Line ids
  std::map<std::int64_t, std::vector<std::int64_t>> embedded_lines;    // surface -> "Line{...} In Surface"
  std::map<std::int64_t, std::vector<std::int64_t>> embedded_points;   // surface -> "Point{...} In Surface"
};

inline std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(trim(item));
  return out;
}

// The ids of "{a, b, ...}" (no text around the braces).
inline std::vector<std::int64_t> brace_ids(const std::string& s) {
  if (s.size() < 2 || s.front() != '{' || s.back() != '}') throw std::runtime_error("bad list: " + s);
  std::vector<std::int64_t> ids;
  for (const std::string& v : split_commas(s.substr(1, s.size() - 2)))
    ids.push_back(static_cast<std::int64_t>(to_number(v)));
  return ids;
}

// "Line{...} In Surface{k}" or "Point{...} In Surface{k}": true when st is one.
inline bool parse_embedded(const std::string& st, GeoModel& g) {
  const auto in = st.find(" In Surface");
  if (in == std::string::npos) return false;
  const std::string head = trim(st.substr(0, in)), tail = trim(st.substr(in + 11));
  const bool line = head.rfind("Line", 0) == 0;
  if (!line && head.rfind("Point", 0) != 0) throw std::runtime_error("bad embedding: " + st);
  const std::vector<std::int64_t> surface = brace_ids(tail);
  if (surface.size() != 1) throw std::runtime_error("bad embedding: " + st);
  auto& list = (line ? g.embedded_lines : g.embedded_points)[surface[0]];
  if (!list.empty()) throw std::runtime_error("embedded twice: " + st);
  list = brace_ids(trim(head.substr(line ? 4 : 5)));
  return true;
}

inline GeoModel parse_geo(const std::string& text) {
  std::string code;  // without // comments
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) code += line.substr(0, line.find("//")) + "\n";
  GeoModel g;
  std::stringstream statements(code);
  for (std::string st; std::getline(statements, st, ';');) {
    st = trim(st);
    if (st.empty() || parse_embedded(st, g)) continue;
    const auto open = st.find('('), close = st.find(')'), lb = st.find('{'), rb = st.find('}');
    if (open == std::string::npos || close < open || lb < close || rb < lb || rb + 1 != st.size())
      throw std::runtime_error("bad statement: " + st);
    const std::string kind = trim(st.substr(0, open));
    const std::vector<std::string> args = split_commas(st.substr(open + 1, close - open - 1));
    std::vector<std::int64_t> ids;
    std::vector<double> values;
    for (const std::string& v : split_commas(st.substr(lb + 1, rb - lb - 1))) values.push_back(to_number(v));
    for (const double v : values) ids.push_back(static_cast<std::int64_t>(v));
    const auto expect_id = [&](std::size_t next) {
      if (args.size() != 1 || to_number(args[0]) != static_cast<double>(next)) throw std::runtime_error("id: " + st);
    };
    if (kind == "Point") {
      expect_id(g.points.size() + 1);
      if (values.size() != 4 || values[2] != 0 || !(values[3] > 0)) throw std::runtime_error(st);
      g.points.push_back({values[0], values[1]});
    } else if (kind == "Line") {
      expect_id(g.lines.size() + 1);
      if (ids.size() != 2) throw std::runtime_error(st);
      g.lines.push_back({static_cast<std::uint32_t>(ids[0] - 1), static_cast<std::uint32_t>(ids[1] - 1)});
    } else if (kind == "Curve Loop") {
      expect_id(g.loops.size() + 1);
      g.loops.push_back(ids);
    } else if (kind == "Plane Surface") {
      expect_id(g.surfaces.size() + 1);
      g.surfaces.push_back(ids);
    } else if (kind == "Physical Surface") {
      if (args.size() != 2 || ids.size() != 1 || ids[0] != static_cast<std::int64_t>(to_number(args[1])))
        throw std::runtime_error(st);
      g.physical_surfaces[ids[0]] = args[0].substr(1, args[0].size() - 2);
    } else if (kind == "Physical Curve") {
      const std::string name = args.at(0).substr(1, args[0].size() - 2);
      g.physical_curves[name].insert(ids.begin(), ids.end());
    } else {
      throw std::runtime_error("unexpected statement: " + st);
    }
  }
  return g;
}

// ---- JSON (RFC 8259), strict; depth is bounded so recursion is safe ----
struct Json {
  enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
  double number = 0;
  std::string text;
  std::vector<Json> items;  // an array's elements, an object's values
  // An object's keys: keys[i] names items[i]. (Not a vector of key-value
  // pairs: clang 14 with libstdc++ 12 rejects a pair of the incomplete Json.)
  std::vector<std::string> keys;
  const Json& at(const std::string& key) const {
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] == key) return items[i];
    throw std::runtime_error("no key " + key);
  }
};

class JsonParser {
public:
  explicit JsonParser(const std::string& s) : s_(s) {}
  Json document() {
    Json v = value(0);
    space();
    if (at_ != s_.size()) fail("trailing text");
    return v;
  }

private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("JSON: " + what + " at " + std::to_string(at_));
  }
  void space() {
    while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\n' || s_[at_] == '\t' || s_[at_] == '\r')) ++at_;
  }
  char peek() { return at_ < s_.size() ? s_[at_] : '\0'; }
  void expect(char c) {
    space();
    if (peek() != c) fail(std::string("expected ") + c);
    ++at_;
  }
  bool digit() { return peek() >= '0' && peek() <= '9'; }
  void digits() {
    if (!digit()) fail("digit expected");
    while (digit()) ++at_;
  }
  Json value(int depth) {
    if (depth > 32) fail("too deep");
    space();
    Json v;
    const char c = peek();
    if (c == '{' || c == '[') {
      const char end = c == '{' ? '}' : ']';
      v.kind = c == '{' ? Json::Kind::object : Json::Kind::array;
      ++at_;
      space();
      if (peek() == end) {
        ++at_;
        return v;
      }
      for (;;) {
        if (v.kind == Json::Kind::object) {
          space();
          v.keys.push_back(string());
          expect(':');
          v.items.push_back(value(depth + 1));
        } else {
          v.items.push_back(value(depth + 1));
        }
        space();
        if (peek() == end) break;
        expect(',');
      }
      ++at_;
    } else if (c == '"') {
      v.kind = Json::Kind::string;
      v.text = string();
    } else if (s_.compare(at_, 4, "true") == 0 || s_.compare(at_, 4, "null") == 0) {
      v.kind = c == 't' ? Json::Kind::boolean : Json::Kind::null;
      at_ += 4;
    } else if (s_.compare(at_, 5, "false") == 0) {
      v.kind = Json::Kind::boolean;
      at_ += 5;
    } else {
      v.kind = Json::Kind::number;
      v.number = number();
    }
    return v;
  }
  std::string string() {
    if (peek() != '"') fail("string expected");
    std::string out;
    for (++at_; peek() != '"'; ++at_) {
      if (at_ >= s_.size() || static_cast<unsigned char>(s_[at_]) < 0x20) fail("bad string");
      if (s_[at_] == '\\') ++at_;  // escapes are taken literally; madd writes none but \"
      out += s_[at_];
    }
    ++at_;
    return out;
  }
  double number() {
    const std::size_t start = at_;
    if (peek() == '-') ++at_;
    if (peek() == '0') {
      ++at_;
    } else {
      digits();
    }
    if (peek() == '.') {
      ++at_;
      digits();
    }
    if (peek() == 'e' || peek() == 'E') {
      ++at_;
      if (peek() == '+' || peek() == '-') ++at_;
      digits();
    }
    return to_number(s_.substr(start, at_ - start));
  }
  const std::string& s_;
  std::size_t at_ = 0;
};

inline Json parse_json(const std::string& text) { return JsonParser(text).document(); }

// ---- legacy VTK POLYDATA as format_vtk writes it ----
// Cells in POLYDATA's order: vertices, lines, polygons; the cell data of all.
struct VtkPolyData {
  std::vector<Point> points;
  std::vector<std::uint32_t> vertices;                         // VERTICES (one point each)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> lines;  // LINES (two points each)
  std::vector<std::vector<std::uint32_t>> cells;               // POLYGONS
  std::vector<long> subdomain;                                 // per cell, vertices first
  std::vector<double> area, weight;
  std::vector<long> kind, marker;
  std::vector<double> region_attribute, region_max_area;  // only with the input's regions
};

inline void expect_word(std::istream& in, const std::string& word) {
  std::string w;
  if (!(in >> w) || w != word) throw std::runtime_error("VTK: expected " + word + ", got " + w);
}

// One cell section: "<keyword> n size", then n cells of `arity` points
// (0: any), whose integers must add up to size.
inline std::vector<std::vector<std::uint32_t>> read_vtk_cells(std::istream& in, std::size_t points, std::size_t arity) {
  std::size_t n = 0, size = 0, integers = 0;
  in >> n >> size;
  std::vector<std::vector<std::uint32_t>> out;
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t k = 0;
    in >> k;
    if (!in || (arity != 0 && k != arity)) throw std::runtime_error("VTK: bad cell size");
    std::vector<std::uint32_t> cell(k);
    for (auto& p : cell)
      if (!(in >> p) || p >= points) throw std::runtime_error("VTK: bad cell");
    integers += k + 1;
    out.push_back(cell);
  }
  if (integers != size) throw std::runtime_error("VTK: section size does not match");
  return out;
}

inline VtkPolyData parse_vtk(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  if (line != "# vtk DataFile Version 3.0") throw std::runtime_error("VTK: bad first line");
  std::getline(in, line);
  if (line.empty() || line.size() > 255) throw std::runtime_error("VTK: bad title");
  VtkPolyData v;
  std::size_t n = 0;
  expect_word(in, "ASCII");
  expect_word(in, "DATASET");
  expect_word(in, "POLYDATA");
  expect_word(in, "POINTS");
  in >> n;
  expect_word(in, "double");
  for (std::size_t i = 0; i < n; ++i) {
    double x = 0, y = 0, z = 1;
    in >> x >> y >> z;
    if (!in || z != 0) throw std::runtime_error("VTK: bad point");
    v.points.push_back({x, y});
  }
  std::string word;
  in >> word;
  if (word == "VERTICES") {
    for (const auto& c : read_vtk_cells(in, n, 1)) v.vertices.push_back(c[0]);
    in >> word;
  }
  if (word != "LINES") throw std::runtime_error("VTK: expected LINES, got " + word);
  for (const auto& c : read_vtk_cells(in, n, 2)) v.lines.push_back({c[0], c[1]});
  expect_word(in, "POLYGONS");
  v.cells = read_vtk_cells(in, n, 0);
  const std::size_t cells = v.vertices.size() + v.lines.size() + v.cells.size();
  expect_word(in, "CELL_DATA");
  std::size_t data = 0;
  in >> data;
  if (data != cells) throw std::runtime_error("VTK: CELL_DATA count");
  expect_word(in, "SCALARS");
  expect_word(in, "subdomain");
  expect_word(in, "int");
  expect_word(in, "1");
  expect_word(in, "LOOKUP_TABLE");
  expect_word(in, "default");
  for (std::size_t c = 0; c < cells; ++c) {
    long k = -2;
    if (!(in >> k)) throw std::runtime_error("VTK: short subdomain");
    v.subdomain.push_back(k);
  }
  expect_word(in, "FIELD");
  expect_word(in, "FieldData");
  std::string arrays;
  in >> arrays;
  if (arrays != "4" && arrays != "6") throw std::runtime_error("VTK: FieldData of " + arrays + " arrays");
  std::vector<std::string> names{"area", "weight", "kind", "marker"};
  if (arrays == "6") names.insert(names.end(), {"region_attribute", "region_max_area"});
  for (const std::string& name : names) {
    const bool real = name != "kind" && name != "marker";
    expect_word(in, name);
    expect_word(in, "1");
    expect_word(in, std::to_string(cells));
    expect_word(in, real ? "double" : "int");
    for (std::size_t c = 0; c < cells; ++c) {
      double x = 0;
      long i = 0;
      if (!(real ? static_cast<bool>(in >> x) : static_cast<bool>(in >> i)))
        throw std::runtime_error("VTK: short " + name);
      if (name == "area") v.area.push_back(x);
      else if (name == "weight") v.weight.push_back(x);
      else if (name == "region_attribute") v.region_attribute.push_back(x);
      else if (name == "region_max_area") v.region_max_area.push_back(x);
      else (name == "kind" ? v.kind : v.marker).push_back(i);
    }
  }
  std::string rest;
  if (in >> rest) throw std::runtime_error("VTK: trailing " + rest);
  return v;
}

}  // namespace madd::test

#include "output_formats_test_gmsh.hpp"
