// Decompose the unit square into 4 subdomains through the public API and check
// the result (also the example of docs/api.md; tests/consumers/run.sh builds it).
#include <madd/madd.hpp>

#include <cmath>
#include <cstdio>

int main() {
  madd::Pslg square;
  square.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  square.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};  // endpoints (0-based) and marker
  try {
    madd::validate(square);  // throws madd::InvalidInputError naming the offending ids
    madd::DecomposeOptions options;
    options.subdomains = 4;
    const madd::Decomposition d = madd::decompose(square, options);
    const madd::Verification check = madd::verify_decomposition(d, square, options.subdomains);
    double area = 0;
    for (const madd::Subdomain& s : d.subdomains) area += s.area;
    std::printf("%zu subdomains, %zu points, area %.17g\n%s", d.subdomains.size(), d.points.size(), area,
                madd::format_geojson(d).c_str());
    return check.ok() && d.subdomains.size() == 4 && std::abs(area - 1.0) < 1e-12 ? 0 : 1;
  } catch (const madd::Error& e) {  // every failure madd reports is a madd::Error
    std::fprintf(stderr, "madd: %s\n", e.what());
    return 1;
  }
}
