#pragma once
// Typed errors (docs/design.md, "Errors"). Every failure madd reports to a caller is a
// madd::Error; the CLI maps each subclass to its own exit code (docs/cli.md).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "madd/geometry.hpp"

namespace madd {

// Base of every error madd throws on purpose. Anything else escaping is a bug.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// A file could not be parsed. what() is "path:line:column: message".
class ParseError : public Error {
public:
  ParseError(std::string path, std::size_t line, std::size_t column, const std::string& message);
  const std::string& path() const noexcept { return path_; }
  std::size_t line() const noexcept { return line_; }
  std::size_t column() const noexcept { return column_; }
  const std::string& message() const noexcept { return message_; }

private:
  std::string path_;
  std::size_t line_;
  std::size_t column_;
  std::string message_;
};

// The kinds of semantically invalid input (docs/formats.md, "Bad input").
enum class InputProblem : std::uint8_t {
  duplicate_vertex,
  zero_length_segment,
  segments_intersect,
  open_boundary,
  hole_on_segment,
  hole_outside_domain,
  empty_domain,
  disconnected_domain,
  interior_segment,
  isolated_vertex,
  bad_weight,
  other,
};
const char* to_string(InputProblem problem) noexcept;

// The input parsed but does not describe a valid domain. Carries the offending
// ids (as written in the file, i.e. with the file's 0/1 base) and coordinates,
// and, when the domain came from a file, the line and column of the first item.
class InvalidInputError : public Error {
public:
  InvalidInputError(InputProblem problem, const std::string& message, std::vector<std::int64_t> ids = {},
                    std::vector<Point> points = {}, std::string path = {}, std::size_t line = 0,
                    std::size_t column = 0);
  InputProblem problem() const noexcept { return problem_; }
  const std::vector<std::int64_t>& ids() const noexcept { return ids_; }
  const std::vector<Point>& points() const noexcept { return points_; }
  const std::string& path() const noexcept { return path_; }
  std::size_t line() const noexcept { return line_; }
  std::size_t column() const noexcept { return column_; }

private:
  InputProblem problem_;
  std::vector<std::int64_t> ids_;
  std::vector<Point> points_;
  std::string path_;
  std::size_t line_;
  std::size_t column_;
};

// A decomposition could not be completed (for example no separator meets the
// minimum angle). Names the subdomain, its area and the angle bound in degrees.
class DecompositionError : public Error {
public:
  DecompositionError(const std::string& message, std::int64_t subdomain = -1, double area = 0.0,
                     double min_angle_deg = 0.0);
  std::int64_t subdomain() const noexcept { return subdomain_; }
  double area() const noexcept { return area_; }
  double min_angle_deg() const noexcept { return min_angle_deg_; }

private:
  std::int64_t subdomain_;
  double area_;
  double min_angle_deg_;
};

// An input file could not be opened or read (exit code 3 in the CLI, like
// any other bad input).
class InputFileError : public Error {
public:
  using Error::Error;
};

// An output file or directory could not be written (exit code 5).
class OutputError : public Error {
public:
  using Error::Error;
};

// An invariant that should hold by construction did not: a bug in madd, not a
// problem with the input (exit code 70). Raised instead of returning a wrong result.
class InternalError : public Error {
public:
  using Error::Error;
};

// A resource limit (--max-memory, --time-limit) was reached.
class LimitError : public Error {
public:
  using Error::Error;
};

// The result of a verifier (verify_triangulation, verify_bisection, ...):
// empty problems means every invariant held.
struct Verification {
  std::vector<std::string> problems;
  bool ok() const noexcept { return problems.empty(); }
  explicit operator bool() const noexcept { return ok(); }
  void add(std::string problem) { problems.push_back(std::move(problem)); }
};

} // namespace madd
