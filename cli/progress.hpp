#pragma once
// The CLI's one-line progress note on stderr (docs/cli.md): only on a
// terminal, rewritten in place, cleared before anything else is printed.
#include <chrono>
#include <cstdint>
#include <string>

namespace madd::cli {

// "decomposing: 312/1000 subdomains, 1.4 s" (or "meshing: ...").
std::string count_text(std::uint32_t done, std::uint32_t target, double seconds, const char* doing = "decomposing");

// The phase, and while decomposing the subdomains done of N and the time since
// the phase began, rewritten in place (\r) at most a few times a second.
// Cleared at the end, and by the destructor when an error ends the run, so
// that the error message starts its own line.
class Progress {
public:
  explicit Progress(bool enabled);
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress() { done(); }
  bool enabled() const { return enabled_; }
  void say(const std::string& text);
  // DecomposeOptions::progress: the first count at once, then every 0.25 s.
  void count(std::uint32_t done, std::uint32_t target, const char* doing = "decomposing");
  void done();

private:
  void show(const std::string& text);
  bool enabled_;
  bool shown_ = false;
  bool counted_ = false;
  std::chrono::steady_clock::time_point phase_start_ = std::chrono::steady_clock::now(), last_count_;
};

}  // namespace madd::cli
