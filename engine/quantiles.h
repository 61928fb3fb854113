#pragma once
// Order statistics the benches and run reports share: the median of a few
// timed runs, and nearest-rank percentiles of a series.

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace mtcut::engine {

// The median (the mean of the middle two for an even count; 0 when empty).
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The nearest-rank percentile q in [0, 1] of sorted, non-empty values: the
// value of rank ceil(q n) (the smallest, for q = 0), always one of them.
template <class T>
T nearest_rank(std::span<const T> sorted, double q) {
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

}  // namespace mtcut::engine
