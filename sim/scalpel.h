#pragma once
// The scalpel: a blade segment (base to tip) that cuts while engaged and
// pushes tissue (a capsule) while not. Scripted runs drive it by keyframes.

#include <span>
#include <vector>

#include "engine/predicates.h"

namespace mtcut::sim {

using engine::Vec3;

struct ScalpelPose {
  Vec3 base = Vec3::Zero();  // where the blade meets the handle, m
  Vec3 tip = Vec3::Zero();   // the blade's point, m
  bool engaged = false;      // cutting (true) or only touching (false)
};

struct ScalpelKeyframe {
  double time = 0;  // s
  ScalpelPose pose;
};

// Keyframes linearly interpolated in time (engaged follows the earlier
// keyframe); before the first and after the last, the end poses hold.
class ScalpelPath {
 public:
  ScalpelPath() = default;
  // Keyframes must be non-empty with strictly increasing times (checked by the scenario reader).
  explicit ScalpelPath(std::vector<ScalpelKeyframe> keyframes) : keys_(std::move(keyframes)) {}

  ScalpelPose pose_at(double time) const;
  // The samples of a frame at `time` on a sampled path (a replayed trace):
  // the keyframes with times in (after, time], in order, then the pose at
  // `time` as a sample at `time` (unless the last keyframe is at `time`,
  // whose pose it is). Times strictly increase; never empty. The first
  // frame passes after = -infinity.
  std::vector<ScalpelKeyframe> samples_between(double after, double time) const;
  bool empty() const { return keys_.empty(); }
  double end_time() const { return keys_.empty() ? 0.0 : keys_.back().time; }
  const std::vector<ScalpelKeyframe>& keyframes() const { return keys_; }

 private:
  std::vector<ScalpelKeyframe> keys_;
};

// The poses of samples, in their order (what World::step takes).
std::vector<ScalpelPose> poses_of(std::span<const ScalpelKeyframe> samples);

}  // namespace mtcut::sim
