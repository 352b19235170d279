#pragma once
// Typed errors. Every failure madd reports to a caller is a madd::Error that
// carries its kind; front ends map the kind to an exit code (docs/cli.md; docs/design.md, "Errors")
// without asking which subclass it is. The subclasses add what a caller needs
// to act on the error (the file position, the option, the subdomain).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "madd/geometry.hpp"

namespace madd {

// What went wrong, in the terms a caller acts on (the CLI's exit codes, docs/cli.md).
enum class ErrorKind : std::uint8_t {
  bad_option,     // an option out of its range, or options that contradict each other
  bad_input,      // an input file could not be read or parsed, or is not a valid domain
  decomposition,  // no valid decomposition exists at these settings
  output,         // an output could not be written
  limit,          // a resource limit (time, memory) was reached
  internal,       // an invariant failed: a bug in madd
};
const char* to_string(ErrorKind kind) noexcept;

// Base of every error madd throws on purpose. Anything else escaping is a bug.
class Error : public std::runtime_error {
public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const noexcept { return kind_; }

private:
  ErrorKind kind_;
};

// An option is out of its range or contradicts another one (ErrorKind::bad_option).
// option() names the field as the options struct spells it ("separator_angle_deg"),
// so that a front end can say it in its own words ("--min-angle", "f");
// requirement() is the rule it broke ("must lie strictly between 0 and 90 degrees").
// what() is "option requirement", or a located message given by a front end.
class OptionError : public Error {
public:
  OptionError(std::string option, std::string requirement);
  OptionError(std::string option, std::string requirement, const std::string& message);
  const std::string& option() const noexcept { return option_; }
  const std::string& requirement() const noexcept { return requirement_; }

private:
  std::string option_;
  std::string requirement_;
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
                     double separator_angle_deg = 0.0);
  std::int64_t subdomain() const noexcept { return subdomain_; }
  double area() const noexcept { return area_; }
  double separator_angle_deg() const noexcept { return separator_angle_deg_; }

private:
  std::int64_t subdomain_;
  double area_;
  double separator_angle_deg_;
};

// An input file could not be opened or read (ErrorKind::bad_input, like any
// other bad input).
class InputFileError : public Error {
public:
  explicit InputFileError(const std::string& message) : Error(ErrorKind::bad_input, message) {}
};

// An output file or directory could not be written (ErrorKind::output).
class OutputError : public Error {
public:
  explicit OutputError(const std::string& message) : Error(ErrorKind::output, message) {}
};

// An invariant that should hold by construction did not, or a self-check
// (verify_decomposition before writing) failed: a bug in madd, not a problem
// with the input (ErrorKind::internal). Raised instead of returning a wrong result.
class InternalError : public Error {
public:
  explicit InternalError(const std::string& message) : Error(ErrorKind::internal, message) {}
};

// A resource limit (time_limit_seconds, max_memory_bytes) was reached (ErrorKind::limit).
class LimitError : public Error {
public:
  explicit LimitError(const std::string& message) : Error(ErrorKind::limit, message) {}
};

// The result of a verifier (verify_triangulation, verify_bisection, ...):
// empty problems means every invariant held.
struct Verification {
  std::vector<std::string> problems;
  bool ok() const noexcept { return problems.empty(); }
  explicit operator bool() const noexcept { return ok(); }
  void add(std::string problem) { problems.push_back(std::move(problem)); }
  friend bool operator==(const Verification&, const Verification&) = default;
};

}  // namespace madd
