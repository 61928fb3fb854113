#include "app/hid/hid_path.h"

#include <algorithm>

#include "app/hid/pose_mapper.h"

namespace mtcut::app::hid {

HidPath::HidPath(const sim::ScalpelPose& initial) { keys_.push_back({0.0, initial}); }

void HidPath::add(const Sample& sample) {
  const sim::ScalpelKeyframe key{static_cast<double>(sample.time_us) * 1e-6, sample.pose};
  if (sample.time_us <= last_us_) {
    keys_.back().pose = sample.pose;  // the same microsecond (or the initial key at 0)
    return;
  }
  keys_.push_back(key);
  last_us_ = sample.time_us;
}

void HidPath::forget_before(double t) {
  // Keep one key before the last key at or before t: ScalpelPath then takes
  // the same branch and the same pair of keys as over the whole path.
  while (keys_.size() >= 3 && keys_[2].time <= t) keys_.pop_front();
}

// The keys up to the first one after t: all ScalpelPath needs for times up to t.
sim::ScalpelPath HidPath::path_until(double t) const {
  const auto after = std::upper_bound(keys_.begin(), keys_.end(), t,
                                      [](double time, const sim::ScalpelKeyframe& k) { return time < k.time; });
  const auto end = after == keys_.end() ? after : after + 1;
  return sim::ScalpelPath(std::vector<sim::ScalpelKeyframe>(keys_.begin(), end));
}

sim::ScalpelPose HidPath::pose_at(double t) {
  forget_before(t);
  return path_until(t).pose_at(t);
}

std::vector<sim::ScalpelKeyframe> HidPath::samples_between(double after, double t) {
  // Only keys up to `after` are forgotten: those in (after, t] are the frame's.
  forget_before(after);
  return path_until(t).samples_between(after, t);
}

sim::ScalpelPose initial_pose(const Profile& profile) { return PoseMapper(profile).pose(); }

std::vector<sim::ScalpelKeyframe> to_keyframes(const Profile& profile, std::span<const Sample> samples) {
  HidPath path(initial_pose(profile));
  for (const Sample& s : samples) path.add(s);
  return path.keyframes();
}

}  // namespace mtcut::app::hid
