// Output 4: an SVG picture of a decomposition. Kept light for 5,000
// subdomains and 50,000 segments: one <path> per subdomain, boundary and
// separators each as one path of chained polylines, two-decimal coordinates.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "madd/error.hpp"
#include "kernel/number_format.hpp"
#include "kernel/rings.hpp"
#include "madd/output.hpp"
#include "quality/metrics_detail.hpp"

namespace madd {

namespace {

// Input coordinates to picture pixels: uniform scale, y flipped, small margin.
struct View {
  double min_x = 0, max_y = 0, scale = 1, margin = 0, width = 0, height = 0;

  View(const std::vector<Point>& points, double pixels) {
    double max_x = 0, min_y = 0;
    if (!points.empty()) {
      min_x = max_x = points[0].x;
      min_y = max_y = points[0].y;
    }
    for (const Point& p : points) {
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
    const double extent = std::max(max_x - min_x, max_y - min_y);
    scale = extent > 0 ? pixels / extent : 1.0;
    margin = 0.02 * pixels;
    width = (max_x - min_x) * scale + 2 * margin;
    height = (max_y - min_y) * scale + 2 * margin;
  }
  double x(double v) const { return margin + (v - min_x) * scale; }
  double y(double v) const { return margin + (max_y - v) * scale; }
};

// Two decimals, trailing zeros dropped: "12.5", "3", "-0.25".
void append_px(std::string& out, double v) {
  const long long hundredths = std::llround(v * 100.0);
  if (hundredths < 0) out += '-';
  const long long a = hundredths < 0 ? -hundredths : hundredths;
  detail::append_int(out, a / 100);
  const long long frac = a % 100;
  if (frac == 0) return;
  out += '.';
  out += static_cast<char>('0' + frac / 10);
  if (frac % 10 != 0) out += static_cast<char>('0' + frac % 10);
}

void append_xy(std::string& out, const View& view, Point p) {
  append_px(out, view.x(p.x));
  out += ' ';
  append_px(out, view.y(p.y));
}

// A pleasant, well-spread fill for subdomain k: golden-ratio hues.
std::string colour(std::size_t k) {
  const double h = std::fmod(static_cast<double>(k) * 0.6180339887498949, 1.0) * 6.0;
  const double s = 0.55, l = 0.72;
  const double c = (1 - std::abs(2 * l - 1)) * s;
  const double x = c * (1 - std::abs(std::fmod(h, 2.0) - 1));
  double r = 0, g = 0, b = 0;
  if (h < 1) {
    r = c;
    g = x;
  } else if (h < 2) {
    r = x;
    g = c;
  } else if (h < 3) {
    g = c;
    b = x;
  } else if (h < 4) {
    g = x;
    b = c;
  } else if (h < 5) {
    r = x;
    b = c;
  } else {
    r = c;
    b = x;
  }
  const double m = l - c / 2;
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", int(std::lround((r + m) * 255)),
                int(std::lround((g + m) * 255)), int(std::lround((b + m) * 255)));
  return buffer;
}

void append_fills(std::string& out, const Decomposition& d, const View& view) {
  out += "<g fill-rule=\"evenodd\" stroke=\"none\">\n";
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    out += "<path fill=\"" + colour(k) + "\" d=\"";
    for (const auto& ring : d.subdomains[k].rings) {
      for (std::size_t j = 0; j < ring.size(); ++j) {
        out += j == 0 ? "M" : (j == 1 ? "L" : " ");
        append_xy(out, view, d.points[ring[j]]);
      }
      out += 'Z';
    }
    out += "\"/>\n";
  }
  out += "</g>\n";
}

// Chains the ring edges into polylines: boundary pieces (each in one ring) and
// separators (walked forward, a->b, by exactly one of their two rings).
void append_edges(std::string& boundary, std::string& separators, const Decomposition& d, const View& view) {
  for (const Subdomain& sub : d.subdomains)
    for (std::size_t r = 0; r < sub.rings.size(); ++r) {
      const auto& ring = sub.rings[r];
      const auto& segs = sub.ring_segments[r];
      const std::size_t n = ring.size();
      const auto kind = [&](std::size_t j) {  // 0 none, 1 boundary, 2 separator drawn here
        const std::uint32_t s = segs[j % n];
        if (!d.is_separator(s)) return 1;
        return d.segments[s].a == ring[j % n] ? 2 : 0;
      };
      std::size_t start = 0;  // begin where the kind changes, so runs do not wrap
      while (start < n && kind(start) == kind(start + n - 1)) ++start;
      if (start == n) start = 0;
      int previous = -1;
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = start + i;
        const int k = kind(j);
        if (k != 0) {
          std::string& out = k == 1 ? boundary : separators;
          if (k != previous) {
            out += 'M';
            append_xy(out, view, d.points[ring[j % n]]);
            out += 'L';
          } else {
            out += ' ';
          }
          append_xy(out, view, d.points[ring[(j + 1) % n]]);
        }
        previous = k;
      }
    }
}

// The interior segments as one path, a piece that starts where the last one
// ended continuing its polyline (the pieces of an input polyline come in order).
std::string interior_path(const Decomposition& d, const View& view) {
  std::string out;
  std::uint32_t end = no_index;
  for (const Subdomain& sub : d.subdomains)
    for (const std::uint32_t j : sub.interior_segments) {
      const Segment& s = d.segments[j];
      const bool forward = s.a == end, backward = !forward && s.b == end;
      if (!forward && !backward) {
        out += 'M';
        append_xy(out, view, d.points[s.a]);
        out += 'L';
        end = s.a;
      } else {
        out += ' ';
      }
      end = end == s.a ? s.b : s.a;
      append_xy(out, view, d.points[end]);
    }
  return out;
}

// Interior segments dashed in dark blue over the edges (a colour no fill
// has: the fills are light), isolated points as dots of the same colour;
// both sized like the boundary line, `thick`.
void append_interior(std::string& out, const Decomposition& d, const View& view, double thick) {
  const std::string path = interior_path(d, view);
  if (!path.empty()) {
    out += "<path fill=\"none\" stroke=\"#0a2f8c\" stroke-width=\"";
    append_px(out, thick);
    out += "\" stroke-dasharray=\"";
    append_px(out, 4 * thick);
    out += ' ';
    append_px(out, 2 * thick);
    out += "\" stroke-linejoin=\"round\" d=\"" + path + "\"/>\n";
  }
  bool any = false;
  for (const Subdomain& sub : d.subdomains)
    for (const std::uint32_t p : sub.interior_points) {
      if (!any) {
        out += "<g fill=\"#0a2f8c\" stroke=\"none\">\n";
      }
      any = true;
      out += "<circle cx=\"";
      append_px(out, view.x(d.points[p].x));
      out += "\" cy=\"";
      append_px(out, view.y(d.points[p].y));
      out += "\" r=\"";
      append_px(out, 3 * thick);
      out += "\"/>\n";
    }
  if (any) out += "</g>\n";
}

// Where to write subdomain k's number: its area centroid when that lies
// strictly inside it (it looks centred), otherwise its interior point.
Point label_point(const Decomposition& d, const Subdomain& sub) {
  if (sub.rings.empty() || sub.rings[0].empty()) return sub.interior_point;
  double twice = 0.0, cx = 0.0, cy = 0.0;
  const Point o = d.points[sub.rings[0][0]];
  for (const auto& ring : sub.rings)
    for (std::size_t j = 0; j < ring.size(); ++j) {
      const Point a = d.points[ring[j]] - o, b = d.points[ring[(j + 1) % ring.size()]] - o;
      const double c = cross(a, b);
      twice += c;
      cx += (a.x + b.x) * c;
      cy += (a.y + b.y) * c;
    }
  if (twice == 0.0) return sub.interior_point;
  const Point centroid{o.x + cx / (3.0 * twice), o.y + cy / (3.0 * twice)};
  using detail::RingLocation, detail::RingView;
  bool inside = detail::locate_in_ring(RingView(d.points, sub.rings[0]), centroid) == RingLocation::inside;
  for (std::size_t r = 1; r < sub.rings.size() && inside; ++r)
    inside = detail::locate_in_ring(RingView(d.points, sub.rings[r]), centroid) == RingLocation::outside;
  return inside ? centroid : sub.interior_point;
}

void append_annotations(std::string& out, const Decomposition& d, const View& view, const SvgOptions& options) {
  if (options.numbers && !d.subdomains.empty()) {
    const double area = [&] {
      double a = 0;
      for (const Subdomain& s : d.subdomains) a += std::abs(s.area);
      return a / static_cast<double>(d.subdomains.size());
    }();
    const double size = std::clamp(0.3 * std::sqrt(area) * view.scale, 3.0, 40.0);
    out += "<g font-family=\"sans-serif\" text-anchor=\"middle\" dominant-baseline=\"central\" font-size=\"";
    append_px(out, size);
    out += "\" fill=\"#222\">\n";
    for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
      const Point at = label_point(d, d.subdomains[k]);
      out += "<text x=\"";
      append_px(out, view.x(at.x));
      out += "\" y=\"";
      append_px(out, view.y(at.y));
      out += "\">" + std::to_string(k) + "</text>\n";
    }
    out += "</g>\n";
  }
  if (options.mark_angles_below_deg > 0) {
    out += "<g fill=\"none\" stroke=\"#d00\" stroke-width=\"1.5\">\n";
    detail::for_each_new_angle(d, [&](std::uint32_t s, std::uint32_t r, std::uint32_t k, double angle) {
      if (angle >= options.mark_angles_below_deg) return;
      const Point p = d.points[d.subdomains[s].rings[r][k]];
      out += "<circle cx=\"";
      append_px(out, view.x(p.x));
      out += "\" cy=\"";
      append_px(out, view.y(p.y));
      out += "\" r=\"5\"/>\n";
    });
    out += "</g>\n";
  }
}

}  // namespace

void check_options(const SvgOptions& options) {
  if (!(std::isfinite(options.width) && options.width >= 0.0 && options.width <= 1e6))
    throw OptionError("width", "must lie in [0, 1e6] pixels (0 = the default 1000)");
  if (!(options.mark_angles_below_deg >= 0.0 && options.mark_angles_below_deg <= 180.0))
    throw OptionError("mark_angles_below_deg", "must lie in [0, 180] degrees (0 = none)");
}

std::string format_svg(const Decomposition& d, const SvgOptions& options) {
  check_options(options);
  const View view(d.points, options.width > 0 ? options.width : 1000.0);
  std::string out;
  out.reserve(40 * (d.points.size() + 3 * d.segments.size()) + 1024);
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  append_px(out, view.width);
  out += "\" height=\"";
  append_px(out, view.height);
  out += "\" viewBox=\"0 0 ";
  append_px(out, view.width);
  out += ' ';
  append_px(out, view.height);
  out += "\">\n<title>madd decomposition: " + std::to_string(d.subdomains.size()) + " subdomains</title>\n";
  append_fills(out, d, view);
  std::string boundary, separators;
  append_edges(boundary, separators, d, view);
  const double thick = std::max(1.5, 0.002 * view.width);
  out += "<g fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  out += "<path stroke=\"#333\" stroke-width=\"0.8\" d=\"" + separators + "\"/>\n";
  out += "<path stroke=\"#000\" stroke-width=\"";
  append_px(out, thick);
  out += "\" d=\"" + boundary + "\"/>\n</g>\n";
  append_interior(out, d, view, thick);
  append_annotations(out, d, view, options);
  out += "</svg>\n";
  return out;
}

}  // namespace madd
