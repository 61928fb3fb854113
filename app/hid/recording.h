#pragma once
// Raw HID recordings (.hidrec): every report as read, so a session can be
// decoded again later through the same decoder, with the same or another
// profile. A text format, one event per line:
//
//   # mtcut-hidrec 1                      (first line)
//   # any comment                         (e.g. the device it came from)
//   0.008123 01 0a 00 f6 ff 00 00         (seconds since start, report bytes in hex)
//   1.250000 unplugged                    (the device went away)
//
// Seconds have exactly six decimals: times are whole microseconds, so a
// replay decodes bit for bit as the live run did.

#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "app/hid/decoder.h"
#include "app/hid/sample.h"

namespace mtcut::app::hid {

class Recorder {
 public:
  // Creates `path` and writes the header; throws InputError when it cannot.
  explicit Recorder(const std::string& path);
  void comment(const std::string& text);
  void write(const RawEvent& event);
  // False once a write failed (disk full, file removed...).
  bool ok() const { return static_cast<bool>(out_); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream out_;
};

// One event as a line (without the newline).
std::string format_event(const RawEvent& event);

// Reads a recording; throws InputError "file:line: what" for a malformed line
// or times that go backwards.
std::vector<RawEvent> read_recording(const std::string& path);

// The profile named by the recording's "# profile NAME" comment (the input
// thread writes it), or "" when it has none.
std::string recorded_profile(const std::string& path);

// The recording decoded with `profile`: the timestamped poses a live run gave.
std::vector<Sample> replay_recording(const std::string& path, const Profile& profile, DecodeCounts* counts = nullptr);

// The samples with t0_us < time_us <= t1_us (samples sorted by time): what a
// frame loop driven by a replay takes for the frame ending at t1.
std::span<const Sample> samples_between(std::span<const Sample> samples, std::int64_t t0_us, std::int64_t t1_us);

}  // namespace mtcut::app::hid
