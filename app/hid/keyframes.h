#pragma once
// Decoded HID samples as scalpel keyframes: the form a scalpel trace (and so
// a scenario's scripted scalpel) takes. Times start at the first sample and
// strictly increase; of several samples in one microsecond the last wins.

#include <span>
#include <vector>

#include "app/hid/sample.h"
#include "sim/scalpel.h"

namespace mtcut::app::hid {

std::vector<sim::ScalpelKeyframe> to_keyframes(std::span<const Sample> samples);

}  // namespace mtcut::app::hid
