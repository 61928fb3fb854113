// `mtcut run --hid-replay`: a raw-report recording replayed through the
// decoder and the World cuts the default organ exactly as the equivalent pose
// trace (`mtcut hid convert`) does, and the stroke really cuts.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/hid/recording.h"
#include "tests/app/hid/hid_test_util.h"
#include "tests/app/run_fixture.h"

namespace mtcut::test {
namespace {

// pen_tablet's raw value for a centred axis at u in [-1, 1].
int raw_axis(double u) { return static_cast<int>(std::lround((u + 1.0) / 2.0 * 32767.0)); }

// A pen stroke through the default organ's front end, as the default
// scenario's keyframes draw it: at x = 4 cm, full pressure (the tip 11 cm
// below the pen's home, 2 cm below the floor the sagging organ reaches), from y = -6 cm to +6 cm in one
// second at 125 reports a second, then the pen lifted. Two malformed
// reports on the way are rejected and change nothing.
std::string pen_stroke_recording() {
  std::string text = "# mtcut-hidrec 1\n# profile pen_tablet\n# synthesised: a stroke through the default organ\n";
  const auto line = [&](std::int64_t us, std::vector<std::uint8_t> bytes) {
    text += app::hid::format_event({us, app::hid::RawEvent::Kind::report, std::move(bytes)}) + "\n";
  };
  const int x = raw_axis(0.04 / 0.1);
  for (int k = 0; k <= 125; ++k) {
    const double y = -0.06 + 0.12 * k / 125.0;
    line(100000 + 8000 * k, pen_report(true, x, raw_axis(-y / 0.1), 8191, 0, 0));
    if (k == 40) line(100000 + 8000 * k + 500, {2, 1, 0});   // too short
    if (k == 80) line(100000 + 8000 * k + 500, {7, 0, 0, 0});  // unknown report id
  }
  for (int k = 1; k <= 10; ++k) line(1100000 + 8000 * k, pen_report(false, x, raw_axis(-0.06 / 0.1), 0, 0, 0));
  return text;
}

using RunHidReplay = RunFixture;

TEST_F(RunHidReplay, ARecordingCutsTheOrganExactlyAsItsConvertedTrace) {
  const std::string rec = write("stroke.hidrec", pen_stroke_recording());
  const std::string scenario = source_path("config/scenarios/default.toml");
  const auto replayed = run_json("run " + quoted(scenario) + " --frames 90 --out " + quoted(path("replay")) +
                                 " --hid-replay " + quoted(rec) + " --record " + quoted(path("recorded.csv")));

  const CommandResult converted =
      run_mtcut("hid convert " + quoted(rec) + " --profile pen_tablet -o " + quoted(path("trace.csv")));
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  EXPECT_NE(converted.out.find("from 136 reports (2 rejected)"), std::string::npos) << converted.out;
  const auto traced = run_json("run " + quoted(write("trace.toml", replay_of("trace.csv"))) + " --frames 90 --out " +
                               quoted(path("trace")));
  ASSERT_FALSE(replayed.is_null());
  ASSERT_FALSE(traced.is_null());
  EXPECT_EQ(replayed["state_hash"], traced["state_hash"]);

  // --record keeps every pose the World got (the samples within each frame,
  // then the frame's pose), so its trace replays the run exactly too.
  const std::string recorded = read_text(path("recorded.csv"));
  EXPECT_GT(std::count(recorded.begin(), recorded.end(), '\n'), 1 + 90 + 100);
  const auto rerun = run_json("run " + quoted(write("recorded.toml", replay_of("recorded.csv"))) +
                              " --frames 90 --out " + quoted(path("rerun")));
  ASSERT_FALSE(rerun.is_null());
  EXPECT_EQ(rerun["state_hash"], replayed["state_hash"]);

  // The stroke cut the organ: the flap is a piece of its own, made of new tets.
  EXPECT_GE(replayed["pieces"].get<int>(), 2);
  EXPECT_GT(replayed["tets_total"].get<long>(), replayed["mt"]["tets_total"].get<long>());
  EXPECT_TRUE(replayed["valid"].get<bool>());

  const auto& hid = replayed["hid"];
  EXPECT_EQ(hid["mode"], "replay");
  EXPECT_EQ(hid["profile"], "pen_tablet");  // named by the recording
  EXPECT_EQ(hid["samples"], 136);
  EXPECT_EQ(hid["reports_rejected"], 2);
  // Every sample is within the 90 frames: each reached the World once.
  EXPECT_EQ(hid["sample_to_cut_ms"]["samples"], 136);
  EXPECT_GT(hid["sample_to_cut_ms"]["median"].get<double>(), 0.0);
}

TEST_F(RunHidReplay, OptionFaultsAreOneLineAndExit1) {
  const std::string rec = write("stroke.hidrec", "# mtcut-hidrec 1\n0.010000 02 01 00 00 00 00 00 00 00 00\n");
  const auto one_line = [](const CommandResult& r, const std::string& what) {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  };
  const std::string out = " --frames 2 --out " + quoted(path("out"));
  one_line(run_mtcut("run --hid-replay " + quoted(rec) + out), ": the recording names no profile;");
  one_line(run_mtcut("run --hid-replay " + quoted(path("none.hidrec")) + " --profile pen_tablet" + out),
           "none.hidrec: cannot open the HID recording");
  one_line(run_mtcut("run --record-hid " + quoted(path("r.hidrec")) + out), "add --hid");
  one_line(run_mtcut("run --profile pen_tablet" + out), "--profile pen_tablet: goes with --hid-replay");
  one_line(run_mtcut("run --hid-replay " + quoted(rec) + " --profile trackball" + out), "'trackball'");
}

}  // namespace
}  // namespace mtcut::test
