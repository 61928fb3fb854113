#pragma once
// Benchmark timing: warm up, then time several batches and keep the median,
// as every `mtcut bench` figure is reported.

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace mtcut::app {

struct BatchTiming {
  double median_seconds = 0;  // per batch
  double min_seconds = 0;
  double max_seconds = 0;
  int batches = 0;
};

// Runs `batch` once to warm up, then `batches` times, timing each.
inline BatchTiming time_batches(int batches, const std::function<void()>& batch) {
  batch();
  std::vector<double> seconds;
  for (int i = 0; i < batches; ++i) {
    const auto start = std::chrono::steady_clock::now();
    batch();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return {seconds[seconds.size() / 2], seconds.front(), seconds.back(), batches};
}

// Two batches timed in alternation (a, b, a, b, ... after a warm-up of
// each), for their ratio: on a shared machine the load drifts over seconds,
// and two figures timed one after the other can differ by a tenth for that
// alone. `a_over_b` is the median over rounds of a's time over b's (each
// round's pair sees the same load).
struct PairedTiming {
  BatchTiming a, b;
  double a_over_b = 0;
};

inline PairedTiming time_batch_pair(int batches, const std::function<void()>& a, const std::function<void()>& b) {
  a();
  b();
  std::vector<double> sa, sb, ratio;
  const auto timed = [](const std::function<void()>& batch) {
    const auto start = std::chrono::steady_clock::now();
    batch();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  for (int i = 0; i < batches; ++i) {
    sa.push_back(timed(a));
    sb.push_back(timed(b));
    ratio.push_back(sa.back() / sb.back());
  }
  const auto summary = [batches](std::vector<double> s) {
    std::sort(s.begin(), s.end());
    return BatchTiming{s[s.size() / 2], s.front(), s.back(), batches};
  };
  std::sort(ratio.begin(), ratio.end());
  return {summary(sa), summary(sb), ratio[ratio.size() / 2]};
}

}  // namespace mtcut::app
