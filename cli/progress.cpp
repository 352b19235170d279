#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace madd::cli {

std::string count_text(std::uint32_t done, std::uint32_t target, double seconds, const char* doing) {
  char text[96];
  std::snprintf(text, sizeof text, "%s: %u/%u subdomains, %.1f s", doing, done, target, seconds);
  return text;
}

Progress::Progress(bool enabled) : enabled_(enabled && ::isatty(STDERR_FILENO) == 1) {}

void Progress::say(const std::string& text) {
  phase_start_ = std::chrono::steady_clock::now();
  counted_ = false;
  show(text);
}

void Progress::count(std::uint32_t done, std::uint32_t target, const char* doing) {
  const auto now = std::chrono::steady_clock::now();
  if (counted_ && now - last_count_ < std::chrono::milliseconds(250)) return;
  counted_ = true;
  last_count_ = now;
  show(count_text(done, target, std::chrono::duration<double>(now - phase_start_).count(), doing));
}

void Progress::done() {
  if (enabled_ && shown_) std::fputs("\r\033[K", stderr);
  shown_ = false;
}

void Progress::show(const std::string& text) {
  if (!enabled_) return;
  std::fprintf(stderr, "\r\033[Kmadd: %s", text.c_str());
  shown_ = true;
}

}  // namespace madd::cli
