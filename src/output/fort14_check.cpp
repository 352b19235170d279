// What a model needs of a fort.14 beyond its syntax (include/madd/
// model_output.hpp, check_fort14). The rules and where they come from:
// NETA / NVEL are totals of the lists ("NVEL ... including both the front and
// back nodes on internal barrier boundaries", ADCIRC's parameter
// definitions); elements are triangles listed counter-clockwise; ADCIRC's
// v52 "General Notes for Normal Flow Boundary Conditions": external
// boundaries listed before internal ones, islands (and a boundary that
// surrounds the domain) closed by repeating the first node. That the lists
// together cover the mesh's boundary once, with the domain on their left,
// is what madd's writer guarantees and what SCHISM's notes recommend
// (exterior counter-clockwise).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "madd/model_output.hpp"
#include "madd/predicates.hpp"

namespace madd {

namespace {

constexpr std::size_t shown_per_kind = 10;

// Problems of one kind: the first few said, the others counted at the end.
class Problems {
public:
  Problems(Verification& out, std::string kind) : out_(out), kind_(std::move(kind)) {}
  Problems(const Problems&) = delete;
  Problems& operator=(const Problems&) = delete;
  ~Problems() {
    if (count_ > shown_per_kind)
      out_.add("... and " + std::to_string(count_ - shown_per_kind) + " more " + kind_ + " (" + std::to_string(count_) +
               " in all)");
  }
  void add(const std::string& problem) {
    if (count_++ < shown_per_kind) out_.add(problem);
  }

private:
  Verification& out_;
  std::string kind_;
  std::size_t count_ = 0;
};

std::string id(std::uint32_t v) { return std::to_string(std::uint64_t{v} + 1); }

bool paired_type(int type) { return type == 4 || type == 24 || type == 64 || type == 5 || type == 25; }
bool island_type(int type) { return type == 1 || type == 11 || type == 21; }
bool internal_type(int type) { return island_type(type) || paired_type(type); }

std::string name(const Fort14Boundary& b, bool flow, std::size_t k) {
  return std::string(flow ? "flow boundary " : "open boundary ") + std::to_string(k + 1) + " (" +
         (flow ? "IBTYPE " : "IBTYPEE ") + std::to_string(b.type) + ", line " + std::to_string(b.line) + ")";
}

void check_totals(const Fort14& grid, Verification& out) {
  std::uint64_t open = 0, land = 0;
  for (const Fort14Boundary& b : grid.open_boundaries) open += b.nodes.size();
  for (const Fort14Boundary& b : grid.land_boundaries) land += b.nodes.size() * (paired_type(b.type) ? 2 : 1);
  if (open != grid.declared_open_nodes)
    out.add("NETA is " + std::to_string(grid.declared_open_nodes) + " but the open boundaries list " +
            std::to_string(open) + " nodes");
  if (land != grid.declared_land_nodes)
    out.add("NVEL is " + std::to_string(grid.declared_land_nodes) + " but the flow boundaries list " +
            std::to_string(land) + " nodes (barriers' paired nodes counted)");
}

// Every element counter-clockwise (exact sign) and every node in one.
void check_elements(const Fort14& grid, Verification& out) {
  Problems bad(out, "bad elements"), unused(out, "nodes in no element");
  std::vector<char> used(grid.points.size(), 0);
  for (std::size_t e = 0; e < grid.elements.size(); ++e) {
    const auto& c = grid.elements[e];
    for (const std::uint32_t v : c) used[v] = 1;
    const std::string what =
        "element " + std::to_string(e + 1) + " (nodes " + id(c[0]) + " " + id(c[1]) + " " + id(c[2]) + ")";
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) {
      bad.add(what + " repeats a node");
      continue;
    }
    const double turn = orient2d(grid.points[c[0]], grid.points[c[1]], grid.points[c[2]]);
    if (turn < 0) bad.add(what + " is clockwise (ADCIRC lists elements counter-clockwise)");
    if (turn == 0) bad.add(what + " is degenerate (its nodes are collinear)");
  }
  for (std::size_t v = 0; v < used.size(); ++v)
    if (!used[v]) unused.add("node " + std::to_string(v + 1) + " is in no element");
}

std::uint64_t directed(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }
std::string edge_text(std::uint64_t key) {
  return id(static_cast<std::uint32_t>(key >> 32)) + "-" + id(static_cast<std::uint32_t>(key));
}

// The element edges a -> b grouped by a (counting sort), each group's b
// in increasing order: edge k of group a is (a, to[k]), k in [first[a],
// first[a + 1]).
struct EdgeGroups {
  std::vector<std::size_t> first;
  std::vector<std::uint32_t> to;
  bool contains(std::uint32_t a, std::uint32_t b) const {
    return std::binary_search(to.begin() + static_cast<std::ptrdiff_t>(first[a]),
                              to.begin() + static_cast<std::ptrdiff_t>(first[a + 1]), b);
  }
};

EdgeGroups edge_groups(const Fort14& grid) {
  EdgeGroups g;
  g.first.assign(grid.points.size() + 1, 0);
  const auto each_edge = [&grid](auto&& f) {
    for (const auto& c : grid.elements)
      if (c[0] != c[1] && c[1] != c[2] && c[0] != c[2])
        for (std::size_t i = 0; i < 3; ++i) f(c[i], c[(i + 1) % 3]);
  };
  each_edge([&g](std::uint32_t a, std::uint32_t) { ++g.first[a + 1]; });
  for (std::size_t v = 0; v + 1 < g.first.size(); ++v) g.first[v + 1] += g.first[v];
  std::vector<std::size_t> next(g.first.begin(), g.first.end() - 1);
  g.to.resize(g.first.back());
  each_edge([&](std::uint32_t a, std::uint32_t b) { g.to[next[a]++] = b; });
  for (std::size_t v = 0; v + 1 < g.first.size(); ++v)
    std::sort(g.to.begin() + static_cast<std::ptrdiff_t>(g.first[v]),
              g.to.begin() + static_cast<std::ptrdiff_t>(g.first[v + 1]));
  return g;
}

// The boundary's directed edges (a, b), the domain on their left: element
// edges whose reverse is in no element, in increasing (a, b) order. An
// edge in two elements the same way round (overlap or a flipped element,
// and any edge in three or more) is a problem.
std::vector<std::uint64_t> boundary_edges(const Fort14& grid, Verification& out) {
  const EdgeGroups g = edge_groups(grid);
  Problems twice(out, "edges in two elements the same way round");
  std::vector<std::uint64_t> boundary;
  for (std::uint32_t a = 0; a + 1 < g.first.size(); ++a) {
    for (std::size_t k = g.first[a]; k < g.first[a + 1]; ++k) {
      const std::uint32_t b = g.to[k];
      if (k > g.first[a] && g.to[k - 1] == b) continue;
      if (k + 1 < g.first[a + 1] && g.to[k + 1] == b)
        twice.add("edge " + edge_text(directed(a, b)) + " is in two elements the same way round (they overlap)");
      else if (!g.contains(b, a)) boundary.push_back(directed(a, b));
    }
  }
  return boundary;
}

// The lists against the boundary: each consecutive pair a boundary edge run
// with the domain on its left (a barrier's IBCONN list: on its right), and
// every boundary edge in exactly one list.
class ListCover {
public:
  ListCover(Verification& out, std::vector<std::uint64_t> boundary)
      : boundary_(std::move(boundary)), uses_(boundary_.size(), 0), wrong_(out, "list edges"),
        cover_(out, "boundary edges listed wrongly") {}

  void add(const std::vector<std::uint32_t>& nodes, bool domain_on_left, const std::string& list) {
    for (std::size_t j = 0; j + 1 < nodes.size(); ++j) {
      const std::uint32_t u = domain_on_left ? nodes[j] : nodes[j + 1];
      const std::uint32_t v = domain_on_left ? nodes[j + 1] : nodes[j];
      const std::string pair = list + ": nodes " + id(nodes[j]) + " " + id(nodes[j + 1]);
      if (u == v) {
        wrong_.add(pair + " repeat a node");
      } else if (const std::size_t at = find(directed(u, v)); at < boundary_.size()) {
        ++uses_[at];
      } else if (find(directed(v, u)) < boundary_.size()) {
        wrong_.add(pair + " run with the domain on their " + (domain_on_left ? "right" : "left"));
      } else {
        wrong_.add(pair + " are not a boundary edge (an edge of exactly one element)");
      }
    }
  }

  void finish() {
    for (std::size_t k = 0; k < boundary_.size(); ++k) {
      if (uses_[k] == 0) cover_.add("boundary edge " + edge_text(boundary_[k]) + " is in no boundary list");
      if (uses_[k] > 1)
        cover_.add("boundary edge " + edge_text(boundary_[k]) + " is in " + std::to_string(uses_[k]) + " lists");
    }
  }

private:
  std::size_t find(std::uint64_t key) const {
    const auto at = std::lower_bound(boundary_.begin(), boundary_.end(), key);
    return at != boundary_.end() && *at == key ? static_cast<std::size_t>(at - boundary_.begin()) : boundary_.size();
  }

  std::vector<std::uint64_t> boundary_;
  std::vector<std::uint32_t> uses_;
  Problems wrong_, cover_;
};

void check_lists(const Fort14& grid, Verification& out) {
  ListCover cover(out, boundary_edges(grid, out));
  Problems shape(out, "list problems");
  bool internal_seen = false;
  for (int flow = 0; flow < 2; ++flow) {
    const auto& lists = flow ? grid.land_boundaries : grid.open_boundaries;
    for (std::size_t k = 0; k < lists.size(); ++k) {
      const Fort14Boundary& b = lists[k];
      const std::string list = name(b, flow != 0, k);
      if (b.nodes.size() < 2) shape.add(list + " has fewer than 2 nodes");
      cover.add(b.nodes, true, list);
      if (paired_type(b.type) && flow) cover.add(b.paired, false, list + " IBCONN");
      if (!flow) continue;
      if (island_type(b.type) && !b.nodes.empty() && b.nodes.front() != b.nodes.back())
        shape.add(list + ": an island is not closed: its first node " + id(b.nodes.front()) +
                  " is not repeated as its last (" + id(b.nodes.back()) + ")");
      if (internal_type(b.type)) internal_seen = true;
      else if (internal_seen) shape.add(list + " is external but comes after an internal boundary");
    }
  }
  cover.finish();
}

// Ids within the nodes and arrays of matching sizes (a Fort14 built in
// memory need not be one parse_fort14 made): false stops the check there.
bool check_shape(const Fort14& grid, Verification& out) {
  const std::size_t n = grid.points.size();
  bool ok = grid.depths.size() == n;
  if (!ok) out.add("the nodes have " + std::to_string(grid.depths.size()) + " depths for " + std::to_string(n));
  const auto in_range = [n](const auto& ids) {
    return std::all_of(ids.begin(), ids.end(), [n](std::uint32_t v) { return v < n; });
  };
  for (std::size_t e = 0; e < grid.elements.size(); ++e)
    if (!in_range(grid.elements[e])) ok = false, out.add("element " + std::to_string(e + 1) + " names no node");
  for (int flow = 0; flow < 2; ++flow) {
    const auto& lists = flow ? grid.land_boundaries : grid.open_boundaries;
    for (std::size_t k = 0; k < lists.size(); ++k) {
      const Fort14Boundary& b = lists[k];
      const bool paired = flow && paired_type(b.type);
      if (!in_range(b.nodes) || !in_range(b.paired) || b.paired.size() != (paired ? b.nodes.size() : 0))
        ok = false, out.add(name(b, flow != 0, k) + " names no node, or its IBCONN list does not match");
    }
  }
  return ok;
}

}  // namespace

Verification check_fort14(const Fort14& grid) {
  Verification out;
  if (!check_shape(grid, out)) return out;
  check_totals(grid, out);
  check_elements(grid, out);
  check_lists(grid, out);
  return out;
}

}  // namespace madd
