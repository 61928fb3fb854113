#include "app/hid/hid_feed.h"

#include <cmath>

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

double HidFeed::clock() const { return input_ ? 1e-6 * static_cast<double>(input_->now_us()) : 0.0; }

std::vector<sim::ScalpelKeyframe> HidFeed::frame_samples(double t) {
  if (input_) {
    input_->wait_until_us(static_cast<std::int64_t>(std::ceil((t + lookahead_) * 1e6)));
    take(input_->take_until_us(input_->now_us()));
  }
  std::vector<sim::ScalpelKeyframe> samples = path_.samples_between(last_frame_, t);
  last_frame_ = t;
  return samples;
}

std::optional<sim::ScalpelPose> HidFeed::start_pose() const {
  if (input_) return std::nullopt;
  HidPath path = path_;  // pose_at forgets what lies before its time
  return path.pose_at(0.0);
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
