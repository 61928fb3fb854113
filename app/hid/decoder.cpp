#include "app/hid/decoder.h"

#include <algorithm>

namespace mtcut::app::hid {

Decoder::Decoder(Profile profile) : profile_(std::move(profile)), mapper_(profile_) {}

std::optional<Sample> Decoder::feed(const RawEvent& event) {
  if (event.kind == RawEvent::Kind::unplugged) {
    mapper_.release();
    last_time_us_.reset();
    return Sample{event.time_us, mapper_.pose()};
  }
  const ReportValues read = read_report(profile_, event.bytes);
  switch (read.reject) {
    case Reject::none: break;
    case Reject::too_short: ++counts_.too_short; break;
    case Reject::unknown_report: ++counts_.unknown_report; break;
    case Reject::out_of_range: ++counts_.out_of_range; break;
  }
  if (read.reject != Reject::none) {
    last_reject_ = read.why;
    return std::nullopt;
  }
  ++counts_.accepted;
  if (last_time_us_) {
    const double dt = static_cast<double>(event.time_us - *last_time_us_) * 1e-6;
    mapper_.advance(std::clamp(dt, 0.0, profile_.mapping.max_dt));
  }
  last_time_us_ = event.time_us;
  const ReportDef& report = profile_.reports[static_cast<std::size_t>(read.report)];
  for (std::size_t k = 0; k < report.fields.size(); ++k) mapper_.set_field(report.fields[k], read.values[k]);
  return Sample{event.time_us, mapper_.pose()};
}

std::vector<Sample> decode_events(const Profile& profile, const std::vector<RawEvent>& events, DecodeCounts* counts) {
  Decoder decoder(profile);
  std::vector<Sample> samples;
  for (const RawEvent& e : events)
    if (auto s = decoder.feed(e)) samples.push_back(*s);
  if (counts) *counts = decoder.counts();
  return samples;
}

}  // namespace mtcut::app::hid
