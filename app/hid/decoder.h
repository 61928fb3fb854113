#pragma once
// The decoder: raw events -> timestamped scalpel poses, for one profile.
// Deterministic: the same events give the same samples, live or replayed.
// Malformed reports are counted by reason and yield no sample.

#include <optional>
#include <string>

#include "app/hid/pose_mapper.h"
#include "app/hid/profile.h"
#include "app/hid/report_fields.h"
#include "app/hid/sample.h"

namespace mtcut::app::hid {

struct DecodeCounts {
  long accepted = 0;
  long too_short = 0;
  long unknown_report = 0;
  long out_of_range = 0;
  long rejected() const { return too_short + unknown_report + out_of_range; }
};

class Decoder {
 public:
  explicit Decoder(Profile profile);
  Decoder(const Decoder&) = delete;  // the mapper points into profile_
  Decoder& operator=(const Decoder&) = delete;

  // A sample for an accepted report or an unplug (blade disengaged); nullopt
  // for a rejected report. Events must come in time order.
  std::optional<Sample> feed(const RawEvent& event);

  const Profile& profile() const { return profile_; }
  const DecodeCounts& counts() const { return counts_; }
  // Why the last rejected report was rejected ("" if none was).
  const std::string& last_reject() const { return last_reject_; }

 private:
  Profile profile_;
  PoseMapper mapper_;
  DecodeCounts counts_;
  std::string last_reject_;
  std::optional<std::int64_t> last_time_us_;  // of the last accepted report since start or unplug
};

// Decodes a whole event sequence with a fresh decoder (replay).
std::vector<Sample> decode_events(const Profile& profile, const std::vector<RawEvent>& events,
                                  DecodeCounts* counts = nullptr);

}  // namespace mtcut::app::hid
