#include "app/view/step_clock.h"

#include <algorithm>
#include <cmath>

namespace mtcut::app::view {

int StepClock::advance(double elapsed) {
  accumulated_ += std::max(elapsed, 0.0);
  const double due = std::floor(accumulated_ / dt_);
  const int run = static_cast<int>(std::min(due, static_cast<double>(max_steps_)));
  accumulated_ -= run * dt_;
  if (due > max_steps_) {
    dropped_ += static_cast<std::uint64_t>(due) - static_cast<std::uint64_t>(max_steps_);
    accumulated_ = std::fmod(accumulated_, dt_);
  }
  steps_ += static_cast<std::uint64_t>(run);
  return run;
}

}  // namespace mtcut::app::view
