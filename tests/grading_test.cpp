// Graded decompositions (paper Sec. 5.2): density weights from a function,
// background points or boundary weights, and required areas. Every test also
// checks validity (verify_decomposition) and C1 (min new angle >= Phi0).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"

namespace {

using madd::Decomposition;
using madd::Point;
using madd::Pslg;

// The rectangle [0, w] x [0, h] with `per_unit` boundary points per unit length,
// one attribute per point (its weight, 0 here).
Pslg rectangle(double w, double h, int per_unit = 1) {
  Pslg p;
  p.first_index = 0;
  const Point corners[4] = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  for (int c = 0; c < 4; ++c) {
    const Point a = corners[c], b = corners[(c + 1) % 4];
    const int n = std::max(1, static_cast<int>(std::lround(std::hypot(b.x - a.x, b.y - a.y) * per_unit)));
    for (int k = 0; k < n; ++k) p.points.push_back({a.x + (b.x - a.x) * k / n, a.y + (b.y - a.y) * k / n});
  }
  const auto n = static_cast<std::uint32_t>(p.points.size());
  for (std::uint32_t i = 0; i < n; ++i) p.segments.push_back({i, (i + 1) % n, 0});
  p.attributes_per_point = 1;
  p.attributes.assign(n, 0.0);
  return p;
}

Point centroid(const Decomposition& d, const std::vector<std::uint32_t>& ring) {
  double cx = 0, cy = 0, twice = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point a = d.points[ring[k]], b = d.points[ring[(k + 1) % ring.size()]];
    const double c = a.x * b.y - a.y * b.x;
    twice += c;
    cx += (a.x + b.x) * c;
    cy += (a.y + b.y) * c;
  }
  return {cx / (3 * twice), cy / (3 * twice)};
}

bool inside_ring(const Decomposition& d, const std::vector<std::uint32_t>& ring, Point p) {
  bool in = false;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point a = d.points[ring[k]], b = d.points[ring[(k + 1) % ring.size()]];
    if ((a.y > p.y) != (b.y > p.y) && a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) > p.x) in = !in;
  }
  return in;
}

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size(); ++i) r[order[i]] = static_cast<double>(i);
  return r;
}

// Spearman rank correlation (no ties expected in continuous data).
double spearman(const std::vector<double>& a, const std::vector<double>& b) {
  const auto ra = ranks(a), rb = ranks(b);
  const double n = static_cast<double>(a.size());
  double d2 = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d2 += (ra[i] - rb[i]) * (ra[i] - rb[i]);
  return 1.0 - 6.0 * d2 / (n * (n * n - 1.0));
}

double x_area_correlation(const Decomposition& d) {
  std::vector<double> x, area;
  for (const auto& s : d.subdomains) {
    x.push_back(s.interior_point.x);
    area.push_back(s.area);
  }
  return spearman(x, area);
}

// Validity and C1 for every graded run; returns the decomposition.
Decomposition checked(const Pslg& domain, const madd::DecomposeOptions& o, std::uint32_t expected) {
  const Decomposition d = madd::decompose(domain, o);
  const auto made = static_cast<std::uint32_t>(d.subdomains.size());
  const madd::Verification v = madd::verify_decomposition(d, domain, expected == 0 ? made : expected);
  for (const auto& p : v.problems) INFO(p);
  CHECK(v.ok());
  CHECK(madd::metrics(d).angle_min >= o.separator_angle_deg);
  return d;
}

}  // namespace

TEST_SUITE("grading") {

TEST_CASE("weight function proportional to x: subdomains shrink as x grows") {
  const Pslg domain = rectangle(4, 1);
  madd::DecomposeOptions o;
  o.subdomains = 64;
  o.weight_function = [](double x, double) { return x; };
  const Decomposition d = checked(domain, o, 64);
  CHECK(x_area_correlation(d) < -0.5);
  madd::DecomposeOptions uniform = o;
  uniform.weight_function = nullptr;
  CHECK(madd::metrics(checked(domain, uniform, 64)).max_area_over_mean < madd::metrics(d).max_area_over_mean);
  // The density weights (not the areas) are balanced.
  CHECK(madd::metrics(d).max_weight_over_mean < madd::metrics(d).max_area_over_mean);
}

TEST_CASE("area function: no subdomain exceeds its required area times the bound") {
  const Pslg domain = rectangle(4, 1);
  madd::DecomposeOptions o;
  o.subdomains = 1000;  // a maximum: the bound stops the splitting first
  o.subdomain_area_function = [](double x, double) { return 0.02 + 0.03 * x; };
  o.subdomain_area_ratio = 1.0;
  const Decomposition d = checked(domain, o, 0);
  CHECK(d.subdomains.size() > 10);
  CHECK(d.subdomains.size() < 1000);
  for (const auto& s : d.subdomains) {
    // The function is linear: its largest value over a subdomain is at a
    // vertex, and the required area (a minimum inside) is no larger.
    double most = 0;
    for (std::uint32_t v : s.rings[0]) most = std::max(most, 0.02 + 0.03 * d.points[v].x);
    CHECK(s.area <= o.subdomain_area_ratio * most * (1 + 1e-9));
  }
  CHECK(x_area_correlation(d) > 0.5);
}

TEST_CASE("area function respects the maximum count") {
  madd::DecomposeOptions o;
  o.subdomains = 7;
  o.subdomain_area_function = [](double, double) { return 1e-4; };
  const Decomposition d = checked(rectangle(4, 1), o, 7);
  CHECK(d.subdomains.size() == 7);
}

TEST_CASE("boundary weights concentrate subdomains near the weighted vertices") {
  Pslg domain = rectangle(4, 1, 4);
  std::vector<Point> weighted;
  for (std::size_t i = 0; i < domain.points.size(); ++i) {
    if (domain.points[i].x < 0.6) {
      domain.attributes[i] = 1.0;
      weighted.push_back(domain.points[i]);
    }
  }
  madd::DecomposeOptions o;
  o.subdomains = 32;
  o.gradation = 3.0;
  o.interpolation = 0.5;
  auto mean_distance = [&](const Decomposition& d) {
    double total = 0;
    for (const auto& s : d.subdomains) {
      const Point c = centroid(d, s.rings[0]);
      double best = INFINITY;
      for (Point w : weighted) best = std::min(best, std::hypot(c.x - w.x, c.y - w.y));
      total += best;
    }
    return total / static_cast<double>(d.subdomains.size());
  };
  const double graded = mean_distance(checked(domain, o, 32));
  madd::DecomposeOptions uniform = o;
  uniform.gradation = 0;
  uniform.interpolation = 0;  // nothing to interpolate without boundary weights
  const double plain = mean_distance(checked(domain, uniform, 32));
  INFO("graded " << graded << ", uniform " << plain);
  CHECK(graded < 0.8 * plain);
}

TEST_CASE("boundary weights: a subdomain weighs r * area + a * its boundary vertex weights (p = 0)") {
  Pslg domain = rectangle(4, 1, 3);
  for (std::size_t i = 0; i < domain.points.size(); ++i) domain.attributes[i] = 1.0 + domain.points[i].x;
  madd::DecomposeOptions o;
  o.subdomains = 12;
  o.gradation = 0.5;
  o.interpolation = 0.0;  // new separator points weigh nothing
  const Decomposition d = checked(domain, o, 12);
  for (const auto& s : d.subdomains) {
    double w = 0;
    for (const auto& ring : s.rings) {
      for (std::uint32_t v : ring) w += v < domain.points.size() ? domain.attributes[v] : 0.0;
    }
    CHECK(s.weight == doctest::Approx(o.boundary_refinement * s.area + o.gradation * w).epsilon(1e-9));
  }
}

TEST_CASE("background weights and areas") {
  const Pslg domain = rectangle(4, 1);
  madd::DecomposeOptions o;
  for (int i = 0; i < 80; ++i) {
    for (int j = 0; j < 20; ++j) {
      const Point p{(i + 0.5) / 20.0, (j + 0.5) / 20.0};
      o.weight_samples.push_back({p, p.x});
    }
  }
  o.subdomains = 64;
  const Decomposition d = checked(domain, o, 64);
  CHECK(x_area_correlation(d) < -0.5);

  madd::DecomposeOptions a;
  a.subdomains = 1000;
  for (const auto& p : o.weight_samples) a.subdomain_area_samples.push_back({p.at, 0.02 + 0.03 * p.at.x});
  const Decomposition da = checked(domain, a, 0);
  CHECK(da.subdomains.size() > 10);
  for (const auto& s : da.subdomains) {
    double least = INFINITY;
    for (const auto& p : a.subdomain_area_samples) {
      if (inside_ring(da, s.rings[0], p.at)) least = std::min(least, p.value);
    }
    if (std::isfinite(least)) CHECK(s.area <= a.subdomain_area_ratio * least * (1 + 1e-9));
  }
  CHECK(x_area_correlation(da) > 0.5);
}

TEST_CASE("graded output is identical for 1 and 2 threads") {
  Pslg domain = rectangle(4, 1, 4);
  for (std::size_t i = 0; i < domain.points.size(); ++i) domain.attributes[i] = domain.points[i].x;
  madd::DecomposeOptions variants[4];
  variants[0].weight_function = [](double x, double y) { return 1 + x * y; };
  variants[1].subdomain_area_function = [](double x, double) { return 0.01 + 0.02 * x; };
  variants[2].gradation = 2;
  variants[2].interpolation = 0.5;
  variants[3].weight_samples = {{{0.5, 0.5}, 10}, {{3.5, 0.2}, 1}, {{2, 0.7}, 4}};
  for (auto& o : variants) {
    o.subdomains = 40;
    o.threads = 1;
    const Decomposition one = checked(domain, o, 0);
    o.threads = 2;
    const Decomposition two = madd::decompose(domain, o);
    CHECK(one == two);
  }
}

}  // TEST_SUITE("grading")

// DecomposeOptions::face_work: in a run graded by weight samples, the repair
// balances what it says, not the samples (madd mesh sets it to each face's
// expected triangles). A face_work that calls every face equal leaves
// nothing to repair; each face it is given is that face as a domain of its
// own, separators marked 0 and the boundary 1, its area that of a face.
TEST_CASE("face_work: the repair balances it, reading each face as a domain of its own") {
  const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/comb.poly");
  madd::DecomposeOptions o;
  o.subdomains = 16;
  o.threads = 1;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j)
      o.weight_samples.push_back({{(i + 0.5) * 11.8 / 60.0, -12.0 + (j + 0.5) * 13.0 / 60.0}, 1.0 + i / 60.0});
  o.gradation = 100.0;
  o.repair_balance_above = 1.05;
  madd::DecomposeOptions off = o;
  off.repair_balance_above = 0.0;
  const Decomposition unrepaired = madd::decompose(domain, off);
  REQUIRE(madd::decompose(domain, o) != unrepaired);  // the samples' repair changes something here
  madd::DecomposeOptions flat = o;
  std::vector<Pslg> faces;
  flat.face_work = [&](const Pslg& face) {
    faces.push_back(face);
    return 1.0;
  };
  CHECK(madd::decompose(domain, flat) == unrepaired);
  REQUIRE(faces.size() == 16);  // each face read once
  // The faces tile the domain; the pieces marked as boundary add up to its
  // boundary, each piece in one face (the separators, marked 0, in two).
  const auto length = [](const Pslg& p, bool boundary) {
    double total = 0.0;
    for (const madd::Segment& s : p.segments)
      if ((s.marker != 0) == boundary)
        total += std::hypot(p.points[s.b].x - p.points[s.a].x, p.points[s.b].y - p.points[s.a].y);
    return total;
  };
  double area = 0.0, boundary = 0.0, separators = 0.0;
  for (const Pslg& face : faces) {
    CHECK_NOTHROW(madd::validate(face));
    area += madd::domain_area(face);
    boundary += length(face, true);
    separators += length(face, false);
  }
  Pslg unmarked = domain;
  for (madd::Segment& s : unmarked.segments) s.marker = 1;
  CHECK(area == doctest::Approx(madd::domain_area(domain)).epsilon(1e-9));
  CHECK(boundary == doctest::Approx(length(unmarked, true)).epsilon(1e-9));
  CHECK(separators == doctest::Approx(2.0 * madd::metrics(unrepaired).separator_length).epsilon(1e-9));
}

namespace {
// Whether q is inside `face` (a crossing number over its segments), as
// face_work reads the faces it is given.
bool inside_face(const Pslg& face, Point q) {
  bool inside = false;
  for (const madd::Segment& s : face.segments) {
    const Point u = face.points[s.a], w = face.points[s.b];
    if ((u.y > q.y) != (w.y > q.y) && q.x < u.x + (q.y - u.y) * (w.x - u.x) / (w.y - u.y)) inside = !inside;
  }
  return inside;
}

// A `width` x 1 rectangle in 8 subdomains, graded by weight samples that
// weigh 1 a unit of area everywhere, repaired above 1.1 x the mean by a
// face_work that counts `density` (on its own fine grid): the largest
// subdomain's work by that count over the mean.
template <typename Density>
double largest_by_face_work(int width, Density density) {
  std::vector<madd::ValuedPoint> hidden;
  double total = 0.0;
  for (int i = 0; i < 100 * width; ++i)
    for (int j = 0; j < 100; ++j) {
      const Point p{(i + 0.5) / 100.0, (j + 0.5) / 100.0};
      hidden.push_back({p, density(p) * 1e-4});
      total += hidden.back().value;
    }
  madd::DecomposeOptions o;
  o.subdomains = 8;
  o.threads = 1;
  for (int i = 0; i < 20 * width; ++i)
    for (int j = 0; j < 20; ++j) o.weight_samples.push_back({{(i + 0.5) / 20.0, (j + 0.5) / 20.0}, 1.0});
  o.gradation = 100.0;
  o.repair_balance_above = 1.1;
  o.face_work = [&](const Pslg& face) {
    double work = 0.0;
    for (const madd::ValuedPoint& h : hidden)
      if (inside_face(face, h.at)) work += h.value;
    return work;
  };
  const Decomposition d = checked(rectangle(width, 1, 8), o, 8);
  double largest = 0.0;
  for (const auto& s : d.subdomains) {
    double work = 0.0;
    for (const madd::ValuedPoint& h : hidden)
      if (inside_ring(d, s.rings[0], h.at)) work += h.value;
    largest = std::max(largest, work);
  }
  return largest / (total / 8.0);
}
}  // namespace

// The repair's splits follow the samples, recalibrated per face to what
// face_work says: where the two disagree (madd mesh's samples leave out the
// pinches' clusters, and are merged per grid cell), a union split by the
// samples alone was cut where its faces met, and no repair was kept.
TEST_CASE("face_work: the repair's splits follow it where the samples disagree") {
  // face_work counts 1.6 in the eighth x < 0.5 of a 4 x 1 rectangle: split
  // by the samples alone, the subdomain there is 1.49 x the mean, and a
  // repair splitting its unions by them leaves it there (each union cut
  // again where its faces met).
  CHECK(largest_by_face_work(4, [](Point p) { return p.x < 0.5 ? 1.6 : 1.0; }) < 1.15);
}

// A face at the end of a corridor has one neighbour; where the faces next
// to it are as heavy as itself, a union with that neighbour or with it and
// the next takes no weight off it, and the repair also tries a chain of
// three neighbours split in four.
TEST_CASE("face_work: a face at the end of a corridor sheds weight down a chain of its neighbours") {
  // In an 8 x 1 corridor the three unit faces x < 3 weigh 1.5: 1.26 x the
  // mean; without the chain the end one stays there (its neighbour and the
  // next are as heavy: no union of two or three takes weight off it); with
  // it, 1.18.
  CHECK(largest_by_face_work(8, [](Point p) { return p.x < 3.0 ? 1.5 : 1.0; }) < 1.2);
}
