#pragma once
// The HID scalpel of `mtcut run`: `--hid [PROFILE]` drives the blade live
// from the device through the input thread (optionally recording the raw
// reports, `--record-hid FILE`), `--hid-replay FILE --profile P` replays a
// recording through the same decoder. Either way the World gets, each frame,
// every sample since the last frame and the pose of the samples' path at the
// frame's time (app/hid/hid_feed.h).

#include <iosfwd>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/hid/hid_feed.h"
#include "app/hid/hidapi_transport.h"
#include "sim/scalpel.h"

namespace mtcut::app {

struct RunHidDef {
  bool live = false;         // --hid
  // --hid PROFILE or --profile P; "" = live: the profile that fits a connected
  // device; replay: the one the recording names.
  std::string profile;
  std::string record_path;   // --record-hid: raw reports recorded here (live only)
  std::string replay_path;   // --hid-replay: a .hidrec to replay ("" = none)
  bool enabled() const { return live || !replay_path.empty() || !record_path.empty(); }
};

class RunHid {
 public:
  // Checks the options, reads and decodes a replay, chooses the live
  // device's profile. Throws InputError.
  RunHid(const RunHidDef& def, double dt);
  // Live: starts the input thread, whose clock starts now, with World time 0.
  void start();
  ~RunHid();
  RunHid(const RunHid&) = delete;
  RunHid& operator=(const RunHid&) = delete;

  // The samples for the frame at World time t, the last one at t (live: waits for them).
  std::vector<sim::ScalpelKeyframe> frame_samples(double t) { return feed_->frame_samples(t); }
  // The blade's pose at World time 0, when known before start() (a replay).
  std::optional<sim::ScalpelPose> start_pose() const { return feed_ ? feed_->start_pose() : std::nullopt; }
  // The frame at t took `step_seconds`: latency of the samples it carried.
  void stepped(double t, double step_seconds);
  // Prints the input's events ("mtcut: hid: ..."), each once.
  void report_events(std::ostream& err);
  // The "hid" block of summary.json.
  nlohmann::ordered_json summary() const;

 private:
  RunHidDef def_;
  double dt_;
  std::string profile_name_;
  std::unique_ptr<hid::HidapiTransport> transport_;  // live
  std::unique_ptr<hid::InputThread> input_;          // live
  std::unique_ptr<hid::HidFeed> feed_;
};

}  // namespace mtcut::app
