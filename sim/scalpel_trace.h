#pragma once
// Scalpel traces: the samples of a scalpel's motion as a CSV file, written by
// `mtcut run --record`, the viewer and the HID input, and replayed by a
// scenario (`[scalpel] trace = "file.csv"`). One format for all of them:
//
//   time,base_x,base_y,base_z,tip_x,tip_y,tip_z,engaged
//   0,0.04,-0.06,0.06,0.04,-0.06,-0.045,1
//
// time in seconds (strictly increasing), positions in metres, engaged 0 or 1.
// Reals are printed shortest round-trip (std::to_chars), so reading a trace
// back gives the very doubles that were written, and a replay is
// bit-identical to the run that recorded it. Replayed, the samples are the
// keyframes of a ScalpelPath (linear in between), and each frame the World
// gets the samples since the last frame and the pose at the frame's time
// (ScalpelPath::samples_between).

#include <span>
#include <string>
#include <string_view>

#include "sim/scalpel.h"

namespace mtcut::sim {

// One sample of the scalpel: a pose at a time (a keyframe of the path).
using ScalpelSample = ScalpelKeyframe;

// The header line, without its line end.
inline constexpr std::string_view kScalpelTraceHeader = "time,base_x,base_y,base_z,tip_x,tip_y,tip_z,engaged";

// Writes the samples (times strictly increasing) to path, atomically.
// Throws engine::InputError when the file cannot be written.
void write_scalpel_trace(const std::string& path, std::span<const ScalpelSample> samples);

// Reads a trace as the keyframes of a path. Throws engine::InputError
// "path:line: reason" for a missing or empty file, a wrong header, a row
// without 8 fields, a field that is not a finite number, engaged not 0 or 1,
// or a time not after the previous one.
ScalpelPath read_scalpel_trace(const std::string& path);

}  // namespace mtcut::sim
