// Writer for Triangle's .poly format (docs/formats.md).
#include <cstdint>
#include <string>

#include "kernel/number_format.hpp"
#include "madd/poly_io.hpp"

namespace madd {
namespace {

// Appends numbers without iostreams. Doubles take the shortest text that
// reads back as the same double, so parse_poly gives back the identical
// Pslg, as %.17g would (docs/formats.md, "Precision"), with fewer digits.
class TextOut {
public:
  explicit TextOut(std::size_t reserve) { text_.reserve(reserve); }
  TextOut& num(double v) {
    detail::append_shortest(text_, v);
    return *this;
  }
  TextOut& num(std::int64_t v) {
    detail::append_int(text_, v);
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

}  // namespace

std::string format_poly(const Pslg& pslg, std::string_view header_comment) {
  TextOut out(64 + header_comment.size() + pslg.points.size() * 48 + pslg.segments.size() * 24);
  write_comment(out, header_comment);
  write_points(out, pslg);
  write_segments(out, pslg);
  write_holes_and_regions(out, pslg);
  return out.take();
}

}  // namespace madd
