#pragma once
// Benchmark timing: warm up, then time several batches and keep the median,
// as every `mtcut bench` figure is reported.

#include <algorithm>
#include <chrono>
#include <functional>
#include <utility>
#include <vector>

#include "engine/stopwatch.h"

namespace mtcut::app {

struct BatchTiming {
  double median_seconds = 0;  // per batch
  double min_seconds = 0;
  double max_seconds = 0;
  int batches = 0;
};

// The seconds one run of `batch` took.
inline double time_once(const std::function<void()>& batch) {
  const auto start = std::chrono::steady_clock::now();
  batch();
  return engine::seconds_since(start);
}

// Median, min and max of one timing per batch.
inline BatchTiming summarize(std::vector<double> seconds) {
  std::sort(seconds.begin(), seconds.end());
  return {seconds[seconds.size() / 2], seconds.front(), seconds.back(), static_cast<int>(seconds.size())};
}

// Runs `batch` once to warm up, then `batches` times, timing each.
inline BatchTiming time_batches(int batches, const std::function<void()>& batch) {
  batch();
  std::vector<double> seconds;
  for (int i = 0; i < batches; ++i) seconds.push_back(time_once(batch));
  return summarize(std::move(seconds));
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
  for (int i = 0; i < batches; ++i) {
    sa.push_back(time_once(a));
    sb.push_back(time_once(b));
    ratio.push_back(sa.back() / sb.back());
  }
  return {summarize(std::move(sa)), summarize(std::move(sb)), summarize(std::move(ratio)).median_seconds};
}

}  // namespace mtcut::app
