// Writer for Triangle's .poly format, and the atomic file write used by every
// output of madd.
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <unistd.h>

#include "madd/error.hpp"
#include "madd/poly_io.hpp"

namespace madd {
namespace {

// Appends numbers without iostreams. Doubles use std::to_chars' shortest
// round-trip form: parse_poly reads back the identical double, as %.17g
// would guarantee (docs/formats.md, "Precision"), with fewer digits.
class TextOut {
public:
  explicit TextOut(std::size_t reserve) { text_.reserve(reserve); }
  TextOut& num(double v) {
    char buf[40];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;
    text_.append(buf, ptr);
    return *this;
  }
  TextOut& num(std::int64_t v) {
    char buf[24];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;
    text_.append(buf, ptr);
    return *this;
  }
  TextOut& id(std::size_t index, std::uint32_t base) { return num(static_cast<std::int64_t>(index + base)); }
  TextOut& sp() {
    text_ += ' ';
    return *this;
  }
  TextOut& str(std::string_view s) {
    text_ += s;
    return *this;
  }
  TextOut& nl() {
    text_ += '\n';
    return *this;
  }
  std::string take() { return std::move(text_); }

private:
  std::string text_;
};

void write_comment(TextOut& out, std::string_view comment) {
  while (!comment.empty()) {
    const std::size_t end = comment.find('\n');
    out.str("# ").str(comment.substr(0, end)).nl();
    if (end == std::string_view::npos) break;
    comment.remove_prefix(end + 1);
  }
}

void write_points(TextOut& out, const Pslg& p) {
  const bool markers = !p.point_markers.empty();
  out.num(static_cast<std::int64_t>(p.points.size())).str(" 2 ").num(std::int64_t{p.attributes_per_point});
  out.str(markers ? " 1" : " 0").nl();
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    out.id(i, p.first_index).sp().num(p.points[i].x).sp().num(p.points[i].y);
    for (std::size_t k = 0; k < p.attributes_per_point; ++k) out.sp().num(p.attribute(i, k));
    if (markers) out.sp().num(std::int64_t{p.point_markers[i]});
    out.nl();
  }
}

void write_segments(TextOut& out, const Pslg& p) {
  out.num(static_cast<std::int64_t>(p.segments.size())).str(p.has_segment_markers ? " 1" : " 0").nl();
  for (std::size_t i = 0; i < p.segments.size(); ++i) {
    const Segment& s = p.segments[i];
    out.id(i, p.first_index).sp().id(s.a, p.first_index).sp().id(s.b, p.first_index);
    if (p.has_segment_markers) out.sp().num(std::int64_t{s.marker});
    out.nl();
  }
}

void write_holes_and_regions(TextOut& out, const Pslg& p) {
  out.num(static_cast<std::int64_t>(p.holes.size())).nl();
  for (std::size_t i = 0; i < p.holes.size(); ++i)
    out.id(i, p.first_index).sp().num(p.holes[i].x).sp().num(p.holes[i].y).nl();
  if (p.regions.empty()) return;
  out.num(static_cast<std::int64_t>(p.regions.size())).nl();
  for (std::size_t i = 0; i < p.regions.size(); ++i) {
    const Region& r = p.regions[i];
    out.id(i, p.first_index).sp().num(r.at.x).sp().num(r.at.y).sp().num(r.attribute).sp().num(r.max_area).nl();
  }
}

} // namespace

std::string format_poly(const Pslg& pslg, std::string_view header_comment) {
  TextOut out(64 + header_comment.size() + pslg.points.size() * 48 + pslg.segments.size() * 24);
  write_comment(out, header_comment);
  write_points(out, pslg);
  write_segments(out, pslg);
  write_holes_and_regions(out, pslg);
  return out.take();
}

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
