// The one place that decides which exit code an error gets, and how a
// failure is said (cli/commands.hpp); shared by madd and madd-mpi.
#include <exception>
#include <new>
#include <string>

#include "commands.hpp"

namespace madd::cli {

int exit_code_of(ErrorKind kind) noexcept {
  switch (kind) {
  case ErrorKind::bad_option:
    return exit_usage;
  case ErrorKind::bad_input:
    return exit_bad_input;
  case ErrorKind::decomposition:
    return exit_decompose_failed;
  case ErrorKind::output:
    return exit_io;
  case ErrorKind::limit:
    return exit_limit;
  case ErrorKind::internal:
    return exit_internal;
  }
  return exit_internal;
}

Failure current_failure() noexcept {
  try {
    try {
      throw;
    } catch (const Error& e) {
      const int code = exit_code_of(e.kind());
      return {code, std::string(code == exit_internal ? "internal error: " : "error: ") + e.what()};
    } catch (const std::bad_alloc&) {
      return {exit_limit, "error: out of memory"};
    } catch (const std::exception& e) {
      return {exit_internal, std::string("internal error: ") + e.what()};
    } catch (...) {
      return {exit_internal, "internal error: an unknown exception"};
    }
  } catch (...) {  // no memory left even for the message
    return {exit_limit, {}};
  }
}

}  // namespace madd::cli
