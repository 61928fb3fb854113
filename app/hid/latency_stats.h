#pragma once
// Sample-to-cut latency: from the moment a HID report arrived to the end of
// the World step whose time has passed it (the first frame that carries the
// sample's pose). Keeps the last `window` values for the median.

#include <cstddef>
#include <vector>

namespace mtcut::app::hid {

struct LatencySummary {
  long count = 0;        // samples that reached the World
  double median_ms = 0;  // over the last window
  double max_ms = 0;     // over all
  double last_ms = 0;
};

class LatencyStats {
 public:
  explicit LatencyStats(std::size_t window = 1024) : window_(window) {}
  void add(double seconds);
  LatencySummary summary() const;

 private:
  std::size_t window_;
  std::vector<double> recent_;  // (<= window) ms, a ring
  std::size_t next_ = 0;        // where the next value goes once the ring is full
  LatencySummary totals_;
};

}  // namespace mtcut::app::hid
