// madd_bench number_format [COUNT]: nanoseconds per double of append_g17
// (src/kernel/number_format.cpp) against std::to_chars(general, 17), the
// same bytes, on mesh-like coordinates (uniform in [-10, 10], fixed seed)
// and on random bit patterns; medians of 5 alternating runs.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "bench.hpp"
#include "kernel/number_format.hpp"

namespace {

double per_value_ns(const std::vector<double>& values, bool fast, std::size_t& bytes) {
  std::string out;
  out.reserve(values.size() * 25);
  const double t0 = madd::bench::now_seconds();
  for (const double v : values) {
    if (fast) {
      madd::detail::append_g17(out, v);
    } else {
      char buffer[32];
      out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, 17).ptr);
    }
    out += ' ';
  }
  const double seconds = madd::bench::now_seconds() - t0;
  bytes = out.size();
  return seconds * 1e9 / static_cast<double>(values.size());
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int run_number_format(int argc, char** argv) {
  const std::size_t count = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 2'000'000;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  std::vector<double> coordinates(count), patterns(count);
  for (double& v : coordinates) v = coordinate(random);
  for (double& v : patterns) v = std::bit_cast<double>(random());
  std::printf("number_format: %zu doubles, ns a double (median of 5 alternating runs)\n", count);
  for (const auto& [name, values] :
       {std::pair{"coordinates in [-10, 10]", &coordinates}, std::pair{"random bits", &patterns}}) {
    std::vector<double> fast, reference;
    std::size_t fast_bytes = 0, reference_bytes = 0;
    for (int r = 0; r < 5; ++r) {
      fast.push_back(per_value_ns(*values, true, fast_bytes));
      reference.push_back(per_value_ns(*values, false, reference_bytes));
    }
    std::printf("  %-26s append_g17 %6.1f   to_chars(general, 17) %6.1f   (%s bytes)\n", name, median(fast),
                median(reference), fast_bytes == reference_bytes ? "same" : "DIFFERENT");
  }
  return 0;
}

const madd::bench::Registration registration("number_format", run_number_format);

}  // namespace
