#pragma once
// SIGINT and SIGTERM for madd and madd-mpi (docs/hostile.md): nothing partial
// may stay on disk, so each front end's handler lets an output write unwind
// and remove its staging, and otherwise exits at once.
#include <signal.h>

namespace madd::cli {

// Calls `handler` on SIGINT and SIGTERM; system calls it interrupts restart.
inline void on_interrupts(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace madd::cli
