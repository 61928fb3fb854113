#pragma once
// The HID as the scalpel of a frame loop: every sample, live from the input
// thread or replayed from a recording, joins one HidPath, and each frame the
// World gets every sample since the last frame and the path's pose at the
// frame's time, in time order (a fast stroke reaches it as a polyline of
// poses, not one jump). The input's clock and the World's time both start at
// 0 when the run starts.
//
// Live, the frame that starts at World time t is fed once the device clock
// has passed t + lookahead (frame_samples waits for it): the samples just
// after t, which the path's pose at t is interpolated towards, are in by
// then, so a live run gives the World the poses a replay of its recording
// gives (up to a device silent for longer than the lookahead, whose pose
// then holds).
//
// Use from a frame loop:
//   HidFeed hid(input, dt);                       // or HidFeed(profile, samples)
//   every frame: samples = hid.frame_samples(world.time());
//                world.step(sim::poses_of(samples));
//                hid.reached(t, hid.clock());     // (a replay: t + dt + step seconds)
//                for (const InputEvent& e : hid.take_events()) tell the user;

#include <chrono>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <vector>

#include "app/hid/hid_path.h"
#include "app/hid/input_thread.h"
#include "app/hid/latency_stats.h"

namespace mtcut::app::hid {

class HidFeed {
 public:
  // A replay: the decoded samples of a recording (time order) and how its reports decoded.
  HidFeed(const Profile& profile, const std::vector<Sample>& samples, const DecodeCounts& counts = {});
  // Live: samples as `input` (started, outliving this) queues them.
  HidFeed(InputThread& input, double lookahead_seconds);

  // The samples for the frame starting at `t` s: the path's keyframes after
  // the previous frame's time up to `t`, then the pose at `t` (the last one,
  // at `t`); see sim::ScalpelPath::samples_between. Live, first waits until
  // the device clock reaches t + lookahead and takes every sample queued.
  // `t` must not decrease from call to call.
  std::vector<sim::ScalpelKeyframe> frame_samples(double t);
  // The frame at `t` has been stepped, finishing at `finished` s on the
  // input's clock: samples up to t have reached the World (latency).
  void reached(double t, double finished);
  // Seconds on the input's clock since it started (live; 0 for a replay).
  double clock() const;
  // The pose at World time 0 when it is known before the run starts: a
  // replay's (nullopt live: the device has not been read yet).
  std::optional<sim::ScalpelPose> start_pose() const;

  bool live() const { return input_ != nullptr; }
  // Faults and connections to tell the user, each once (live; none for a replay).
  std::vector<InputEvent> take_events();
  // The input thread's status (live; for a replay: the decode counts).
  InputStatus status() const;
  long samples() const { return samples_; }  // taken into the path so far
  LatencySummary latency() const { return latency_.summary(); }

 private:
  void take(const std::vector<Sample>& samples);

  InputThread* input_ = nullptr;
  double lookahead_ = 0;
  HidPath path_;
  double last_frame_ = -std::numeric_limits<double>::infinity();  // time of the last frame fed
  std::deque<std::int64_t> pending_us_;  // times of samples not yet reached by a frame
  long samples_ = 0;
  InputStatus replay_status_;
  LatencyStats latency_;
};

}  // namespace mtcut::app::hid
