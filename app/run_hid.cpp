#include "app/run_hid.h"

#include <ostream>

#include "app/hid/device_choice.h"
#include "app/hid/profile_file.h"
#include "app/hid/recording.h"
#include "engine/input_error.h"

namespace mtcut::app {

RunHid::RunHid(const RunHidDef& def, double dt) : def_(def), dt_(dt) {
  if (def.live && !def.replay_path.empty())
    throw engine::InputError("--hid and --hid-replay: give one (live from the device, or a recording)");
  if (!def.record_path.empty() && !def.live)
    throw engine::InputError("--record-hid " + def.record_path + ": records the device of a --hid run; add --hid");
  if (!def.replay_path.empty()) {
    const std::string name = def.profile.empty() ? hid::recorded_profile(def.replay_path) : def.profile;
    if (name.empty())
      throw engine::InputError("--hid-replay " + def.replay_path +
                               ": the recording names no profile; give the one it was recorded with (--profile P)");
    const hid::Profile profile = hid::load_profile(name);
    profile_name_ = profile.name;
    hid::DecodeCounts counts;
    const std::vector<hid::Sample> samples = hid::replay_recording(def.replay_path, profile, &counts);
    feed_ = std::make_unique<hid::HidFeed>(profile, samples, counts);
    return;
  }
  transport_ = std::make_unique<hid::HidapiTransport>();
  hid::DeviceChoice choice = hid::choose_device(*transport_, def.profile, "", /*wait_for_device=*/true);
  profile_name_ = choice.profile.name;
  hid::InputDef input;
  input.record_path = def.record_path;
  input_ = std::make_unique<hid::InputThread>(*transport_, std::move(choice.profile), input);
}

void RunHid::start() {
  if (!input_ || feed_) return;
  input_->start();
  feed_ = std::make_unique<hid::HidFeed>(*input_, dt_);
}

RunHid::~RunHid() {
  if (input_) input_->stop();
}

void RunHid::stepped(double t, double step_seconds) {
  // A replay runs as fast as it can: its latency is the one a live run that
  // keeps up would have (fed at t + dt, then the step).
  feed_->reached(t, feed_->live() ? feed_->clock() : t + dt_ + step_seconds);
}

void RunHid::report_events(std::ostream& err) {
  for (const hid::InputEvent& e : feed_->take_events()) err << "mtcut: hid: " << e.message << "\n";
}

nlohmann::ordered_json RunHid::summary() const {
  const hid::InputStatus status = feed_->status();
  const hid::LatencySummary latency = feed_->latency();
  nlohmann::ordered_json out = {{"mode", feed_->live() ? "live" : "replay"},
                                {"profile", profile_name_},
                                {"samples", feed_->samples()},
                                {"reports_rejected", status.counts.rejected()},
                                {"unplugs", status.unplugs},
                                {"sample_to_cut_ms", {{"samples", latency.count},
                                                      {"median", latency.median_ms},
                                                      {"max", latency.max_ms}}}};
  if (!def_.replay_path.empty()) out["recording"] = def_.replay_path;
  if (!def_.record_path.empty()) out["record_hid"] = def_.record_path;
  return out;
}

}  // namespace mtcut::app
