#pragma once
// The progress bar of `mtcut run` on stderr, drawn only when stderr is a
// terminal (so logs and pipes stay clean), at most ten times a second.

#include <chrono>
#include <cstdint>

namespace mtcut::app {

class ProgressBar {
 public:
  // `total` frames; `wanted` false draws nothing.
  ProgressBar(std::int64_t total, bool wanted);
  ~ProgressBar() { finish(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // `done` frames finished, the last one took `frame_ms`.
  void update(std::int64_t done, double frame_ms);
  // Erases the bar (idempotent).
  void finish();

 private:
  std::int64_t total_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace mtcut::app
