#include "sim/scalpel.h"

#include <algorithm>

namespace mtcut::sim {

ScalpelPose ScalpelPath::pose_at(double time) const {
  if (keys_.empty()) return {};
  if (time <= keys_.front().time) return keys_.front().pose;
  if (time >= keys_.back().time) return keys_.back().pose;
  const auto next = std::upper_bound(keys_.begin(), keys_.end(), time,
                                     [](double t, const ScalpelKeyframe& k) { return t < k.time; });
  const ScalpelKeyframe& b = *next;
  const ScalpelKeyframe& a = *(next - 1);
  const double s = (time - a.time) / (b.time - a.time);
  ScalpelPose pose;
  pose.base = (1 - s) * a.pose.base + s * b.pose.base;
  pose.tip = (1 - s) * a.pose.tip + s * b.pose.tip;
  pose.engaged = a.pose.engaged;
  return pose;
}

std::vector<ScalpelKeyframe> ScalpelPath::samples_between(double after, double time) const {
  std::vector<ScalpelKeyframe> out;
  const auto by_time = [](double t, const ScalpelKeyframe& k) { return t < k.time; };
  const auto first = std::upper_bound(keys_.begin(), keys_.end(), after, by_time);
  const auto last = std::upper_bound(first, keys_.end(), time, by_time);
  out.assign(first, last);
  if (out.empty() || out.back().time != time) out.push_back({time, pose_at(time)});
  return out;
}

std::vector<ScalpelPose> poses_of(std::span<const ScalpelKeyframe> samples) {
  std::vector<ScalpelPose> poses;
  poses.reserve(samples.size());
  for (const ScalpelKeyframe& s : samples) poses.push_back(s.pose);
  return poses;
}

}  // namespace mtcut::sim
