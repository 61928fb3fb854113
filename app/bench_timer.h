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

}  // namespace mtcut::app
