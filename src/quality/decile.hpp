#pragma once
// The deciles quoted by metrics() (docs/quality.md) and the benchmarks.
#include <vector>

namespace madd::detail {

// Quantile q (1..9) of 10 over `sorted` values, Python's "exclusive" method.
// NaN when fewer than two values.
double decile(const std::vector<double>& sorted, int q);

}  // namespace madd::detail
