// The all-or-nothing file write used by every output of madd (docs/hostile.md).
#include "madd/atomic_write.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <system_error>
#include <vector>

#include "kernel/threads.hpp"
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
}  // namespace

bool interrupt_output_writes() noexcept {
  interrupt_requested.store(true);
  return writes_in_flight.load() > 0;
}

namespace {

// Creates the new file `tmp` (the staging name of `path`) and lets
// write(f) fill it (true when every byte was written); removes it and
// throws OutputError on failure or on an interrupt (and rethrows what
// write threw).
template <typename Write>
void write_temporary_with(const std::string& path, const std::string& tmp, const Write& write) {
  throw_if_interrupted(path);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) throw OutputError(path + ": cannot create '" + tmp + "': " + std::strerror(errno));
  bool written = false;
  try {
    written = write(f);
  } catch (...) {
    std::fclose(f);
    std::remove(tmp.c_str());
    throw;
  }
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
}

void write_temporary(const std::string& path, const std::string& tmp, std::string_view contents) {
  write_temporary_with(
      path, tmp, [&](std::FILE* f) { return std::fwrite(contents.data(), 1, contents.size(), f) == contents.size(); });
}

// The pieces' writer for one or more files in a row: make() runs on the
// workers, the calling thread stages the files one after another and
// writes each file's pieces in order into it, and the workers stay at most
// `window` pieces ahead of it across the files (the memory held is a few
// pieces, not a file), so the next file's first pieces are made while the
// last of the one before are written: with one writer per file the
// formatters idled at every file's end (docs/performance.md, "Parked
// threads").
class PieceWriter {
public:
  // Fills one file: writes its pieces as they are made; false when a write failed.
  using Fill = std::function<bool(std::FILE*)>;
  // Stages file f (creates it and calls fill); throws to stop.
  using Stage = std::function<void(std::size_t f, const Fill& fill)>;

  explicit PieceWriter(std::vector<const FilePieces*> files) : files_(std::move(files)) {
    first_.push_back(0);
    unsigned threads = 1;
    for (const FilePieces* f : files_) {
      first_.push_back(first_.back() + f->count);
      threads = std::max(threads, f->threads);
    }
    made_.resize(first_.back());
    workers_ = detail::thread_count(threads, first_.back());
    window_ = 4 * std::size_t{workers_};
  }

  // stage(f, fill) for every file in order on the calling thread, the
  // pieces made meanwhile on the workers; rethrows what stage or make threw.
  void run(const Stage& stage) {
    detail::run_on_threads(first_.back() > 0 ? workers_ + 1 : 1, [&](unsigned id) {
      if (id == 0) stage_all(stage);
      else work();
    });
  }

private:
  void stage_all(const Stage& stage) {
    try {
      for (std::size_t f = 0; f < files_.size(); ++f) stage(f, [&](std::FILE* out) { return fill(f, out); });
    } catch (...) {
      stop();
      throw;
    }
    stop();
  }

  void stop() {
    {
      const std::lock_guard lock(mutex_);
      stop_ = true;
    }
    changed_.notify_all();
  }

  bool fill(std::size_t f, std::FILE* out) {
    for (std::size_t i = first_[f]; i < first_[f + 1]; ++i) {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return made_[i].has_value() || error_; });
      if (error_) std::rethrow_exception(error_);
      const std::string piece = std::move(*made_[i]);
      made_[i].reset();
      written_ = i + 1;
      lock.unlock();
      changed_.notify_all();
      if (std::fwrite(piece.data(), 1, piece.size(), out) != piece.size() || interrupt_requested.load()) return false;
    }
    return true;
  }

  void work() {
    for (;;) {
      std::size_t i = 0;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return stop_ || error_ || next_ >= made_.size() || next_ < written_ + window_; });
        if (stop_ || error_ || next_ >= made_.size()) return;
        i = next_++;
      }
      try {
        const auto f = static_cast<std::size_t>(std::upper_bound(first_.begin(), first_.end(), i) - first_.begin()) - 1;
        std::string piece = files_[f]->make(i - first_[f]);
        const std::lock_guard lock(mutex_);
        made_[i] = std::move(piece);
      } catch (...) {
        const std::lock_guard lock(mutex_);
        if (!error_) error_ = std::current_exception();
      }
      changed_.notify_all();
    }
  }

  std::vector<const FilePieces*> files_;
  std::vector<std::size_t> first_;  // per file, its first piece's number in the run; then the total
  unsigned workers_ = 1;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::optional<std::string>> made_;
  std::size_t next_ = 0, written_ = 0, window_ = 1;
  bool stop_ = false;
  std::exception_ptr error_;
};

std::string temporary_name(const std::string& path, std::size_t serial) {
  return path + ".tmp." + std::to_string(static_cast<long long>(::getpid())) + "." + std::to_string(serial);
}

}  // namespace

void write_file_atomically(const std::string& path, std::string_view contents) {
  const InFlight in_flight;
  const std::string tmp = temporary_name(path, 0);
  write_temporary(path, tmp, contents);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    throw OutputError(path + ": cannot rename '" + tmp + "' into place: " + std::strerror(err));
  }
}

namespace {

namespace fs = std::filesystem;

// A directory staged beside its target: ".<name>.madd-tmp-<pid>-<n>".
fs::path staging_directory(const fs::path& dir) {
  fs::path parent = dir.parent_path();
  if (parent.empty()) parent = ".";
  const std::string base = dir.filename().string();
  for (int attempt = 0;; ++attempt) {
    fs::path candidate =
        parent / ("." + base + ".madd-tmp-" + std::to_string(::getpid()) + "-" + std::to_string(attempt));
    if (!fs::exists(candidate)) return candidate;
  }
}

// "parts/" names "parts".
fs::path directory_path(const std::string& name) {
  fs::path dir = fs::path(name).lexically_normal();
  if (dir.filename().empty() && dir.has_parent_path()) dir = dir.parent_path();
  return dir;
}

// One output on its way: where it was staged, where it goes.
struct Staged {
  fs::path staged, target;
  bool directory = false;
  std::function<bool(const std::string&)> is_stale;
  std::vector<std::string> names;  // of a directory's files
};

void remove_staged(const std::vector<Staged>& staged) {
  std::error_code ignored;
  for (const Staged& s : staged)
    if (!s.staged.empty()) fs::remove_all(s.staged, ignored);
}

// Stages `files` into a new temporary directory beside `s.target`.
void stage_directory(const std::string& name, const std::vector<std::pair<std::string, std::string>>& files,
                     Staged& s) {
  if (fs::exists(s.target) && !fs::is_directory(s.target)) throw OutputError(name + ": exists and is not a directory");
  if (!s.target.parent_path().empty()) fs::create_directories(s.target.parent_path());
  s.staged = staging_directory(s.target);
  fs::create_directory(s.staged);
  for (const auto& [file, contents] : files) {
    write_temporary((s.target / file).string(), (s.staged / file).string(), contents);
    s.names.push_back(file);
  }
}

// Moves a staged directory's files into the target (or the staged directory
// itself, when there is no target yet), then removes the stale ones.
void publish_directory(const Staged& s) {
  if (!fs::exists(s.target)) {
    fs::rename(s.staged, s.target);
    return;
  }
  for (const std::string& name : s.names) fs::rename(s.staged / name, s.target / name);
  std::vector<fs::path> stale;
  if (s.is_stale) {
    for (const auto& entry : fs::directory_iterator(s.target)) {
      const std::string name = entry.path().filename().string();
      if (s.is_stale(name) && std::find(s.names.begin(), s.names.end(), name) == s.names.end())
        stale.push_back(entry.path());
    }
  }
  for (const fs::path& p : stale) fs::remove(p);
  fs::remove_all(s.staged);
}

}  // namespace

void OutputSet::claim(const std::string& path) {
  const std::string normal = directory_path(path).string();
  if (std::find(targets_.begin(), targets_.end(), normal) != targets_.end())
    throw OutputError(path + ": named twice among the outputs");
  targets_.push_back(normal);
}

void OutputSet::add_file(std::string path, std::string contents) {
  claim(path);
  files_.push_back({std::move(path), std::move(contents), {}});
}

void OutputSet::add_file(std::string path, FilePieces pieces) {
  claim(path);
  files_.push_back({std::move(path), {}, std::move(pieces)});
}

void OutputSet::add_directory(std::string dir, std::vector<std::pair<std::string, std::string>> files,
                              std::function<bool(const std::string&)> is_stale) {
  claim(dir);
  directories_.push_back({std::move(dir), std::move(files), std::move(is_stale)});
}

void OutputSet::write() { write({}); }

void OutputSet::write(const std::function<bool(bool staged_here)>& all_staged) {
  const InFlight in_flight;
  std::vector<Staged> staged;
  std::string current;  // the output being staged, for messages
  std::string failure;  // why staging failed here, when it did
  try {
    // File k staged with fill (its contents, or its pieces as they are made).
    const auto stage = [&](std::size_t k, const PieceWriter::Fill& fill) {
      current = files_[k].path;
      // Found now, not when moving into place: the others must not be moved either.
      if (fs::is_directory(files_[k].path)) throw OutputError(files_[k].path + ": is a directory");
      Staged s;
      s.target = files_[k].path;
      s.staged = temporary_name(files_[k].path, k);
      write_temporary_with(files_[k].path, s.staged.string(), fill);
      staged.push_back(std::move(s));
    };
    for (std::size_t k = 0; k < files_.size();) {
      if (!files_[k].pieces.make) {
        const std::string& contents = files_[k].contents;
        stage(k, [&](std::FILE* f) { return std::fwrite(contents.data(), 1, contents.size(), f) == contents.size(); });
        ++k;
        continue;
      }
      // Files made in pieces one after another: one pipeline for all of them.
      std::vector<const FilePieces*> run;
      const std::size_t first = k;
      for (; k < files_.size() && files_[k].pieces.make; ++k) run.push_back(&files_[k].pieces);
      PieceWriter(std::move(run)).run([&](std::size_t f, const PieceWriter::Fill& fill) { stage(first + f, fill); });
    }
    for (const Directory& d : directories_) {
      current = d.path;
      Staged& s = staged.emplace_back();
      s.target = directory_path(d.path);
      s.directory = true;
      s.is_stale = d.is_stale;
      stage_directory(d.path, d.files, s);
    }
    throw_if_interrupted(current);
  } catch (const fs::filesystem_error& e) {
    failure = current + ": cannot write: " + e.code().message() + " (no output was written)";
  } catch (const OutputError& e) {
    failure = std::string(e.what()) + " (no output was written)";
  } catch (const std::exception& e) {  // out of memory, say: the others must still hear of it
    failure = current + ": cannot write: " + e.what() + " (no output was written)";
  }
  // With several writers, every one answers once, whatever happened here.
  const bool everyone = all_staged ? all_staged(failure.empty()) : failure.empty();
  if (!failure.empty() || !everyone) {
    remove_staged(staged);
    throw OutputError(failure.empty() ? "another process could not write its outputs (no output was written)"
                                      : failure);
  }
  // Everything is staged: move it into place.
  std::vector<std::string> published;
  for (std::size_t k = 0; k < staged.size(); ++k) {
    const Staged& s = staged[k];
    std::error_code error;
    if (s.directory) {
      try {
        publish_directory(s);
      } catch (const fs::filesystem_error& e) {
        error = e.code();
      }
    } else {
      fs::rename(s.staged, s.target, error);
    }
    if (error) {
      remove_staged({staged.begin() + static_cast<std::ptrdiff_t>(k), staged.end()});
      std::string done;
      for (const std::string& p : published) done += (done.empty() ? "" : ", ") + p;
      throw OutputError(s.target.string() + ": cannot move into place: " + error.message() +
                        (done.empty() ? std::string(" (no output was written)") : " (already written: " + done + ")"));
    }
    published.push_back(s.target.string());
  }
  files_.clear();
  directories_.clear();
  targets_.clear();
}

}  // namespace madd
