// The all-or-nothing file write used by every output of madd (docs/hostile.md).
#include "madd/atomic_write.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "madd/error.hpp"

namespace madd {

namespace {
// Set from a signal handler (interrupt_output_writes), read by the writer:
// lock-free atomics are async-signal-safe.
std::atomic<bool> interrupt_requested{false};
std::atomic<int> writes_in_flight{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

struct InFlight {
  InFlight() { ++writes_in_flight; }
  ~InFlight() { --writes_in_flight; }
  InFlight(const InFlight&) = delete;
  InFlight& operator=(const InFlight&) = delete;
};

void throw_if_interrupted(const std::string& path) {
  if (interrupt_requested.load()) throw OutputError(path + ": interrupted; the file was not written");
}
} // namespace

bool interrupt_output_writes() noexcept {
  interrupt_requested.store(true);
  return writes_in_flight.load() > 0;
}

void write_file_atomically(const std::string& path, std::string_view contents) {
  const InFlight in_flight;
  throw_if_interrupted(path);
  const std::string tmp = path + ".tmp." + std::to_string(static_cast<long long>(::getpid()));
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) throw OutputError(path + ": cannot create '" + tmp + "': " + std::strerror(errno));
  const bool written = std::fwrite(contents.data(), 1, contents.size(), f) == contents.size();
  const int saved = errno;
  const bool closed = std::fclose(f) == 0;
  if (interrupt_requested.load()) {  // a signal arrived while writing: leave nothing behind
    std::remove(tmp.c_str());
    throw_if_interrupted(path);
  }
  if (!written || !closed) {
    std::remove(tmp.c_str());
    throw OutputError(path + ": cannot write '" + tmp + "': " + std::strerror(written ? errno : saved));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    throw OutputError(path + ": cannot rename '" + tmp + "' into place: " + std::strerror(err));
  }
}

} // namespace madd
