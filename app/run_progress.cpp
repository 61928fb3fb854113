#include "app/run_progress.h"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace mtcut::app {

ProgressBar::ProgressBar(std::int64_t total, bool wanted)
    : total_(total), enabled_(wanted && total > 0 && ::isatty(STDERR_FILENO) == 1) {}

void ProgressBar::update(std::int64_t done, double frame_ms) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  constexpr int kWidth = 30;
  const auto filled = static_cast<int>(kWidth * done / total_);
  const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                          std::string(static_cast<std::size_t>(kWidth - filled), '.');
  std::fprintf(stderr, "\r[%s] frame %lld/%lld  %.1f ms/frame\x1b[K", bar.c_str(), static_cast<long long>(done),
               static_cast<long long>(total_), frame_ms);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\x1b[K");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace mtcut::app
