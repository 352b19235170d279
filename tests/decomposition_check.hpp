#pragma once
// The whole contract of one decomposition, checked from outside: decompose
// on one thread, then verify_decomposition (cover, no overlap, connected,
// conforming, count) and every new angle >= Phi0 (criterion C1).
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "madd/decomposition.hpp"
#include "madd/metrics.hpp"

namespace madd::test {

inline Metrics checked_decomposition(const Pslg& domain, std::uint32_t n, double separator_angle_deg = 60.0) {
  DecomposeOptions options;
  options.subdomains = n;
  options.separator_angle_deg = separator_angle_deg;
  options.threads = 1;
  const Decomposition d = decompose(domain, options);
  const Verification check = verify_decomposition(d, domain, n);
  INFO((check.ok() ? std::string() : check.problems.front()));
  CHECK(check.ok());
  CHECK(d.subdomains.size() == n);
  const Metrics m = metrics(d);
  if (!std::isnan(m.angle_min)) CHECK(m.angle_min >= separator_angle_deg - 1e-9);
  return m;
}

}  // namespace madd::test
