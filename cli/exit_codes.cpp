// The one place that decides which exit code an error gets (cli/commands.hpp);
// shared by madd and madd-mpi.
#include "commands.hpp"

namespace madd::cli {

int exit_code_of(ErrorKind kind) noexcept {
  switch (kind) {
  case ErrorKind::bad_option: return exit_usage;
  case ErrorKind::bad_input: return exit_bad_input;
  case ErrorKind::decomposition: return exit_decompose_failed;
  case ErrorKind::output: return exit_io;
  case ErrorKind::limit: return exit_limit;
  case ErrorKind::internal: return exit_internal;
  }
  return exit_internal;
}

} // namespace madd::cli
