#pragma once
// The scalpel path a HID stroke draws: the decoded samples as keyframes on
// the input's own clock (seconds since its epoch: the start of the run, or of
// the recording), linear in between, starting with the decoder's pose before
// any report at time 0. A live frame loop, a replayed recording and the
// scalpel trace `mtcut hid convert` writes all follow this one path, so a
// replay and its trace give the World the very same poses: each frame, the
// keyframes since the last frame and the pose at the frame's time.
//
// Kept incrementally for a live run: pose_at() and samples_between() forget
// the keyframes no later call can need (times asked for never go back), and
// evaluate sim::ScalpelPath on the few that remain, which gives bit for bit
// what ScalpelPath gives over every keyframe.

#include <deque>
#include <span>
#include <vector>

#include "app/hid/profile.h"
#include "app/hid/sample.h"
#include "sim/scalpel.h"

namespace mtcut::app::hid {

class HidPath {
 public:
  // The path at rest in `initial` from time 0.
  explicit HidPath(const sim::ScalpelPose& initial);

  // Appends a sample (time order); of several samples in one microsecond the last wins.
  void add(const Sample& sample);
  // The pose at `t` seconds; `t` must not decrease from call to call.
  sim::ScalpelPose pose_at(double t);
  // The samples of the frame at `t` after the one at `after` (-infinity for
  // the first): what sim::ScalpelPath::samples_between gives over the whole
  // path, bit for bit. `after` must not be before a time asked for earlier.
  std::vector<sim::ScalpelKeyframe> samples_between(double after, double t);
  // The keyframes not forgotten yet (all of them before the first pose_at).
  std::vector<sim::ScalpelKeyframe> keyframes() const { return {keys_.begin(), keys_.end()}; }

 private:
  // Forgets the keys no call at `t` or later needs.
  void forget_before(double t);
  // The keys up to the first one after t, as a path (all it needs up to t).
  sim::ScalpelPath path_until(double t) const;

  std::deque<sim::ScalpelKeyframe> keys_;  // strictly increasing times
  std::int64_t last_us_ = 0;               // time of the last key, microseconds
};

// The decoder's pose before any report: the mapping's home, blade disengaged.
sim::ScalpelPose initial_pose(const Profile& profile);

// The whole path of decoded samples as keyframes (what a scalpel trace holds).
std::vector<sim::ScalpelKeyframe> to_keyframes(const Profile& profile, std::span<const Sample> samples);

}  // namespace mtcut::app::hid
