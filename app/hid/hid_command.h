#pragma once
// `mtcut hid list` (every HID device and the profile that fits it) and
// `mtcut hid monitor [--profile P] [--device PATH] [--seconds S] [--record-hid FILE]`
// (live decoded samples, optionally recording the raw reports), and
// `mtcut hid replay REC --profile P` (a recording decoded again), and
// `mtcut hid convert REC --profile P -o TRACE` (a recording as a scalpel trace).

#include <CLI/CLI.hpp>

namespace mtcut::app::hid {

void register_hid_command(CLI::App& app);

}  // namespace mtcut::app::hid
