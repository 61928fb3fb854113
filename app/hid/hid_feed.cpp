#include "app/hid/hid_feed.h"

#include <thread>

namespace mtcut::app::hid {

HidFeed::HidFeed(const Profile& profile, const std::vector<Sample>& samples, const DecodeCounts& counts)
    : path_(initial_pose(profile)) {
  take(samples);
  replay_status_.samples = static_cast<long>(samples.size());
  replay_status_.counts = counts;
}

HidFeed::HidFeed(InputThread& input, double lookahead_seconds)
    : input_(&input), lookahead_(lookahead_seconds), path_(initial_pose(input.profile())) {}

void HidFeed::take(const std::vector<Sample>& samples) {
  for (const Sample& s : samples) {
    path_.add(s);
    pending_us_.push_back(s.time_us);
  }
  samples_ += static_cast<long>(samples.size());
}

double HidFeed::clock() const {
  if (!input_) return 0.0;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - input_->epoch()).count();
}

std::vector<sim::ScalpelKeyframe> HidFeed::frame_samples(double t) {
  if (input_) {
    const auto due = input_->epoch() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                           std::chrono::duration<double>(t + lookahead_));
    std::this_thread::sleep_until(due);
    take(input_->take_until(std::chrono::steady_clock::now()));
  }
  std::vector<sim::ScalpelKeyframe> samples = path_.samples_between(last_frame_, t);
  last_frame_ = t;
  return samples;
}

void HidFeed::reached(double t, double finished) {
  while (!pending_us_.empty() && static_cast<double>(pending_us_.front()) * 1e-6 <= t) {
    latency_.add(finished - static_cast<double>(pending_us_.front()) * 1e-6);
    pending_us_.pop_front();
  }
}

std::vector<InputEvent> HidFeed::take_events() { return input_ ? input_->take_events() : std::vector<InputEvent>{}; }

InputStatus HidFeed::status() const { return input_ ? input_->status() : replay_status_; }

}  // namespace mtcut::app::hid
