// Strict reader for ADCIRC's fort.14 (include/madd/model_output.hpp,
// parse_fort14). The records are those of "Fort.14: Grid and Boundary
// Information File" (adcirc.github.io/adcirc/technical_reference/
// input_files/fort14.html), one a line:
//   AGRID / NE, NP / NP x (JN, X, Y, DP) / NE x (JE, NHY, NM1, NM2, NM3) /
//   NOPE / NETA / NOPE x (NVDLL, IBTYPEE, then NVDLL x NBDV) /
//   NBOU / NVEL / NBOU x (NVELL, IBTYPE, then NVELL node records)
// where a node record of a flow boundary is, by IBTYPE: NBVV (0, 1, 2, 10,
// 11, 12, 20, 21, 22, 30); NBVV, BARLANHT, BARLANCFSP (3, 13, 23); NBVV,
// IBCONN, BARINHT, BARINCFSB, BARINCFSP (4, 24, 64); the same and PIPEHT,
// PIPECOEF, PIPEDIAM (5, 25).
#include <fstream>
#include <string>

#include "madd/error.hpp"
#include "madd/model_output.hpp"
#include "output/fort14_lexer.hpp"

namespace madd {

namespace {

using detail::Fort14Lexer;

// n records of at least `fields` fields each need 2 n fields - 1 bytes (one
// byte a field and a separator): a lying count fails before allocating.
void check_fits(const Fort14Lexer& lx, std::uint64_t n, std::uint64_t fields, std::size_t column, const char* what) {
  const std::uint64_t available = std::uint64_t{lx.remaining_bytes()} + 1;
  if (n != 0 && (2 * fields > available || n > available / (2 * fields)))
    lx.fail_column(column, std::to_string(n) + " " + what + " cannot fit in the " + std::to_string(available - 1) +
                               " bytes left in the file");
}

// A 1-based node id of the file, returned 0-based.
std::uint32_t node_id(Fort14Lexer& lx, std::uint32_t points, const char* what) {
  const std::int64_t id = lx.integer(what);
  if (id < 1 || id > std::int64_t{points})
    lx.fail_token(std::string(what) + " " + std::to_string(id) + " is not a node id (1.." + std::to_string(points) +
                  ")");
  return static_cast<std::uint32_t>(id - 1);
}

// The record number JN or JE of record k (0-based): it must be k + 1.
void expect_number(Fort14Lexer& lx, std::uint32_t k, const char* what) {
  const std::int64_t id = lx.integer(what);
  if (id != std::int64_t{k} + 1)
    lx.fail_token(std::string(what) + " " + std::to_string(id) + " is out of sequence: expected " +
                  std::to_string(std::int64_t{k} + 1) + " (records are numbered 1, 2, ... in order)");
}

void read_nodes(Fort14Lexer& lx, std::uint32_t np, Fort14& out) {
  out.points.reserve(np);
  out.depths.reserve(np);
  for (std::uint32_t k = 0; k < np; ++k) {
    lx.require_line("node record " + std::to_string(std::uint64_t{k} + 1) + " of " + std::to_string(np) +
                    " 'JN X Y DP'");
    expect_number(lx, k, "node number JN");
    const double x = lx.real("X");
    const double y = lx.real("Y");
    out.points.push_back({x, y});
    out.depths.push_back(lx.real("DP"));
    lx.end_of_record("the node record 'JN X Y DP'");
  }
}

void read_elements(Fort14Lexer& lx, std::uint32_t ne, std::uint32_t np, Fort14& out) {
  out.elements.reserve(ne);
  for (std::uint32_t k = 0; k < ne; ++k) {
    lx.require_line("element record " + std::to_string(std::uint64_t{k} + 1) + " of " + std::to_string(ne) +
                    " 'JE NHY NM1 NM2 NM3'");
    expect_number(lx, k, "element number JE");
    if (lx.integer("NHY") != 3) lx.fail_token("NHY must be 3 (ADCIRC's elements are triangles)");
    std::array<std::uint32_t, 3> element{};
    for (std::uint32_t& v : element) v = node_id(lx, np, "element node");
    out.elements.push_back(element);
    lx.end_of_record("the element record 'JE NHY NM1 NM2 NM3'");
  }
}

// A record of one count ("NOPE", "NETA"...) on its own line.
std::uint32_t count_record(Fort14Lexer& lx, const char* name, const char* meaning) {
  lx.require_line(std::string("the record ") + name + " (" + meaning + ")");
  const std::uint32_t n = lx.count(name);
  lx.end_of_record(name);
  return n;
}

// The per-node fields of a flow boundary of type `type`: ids (1, or 2 with
// IBCONN) and reals after them; false for a type the page does not list.
bool node_fields(int type, int& ids, int& reals) {
  switch (type) {
  case 0:
  case 1:
  case 2:
  case 10:
  case 11:
  case 12:
  case 20:
  case 21:
  case 22:
  case 30:
    ids = 1, reals = 0;
    return true;
  case 3:
  case 13:
  case 23:
    ids = 1, reals = 2;
    return true;
  case 4:
  case 24:
  case 64:
    ids = 2, reals = 3;
    return true;
  case 5:
  case 25:
    ids = 2, reals = 6;
    return true;
  default:
    return false;
  }
}

// One boundary segment: its "NVDLL IBTYPEE" or "NVELL IBTYPE" record, then
// its node records (`flow`: fields by IBTYPE; else one id).
Fort14Boundary read_boundary(Fort14Lexer& lx, std::uint32_t np, bool flow, std::uint32_t k) {
  const std::string which = std::string(flow ? "flow" : "open") + " boundary " + std::to_string(k + 1);
  lx.require_line("the record '" + std::string(flow ? "NVELL IBTYPE" : "NVDLL IBTYPEE") + "' of " + which);
  Fort14Boundary b;
  b.line = static_cast<std::uint32_t>(lx.line());
  const std::uint32_t n = lx.count(flow ? "NVELL" : "NVDLL");
  const std::size_t column = lx.token_column();
  const std::int64_t type = lx.integer(flow ? "IBTYPE" : "IBTYPEE");
  int ids = 1, reals = 0;
  if (type < -1000000 || type > 1000000 || (flow && !node_fields(static_cast<int>(type), ids, reals)))
    lx.fail_token(std::string(flow ? "IBTYPE " : "IBTYPEE ") + std::to_string(type) +
                  " is not a type the fort.14 page lists (0, 1, 2, 10, 11, 12, 20, 21, 22, 30; 3, 13, 23; "
                  "4, 24, 64; 5, 25)");
  b.type = static_cast<int>(type);
  lx.end_of_record(flow ? "'NVELL IBTYPE'" : "'NVDLL IBTYPEE'");
  check_fits(lx, n, static_cast<std::uint64_t>(ids + reals), column, "boundary node records");
  b.nodes.reserve(n);
  if (ids == 2) b.paired.reserve(n);
  b.values.reserve(std::size_t{n} * static_cast<std::size_t>(reals));
  for (std::uint32_t j = 0; j < n; ++j) {
    lx.require_line("node record " + std::to_string(std::uint64_t{j} + 1) + " of " + std::to_string(n) + " of " +
                    which);
    b.nodes.push_back(node_id(lx, np, flow ? "NBVV" : "NBDV"));
    if (ids == 2) b.paired.push_back(node_id(lx, np, "IBCONN"));
    for (int r = 0; r < reals; ++r) b.values.push_back(lx.real("barrier value"));
    lx.end_of_record("the boundary node record");
  }
  return b;
}

// NOPE, NETA and the open boundaries, or NBOU, NVEL and the flow boundaries.
void read_boundaries(Fort14Lexer& lx, std::uint32_t np, bool flow, Fort14& out) {
  const char* name = flow ? "NBOU" : "NOPE";
  lx.require_line(std::string("the record ") + name +
                  (flow ? " (number of flow boundary segments)" : " (number of open boundary segments)"));
  const std::uint32_t segments = lx.count(name);
  check_fits(lx, segments, 2, lx.token_column(), "boundary segments");
  lx.end_of_record(name);
  (flow ? out.declared_land_nodes : out.declared_open_nodes) =
      flow ? count_record(lx, "NVEL", "total number of flow boundary nodes")
           : count_record(lx, "NETA", "total number of open boundary nodes");
  auto& lists = flow ? out.land_boundaries : out.open_boundaries;
  lists.reserve(segments);
  for (std::uint32_t k = 0; k < segments; ++k) lists.push_back(read_boundary(lx, np, flow, k));
}

}  // namespace

Fort14 parse_fort14(std::string_view text, const std::string& path) {
  Fort14Lexer lx(text, path);
  Fort14 out;
  out.title = lx.title();
  lx.require_line("the record 'NE NP' (number of elements and nodes)");
  const std::uint32_t ne = lx.count("NE");
  const std::size_t column = lx.token_column();
  const std::uint32_t np = lx.count("NP");
  lx.end_of_record("'NE NP'");
  // A node record is at least 4 fields (8 bytes), an element record 5 (10).
  const std::uint64_t needed = 8 * std::uint64_t{np} + 10 * std::uint64_t{ne};
  if (needed > std::uint64_t{lx.remaining_bytes()} + 1)
    lx.fail_column(column, std::to_string(ne) + " elements and " + std::to_string(np) + " nodes cannot fit in the " +
                               std::to_string(lx.remaining_bytes()) + " bytes left in the file");
  read_nodes(lx, np, out);
  read_elements(lx, ne, np, out);
  read_boundaries(lx, np, false, out);
  read_boundaries(lx, np, true, out);
  lx.expect_end("the last flow boundary");
  return out;
}

Fort14 read_fort14_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputFileError("cannot open '" + path + "'");
  const std::streamoff size = in.tellg();
  std::string text;
  if (size > 0) {
    text.resize(static_cast<std::size_t>(size));
    in.seekg(0);
    if (!in.read(text.data(), size)) throw InputFileError("cannot read '" + path + "'");
  } else if (size < 0) {
    throw InputFileError("cannot read '" + path + "'");
  }
  return parse_fort14(text, path);
}

}  // namespace madd
