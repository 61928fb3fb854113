#include "app/hid/latency_stats.h"

#include <algorithm>

namespace mtcut::app::hid {

void LatencyStats::add(double seconds) {
  const double ms = 1000.0 * seconds;
  if (recent_.size() < window_) {
    recent_.push_back(ms);
  } else {
    recent_[next_] = ms;
    next_ = (next_ + 1) % window_;
  }
  ++totals_.count;
  totals_.max_ms = std::max(totals_.max_ms, ms);
  totals_.last_ms = ms;
}

LatencySummary LatencyStats::summary() const {
  LatencySummary s = totals_;
  if (recent_.empty()) return s;
  std::vector<double> sorted = recent_;
  const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), mid, sorted.end());
  s.median_ms = *mid;
  return s;
}

}  // namespace mtcut::app::hid
