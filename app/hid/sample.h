#pragma once
// What flows from a HID device to the frame loop: raw events as read (and
// recorded), and the timestamped scalpel poses decoded from them.

#include <cstdint>
#include <vector>

#include "sim/scalpel.h"

namespace mtcut::app::hid {

// One thing the input thread saw. Times are whole microseconds so that a
// recording written as text and read back decodes bit for bit as it did live.
struct RawEvent {
  enum class Kind { report, unplugged };
  std::int64_t time_us = 0;         // since the source's epoch (steady clock at start)
  Kind kind = Kind::report;
  std::vector<std::uint8_t> bytes;  // the report as hid_read returned it (empty when unplugged)
};

// A decoded scalpel pose at the time its report arrived.
struct Sample {
  std::int64_t time_us = 0;  // since the source's epoch
  sim::ScalpelPose pose;
  double time() const { return static_cast<double>(time_us) * 1e-6; }  // s
};

}  // namespace mtcut::app::hid
