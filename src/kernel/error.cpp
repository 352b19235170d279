#include "madd/error.hpp"

#include <utility>

namespace madd {

const char* to_string(ErrorKind kind) noexcept {
  switch (kind) {
  case ErrorKind::bad_option:
    return "bad option";
  case ErrorKind::bad_input:
    return "bad input";
  case ErrorKind::decomposition:
    return "decomposition failed";
  case ErrorKind::output:
    return "output failed";
  case ErrorKind::limit:
    return "limit reached";
  case ErrorKind::internal:
    return "internal error";
  }
  return "error";
}

OptionError::OptionError(std::string option, std::string requirement)
    : Error(ErrorKind::bad_option, option + " " + requirement), option_(std::move(option)),
      requirement_(std::move(requirement)) {}

OptionError::OptionError(std::string option, std::string requirement, const std::string& message)
    : Error(ErrorKind::bad_option, message), option_(std::move(option)), requirement_(std::move(requirement)) {}

ParseError::ParseError(std::string path, std::size_t line, std::size_t column, const std::string& message)
    : Error(ErrorKind::bad_input, path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message),
      path_(std::move(path)), line_(line), column_(column), message_(message) {}

const char* to_string(InputProblem problem) noexcept {
  switch (problem) {
  case InputProblem::duplicate_vertex:
    return "duplicate vertex";
  case InputProblem::zero_length_segment:
    return "zero-length segment";
  case InputProblem::segments_intersect:
    return "segments intersect";
  case InputProblem::open_boundary:
    return "open boundary";
  case InputProblem::hole_on_segment:
    return "hole on segment";
  case InputProblem::hole_outside_domain:
    return "hole outside domain";
  case InputProblem::empty_domain:
    return "empty domain";
  case InputProblem::disconnected_domain:
    return "disconnected domain";
  case InputProblem::interior_segment:
    return "interior segment";
  case InputProblem::isolated_vertex:
    return "isolated vertex";
  case InputProblem::bad_weight:
    return "bad weight";
  case InputProblem::other:
    return "invalid input";
  }
  return "invalid input";
}

namespace {
std::string located(const std::string& path, std::size_t line, std::size_t column, const std::string& message) {
  if (path.empty()) return message;
  if (line == 0) return path + ": " + message;
  return path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
}
}  // namespace

InvalidInputError::InvalidInputError(InputProblem problem, const std::string& message, std::vector<std::int64_t> ids,
                                     std::vector<Point> points, std::string path, std::size_t line, std::size_t column)
    : Error(ErrorKind::bad_input, located(path, line, column, message)), problem_(problem), ids_(std::move(ids)),
      points_(std::move(points)), path_(std::move(path)), line_(line), column_(column) {}

DecompositionError::DecompositionError(const std::string& message, std::int64_t subdomain, double area,
                                       double separator_angle_deg)
    : Error(ErrorKind::decomposition, message), subdomain_(subdomain), area_(area),
      separator_angle_deg_(separator_angle_deg) {}

}  // namespace madd
