#pragma once
// Strict readers for mesh_output_test.cpp: Triangle's .node/.ele/.neigh/.edge
// tables, gmsh MSH 4.1 ASCII and the VTK XML UnstructuredGrid that
// mesh_output.hpp writes. Anything unexpected (a wrong count, a bad number,
// a missing section, a duplicate tag) throws std::runtime_error, so a test
// that reads a file back also checks its layout.
#include <charconv>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::test {

inline std::vector<std::string> words_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

inline std::int64_t integer_of(const std::string& s) {
  std::int64_t v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) throw std::runtime_error("not an integer: '" + s + "'");
  return v;
}

inline double real_of(const std::string& s) {
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) throw std::runtime_error("not a number: '" + s + "'");
  return v;
}

// ---- Triangle tables ----
// A Triangle file: its header and its rows (words), comments removed. Rows
// must be numbered first_index, first_index + 1, ... and each have `columns` words.
struct TriangleTable {
  std::vector<std::int64_t> header;
  std::vector<std::vector<std::string>> rows;  // without the id
};

inline TriangleTable parse_triangle_table(const std::string& text, std::size_t header_words, std::size_t row_words,
                                          std::int64_t first_index) {
  std::istringstream in(text);
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(in, line);) {
    const auto words = words_of(line.substr(0, line.find('#')));
    if (!words.empty()) lines.push_back(words);
  }
  if (lines.empty() || lines[0].size() != header_words) throw std::runtime_error("table: bad header");
  TriangleTable t;
  for (const std::string& w : lines[0]) t.header.push_back(integer_of(w));
  if (t.header[0] < 0 || static_cast<std::size_t>(t.header[0]) + 1 != lines.size())
    throw std::runtime_error("table: the header's count is not the number of rows");
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].size() != row_words)
      throw std::runtime_error("table: row " + std::to_string(i) + " has a wrong width");
    if (integer_of(lines[i][0]) != static_cast<std::int64_t>(i - 1) + first_index)
      throw std::runtime_error("table: ids are not consecutive from first_index");
    t.rows.emplace_back(lines[i].begin() + 1, lines[i].end());
  }
  return t;
}

// ---- gmsh MSH 4.1 ASCII ----
struct Msh41Entity {
  int dim = 0;
  std::int64_t tag = 0;
  std::vector<std::int64_t> physical_tags;
  std::vector<std::int64_t> bounding;  // signed tags of bounding entities
};

struct Msh41Element {
  std::int64_t tag = 0;
  int type = 0;  // 1 = 2-node line, 2 = 3-node triangle
  int entity_dim = 0;
  std::int64_t entity_tag = 0;
  std::vector<std::int64_t> nodes;
};

struct Msh41 {
  std::map<std::pair<int, std::int64_t>, std::string> physical_names;  // (dim, tag) -> name
  std::map<std::pair<int, std::int64_t>, Msh41Entity> entities;        // (dim, tag)
  std::map<std::int64_t, Point> nodes;
  std::map<std::int64_t, std::pair<int, std::int64_t>> node_entity;  // node tag -> (dim, tag)
  std::vector<Msh41Element> elements;
  // $ElementData views by name: element tag -> the one value.
  std::map<std::string, std::map<std::int64_t, double>> element_data;
};

class Msh41Reader {
public:
  explicit Msh41Reader(const std::string& text) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines_.push_back(line);
  }

  Msh41 read() {
    expect("$MeshFormat");
    if (next() != std::vector<std::string>{"4.1", "0", "8"}) fail("not MSH 4.1 ASCII with 8-byte reals");
    expect("$EndMeshFormat");
    Msh41 m;
    while (at_ < lines_.size()) {
      const auto section = next();
      if (section.size() != 1) fail("a section name expected");
      if (section[0] == "$PhysicalNames") physical_names(m);
      else if (section[0] == "$Entities") entities(m);
      else if (section[0] == "$Nodes") nodes(m);
      else if (section[0] == "$Elements") elements(m);
      else if (section[0] == "$ElementData") element_data(m);
      else fail("unexpected section " + section[0]);
    }
    if (!seen_nodes_ || !seen_elements_) fail("$Nodes or $Elements missing");
    return m;
  }

private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("msh line " + std::to_string(at_) + ": " + what);
  }
  std::vector<std::string> next() {
    if (at_ >= lines_.size()) fail("unexpected end");
    return words_of(lines_[at_++]);
  }
  std::vector<std::int64_t> integers(std::size_t count) {
    const auto words = next();
    if (words.size() != count) fail("expected " + std::to_string(count) + " numbers");
    std::vector<std::int64_t> v;
    for (const auto& w : words) v.push_back(integer_of(w));
    return v;
  }
  void expect(const std::string& word) {
    if (next() != std::vector<std::string>{word}) fail("expected " + word);
  }

  // One string tag (the quoted name), one real tag (time), three integer
  // tags (step, 1 component, count), then "element-tag value" lines, each
  // element once and known.
  void element_data(Msh41& m) {
    if (integers(1)[0] != 1) fail("element data: one string tag expected");
    const std::string& quoted = lines_.at(at_++);
    if (quoted.size() < 2 || quoted.front() != '"' || quoted.back() != '"')
      fail("element data: a quoted name expected");
    const std::string name = quoted.substr(1, quoted.size() - 2);
    if (integers(1)[0] != 1) fail("element data: one real tag expected");
    real_of(next().at(0));
    if (integers(1)[0] != 3) fail("element data: three integer tags expected");
    integers(1);
    if (integers(1)[0] != 1) fail("element data: one component expected");
    const std::int64_t count = integers(1)[0];
    auto& view = m.element_data[name];
    for (std::int64_t i = 0; i < count; ++i) {
      const auto w = next();
      if (w.size() != 2) fail("element data: tag and value expected");
      if (!view.emplace(integer_of(w[0]), real_of(w[1])).second) fail("element data: an element twice");
    }
    expect("$EndElementData");
  }

  void physical_names(Msh41& m) {
    const std::int64_t n = integers(1)[0];
    for (std::int64_t i = 0; i < n; ++i) {
      const std::string& line = lines_.at(at_);
      const auto q = line.find('"');
      if (q == std::string::npos || line.back() != '"' || q + 1 >= line.size()) fail("bad physical name");
      const auto head = words_of(line.substr(0, q));
      ++at_;
      if (head.size() != 2) fail("bad physical name");
      const auto key = std::pair{static_cast<int>(integer_of(head[0])), integer_of(head[1])};
      if (!m.physical_names.emplace(key, line.substr(q + 1, line.size() - q - 2)).second) fail("duplicate physical");
    }
    expect("$EndPhysicalNames");
  }

  // pointTag x y z #phys tags... | tag box(6) #phys tags... #bounding tags...
  void entities(Msh41& m) {
    const auto counts = integers(4);
    for (int dim = 0; dim < 4; ++dim) {
      for (std::int64_t i = 0; i < counts[static_cast<std::size_t>(dim)]; ++i) {
        const auto w = next();
        Msh41Entity e;
        e.dim = dim;
        std::size_t at = 0;
        const auto word = [&]() -> const std::string& {
          if (at >= w.size()) fail("short entity line");
          return w[at++];
        };
        e.tag = integer_of(word());
        for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) real_of(word());
        const std::int64_t physicals = integer_of(word());
        for (std::int64_t p = 0; p < physicals; ++p) e.physical_tags.push_back(integer_of(word()));
        if (dim > 0) {
          const std::int64_t bounding = integer_of(word());
          for (std::int64_t b = 0; b < bounding; ++b) e.bounding.push_back(integer_of(word()));
        }
        if (at != w.size()) fail("long entity line");
        if (!m.entities.emplace(std::pair{dim, e.tag}, e).second) fail("duplicate entity");
      }
    }
    expect("$EndEntities");
  }

  void nodes(Msh41& m) {
    seen_nodes_ = true;
    const auto head = integers(4);
    std::int64_t total = 0;
    for (std::int64_t b = 0; b < head[0]; ++b) {
      const auto block = integers(4);
      if (block[2] != 0) fail("parametric nodes");
      const std::pair entity{static_cast<int>(block[0]), block[1]};
      if (!m.entities.count(entity)) fail("node block on an unknown entity");
      std::vector<std::int64_t> tags;
      for (std::int64_t i = 0; i < block[3]; ++i) tags.push_back(integers(1)[0]);
      for (const std::int64_t tag : tags) {
        const auto xyz = next();
        if (xyz.size() != 3 || real_of(xyz[2]) != 0.0) fail("bad coordinates");
        if (tag < head[2] || tag > head[3]) fail("node tag outside [min, max]");
        if (!m.nodes.emplace(tag, Point{real_of(xyz[0]), real_of(xyz[1])}).second) fail("node listed twice");
        m.node_entity[tag] = entity;
      }
      total += block[3];
    }
    if (total != head[1]) fail("node count");
    expect("$EndNodes");
  }

  void elements(Msh41& m) {
    seen_elements_ = true;
    const auto head = integers(4);
    std::int64_t total = 0;
    std::set<std::int64_t> tags;
    for (std::int64_t b = 0; b < head[0]; ++b) {
      const auto block = integers(4);
      const int type = static_cast<int>(block[2]);
      if (type != 1 && type != 2) fail("unexpected element type");
      const std::pair entity{static_cast<int>(block[0]), block[1]};
      if (entity.first != type || !m.entities.count(entity)) fail("element block on a wrong entity");
      for (std::int64_t i = 0; i < block[3]; ++i) {
        const auto v = integers(static_cast<std::size_t>(type) + 2);
        Msh41Element e{v[0], type, entity.first, entity.second, std::vector<std::int64_t>(v.begin() + 1, v.end())};
        if (e.tag < head[2] || e.tag > head[3] || !tags.insert(e.tag).second) fail("bad element tag");
        for (const std::int64_t n : e.nodes)
          if (!m.nodes.count(n)) fail("element uses an unknown node");
        m.elements.push_back(e);
      }
      total += block[3];
    }
    if (total != head[1]) fail("element count");
    expect("$EndElements");
  }

  std::vector<std::string> lines_;
  std::size_t at_ = 0;
  bool seen_nodes_ = false, seen_elements_ = false;
};

inline Msh41 parse_msh41(const std::string& text) { return Msh41Reader(text).read(); }

// ---- VTK XML: just enough XML for the .vtu (tags balanced, attributes quoted) ----
struct XmlArray {
  std::map<std::string, std::string> attributes;
  std::vector<std::string> values;
  std::string parent;  // PointData, CellData, Points or Cells
};

struct Vtu {
  std::map<std::string, std::string> piece;  // the Piece's attributes
  std::vector<XmlArray> arrays;
  const XmlArray& array(const std::string& parent, const std::string& name) const {
    for (const XmlArray& a : arrays) {
      const auto it = a.attributes.find("Name");
      if (a.parent == parent &&
          (name.empty() ? it == a.attributes.end() : it != a.attributes.end() && it->second == name))
        return a;
    }
    throw std::runtime_error("vtu: no array " + parent + "/" + name);
  }
};

inline std::map<std::string, std::string> xml_attributes(const std::string& body) {
  std::map<std::string, std::string> out;
  std::size_t at = 0;
  while (true) {
    at = body.find_first_not_of(" \n\t", at);
    if (at == std::string::npos) break;
    const auto eq = body.find('=', at);
    if (eq == std::string::npos || eq + 1 >= body.size() || body[eq + 1] != '"')
      throw std::runtime_error("xml: bad attribute in " + body);
    const auto close = body.find('"', eq + 2);
    if (close == std::string::npos) throw std::runtime_error("xml: unterminated attribute");
    if (!out.emplace(body.substr(at, eq - at), body.substr(eq + 2, close - eq - 2)).second)
      throw std::runtime_error("xml: duplicate attribute");
    at = close + 1;
  }
  return out;
}

inline Vtu parse_vtu(const std::string& text) {
  const std::string declaration = "<?xml version=\"1.0\"?>\n";
  if (text.compare(0, declaration.size(), declaration) != 0) throw std::runtime_error("vtu: no XML declaration");
  Vtu v;
  std::vector<std::string> open;
  std::size_t at = declaration.size();
  while (true) {
    const auto lt = text.find('<', at);
    const std::string between = text.substr(at, lt == std::string::npos ? std::string::npos : lt - at);
    if (!open.empty() && open.back() == "DataArray") {
      v.arrays.back().values = words_of(between);
    } else if (!words_of(between).empty()) {
      throw std::runtime_error("vtu: text outside a DataArray");
    }
    if (lt == std::string::npos) break;
    const auto gt = text.find('>', lt);
    if (gt == std::string::npos) throw std::runtime_error("vtu: unterminated tag");
    std::string tag = text.substr(lt + 1, gt - lt - 1);
    at = gt + 1;
    if (tag.front() == '/') {
      if (open.empty() || open.back() != tag.substr(1)) throw std::runtime_error("vtu: unbalanced </" + tag + ">");
      open.pop_back();
      continue;
    }
    const bool empty_element = tag.back() == '/';
    if (empty_element) tag.pop_back();
    const auto space = tag.find(' ');
    const std::string name = tag.substr(0, space);
    const auto attributes =
        space == std::string::npos ? std::map<std::string, std::string>{} : xml_attributes(tag.substr(space));
    if (name == "VTKFile") {
      if (!open.empty() || attributes.at("type") != "UnstructuredGrid") throw std::runtime_error("vtu: root");
    } else if (name == "Piece") {
      v.piece = attributes;
    } else if (name == "DataArray") {
      if (attributes.at("format") != "ascii") throw std::runtime_error("vtu: not ascii");
      v.arrays.push_back({attributes, {}, open.empty() ? std::string() : open.back()});
    }
    if (!empty_element) open.push_back(name);
  }
  if (!open.empty()) throw std::runtime_error("vtu: unclosed <" + open.back() + ">");
  return v;
}

}  // namespace madd::test
