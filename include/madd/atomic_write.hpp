#pragma once
// Writing an output file all or nothing, as every output of madd does
// (docs/hostile.md): through a temporary file and a rename, never leaving a
// partial file, even when the process is interrupted.
#include <string>
#include <string_view>

namespace madd {

// Writes text to `path` through a temporary file and a rename, so that a
// failure never leaves a partial file. Throws OutputError on I/O failure.
void write_file_atomically(const std::string& path, std::string_view contents);

// Async-signal-safe, for a SIGINT/SIGTERM handler: from now on every
// write_file_atomically removes its temporary file and throws OutputError
// instead of finishing. Returns true when such a write is in progress (the
// handler should then return and let it unwind rather than exit at once).
bool interrupt_output_writes() noexcept;

} // namespace madd
