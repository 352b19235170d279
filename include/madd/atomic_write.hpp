#pragma once
// Writing an output file all or nothing, as every output of madd does
// (docs/hostile.md): through a temporary file and a rename, never leaving a
// partial file, even when the process is interrupted.
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace madd {

// Writes text to `path` through a temporary file and a rename, so that a
// failure never leaves a partial file. Throws OutputError on I/O failure.
void write_file_atomically(const std::string& path, std::string_view contents);

// Async-signal-safe, for a SIGINT/SIGTERM handler: from now on every
// write_file_atomically removes its temporary file and throws OutputError
// instead of finishing. Returns true when such a write is in progress (the
// handler should then return and let it unwind rather than exit at once).
bool interrupt_output_writes() noexcept;

// Several outputs written as one, all or nothing (the CLI's set of -o, --svg,
// --split... files). write() first stages every output in full under a
// temporary name beside its target (a directory as a whole temporary
// directory); only when every one is staged are they moved into place. A
// failure while staging (a missing directory, a full disk, an interrupt)
// removes every temporary and leaves every target as it was. The moves
// themselves are renames within each target's directory, which do not fail
// for space; should one fail anyway, the error says which outputs were
// already in place.
// A file's text made in pieces: make(i) returns piece i of `count`, on any
// of `threads` threads (several at once). The pieces are written in order,
// each as soon as it and all before it are made, a few pieces ahead at the
// most, so the whole text is never held at once and making overlaps writing;
// the file is the same for any thread count. Whatever make reads must live
// until the set is written.
struct FilePieces {
  std::size_t count = 0;
  std::function<std::string(std::size_t piece)> make;
  unsigned threads = 1;
};

class OutputSet {
public:
  // One file. Throws OutputError when `path` is already in the set.
  void add_file(std::string path, std::string contents);
  void add_file(std::string path, FilePieces pieces);
  // A directory holding `files` (name, contents; names without '/'), created
  // or updated: files of an existing `dir` for which `is_stale(name)` is true
  // and that are not in `files` are removed once the new ones are in place
  // (an older run's files). Throws OutputError when `dir` is already in the set.
  void add_directory(std::string dir, std::vector<std::pair<std::string, std::string>> files,
                     std::function<bool(const std::string& name)> is_stale = {});
  bool empty() const noexcept { return files_.empty() && directories_.empty(); }
  // Stages and publishes everything; throws OutputError. The set is empty afterwards.
  void write();
  // The same for one of several processes writing one set together
  // (madd-mpi): once staging has ended here, all_staged(staged_here) is called
  // exactly once, whether or not staging succeeded, and must return whether
  // every process staged everything (an MPI_Allreduce). Only then is anything
  // moved into place; otherwise every temporary is removed and OutputError thrown.
  void write(const std::function<bool(bool staged_here)>& all_staged);

private:
  struct File {
    std::string path, contents;
    FilePieces pieces;  // when pieces.make: the contents, made while writing
  };
  struct Directory {
    std::string path;
    std::vector<std::pair<std::string, std::string>> files;
    std::function<bool(const std::string&)> is_stale;
  };
  void claim(const std::string& path);
  std::vector<File> files_;
  std::vector<Directory> directories_;
  std::vector<std::string> targets_;
};

}  // namespace madd
