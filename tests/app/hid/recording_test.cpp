// Raw recordings: written and read back exactly; faults are file:line; the
// frame loop's window of samples.

#include "app/hid/recording.h"

#include <gtest/gtest.h>

#include <functional>

#include "app/hid/profile_file.h"
#include "engine/input_error.h"
#include "tests/app/hid/hid_test_util.h"
#include "tests/temp_dir.h"

namespace mtcut::app::hid {
namespace {

class HidRecording : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return dir_.file(name); }
  std::string write(const std::string& text) const { return dir_.write("r.hidrec", text); }
  std::string error_of(const std::string& text) const {
    return mtcut::test::input_error_of([&] { read_recording(write(text)); });
  }
  mtcut::test::TempDir dir_;
};

TEST_F(HidRecording, RoundTripsEventsExactly) {
  const std::vector<RawEvent> events = {
      {0, RawEvent::Kind::report, test::spacemouse_report(1, 350, -2, 0)},
      {8123, RawEvent::Kind::report, {0x03, 0x01}},
      {1250000, RawEvent::Kind::unplugged, {}},
      {123456789012, RawEvent::Kind::report, {0xff}},
  };
  {
    Recorder recorder(path("a.hidrec"));
    recorder.comment("device 256f:c635 /dev/hidraw3");
    for (const RawEvent& e : events) recorder.write(e);
    EXPECT_TRUE(recorder.ok());
  }
  EXPECT_EQ(format_event(events[0]), "0.000000 01 5e 01 fe ff 00 00");
  EXPECT_EQ(format_event(events[2]), "1.250000 unplugged");
  const std::vector<RawEvent> back = read_recording(path("a.hidrec"));
  ASSERT_EQ(back.size(), events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(back[i].time_us, events[i].time_us);
    EXPECT_EQ(back[i].kind, events[i].kind);
    EXPECT_EQ(back[i].bytes, events[i].bytes);
  }
}

TEST_F(HidRecording, ReplayDecodesLikeTheDecoder) {
  const Profile profile = load_profile("spacemouse");
  std::vector<RawEvent> events;
  for (int k = 0; k < 20; ++k)
    events.push_back({k * 8000, RawEvent::Kind::report, test::spacemouse_report(1 + k % 2, 10 * k, -5 * k, 3 * k)});
  events.push_back({200000, RawEvent::Kind::report, {0x09}});  // rejected, counted
  {
    Recorder recorder(path("b.hidrec"));
    for (const RawEvent& e : events) recorder.write(e);
  }
  DecodeCounts counts;
  const std::vector<Sample> replayed = replay_recording(path("b.hidrec"), profile, &counts);
  EXPECT_TRUE(test::same_samples(replayed, decode_events(profile, events)));
  EXPECT_EQ(replayed.size(), 20u);
  EXPECT_EQ(counts.unknown_report, 1);
}

TEST_F(HidRecording, FaultsNameTheFileAndLine) {
  const std::string h = "# mtcut-hidrec 1\n";
  EXPECT_EQ(error_of("0.000000 01\n"), path("r.hidrec") + ":1: not an mtcut HID recording (the first line must be '# mtcut-hidrec 1')");
  EXPECT_EQ(error_of(h + "# c\n0.5 01\n"), path("r.hidrec") + ":3: '0.5' is not a time in seconds with six decimals");
  EXPECT_EQ(error_of(h + "0.000000 01 0g\n"), path("r.hidrec") + ":2: '0g' is not a byte in hex");
  EXPECT_EQ(error_of(h + "0.000000 01 123\n"), path("r.hidrec") + ":2: '123' is not a byte in hex");
  EXPECT_EQ(error_of(h + "0.000000\n"), path("r.hidrec") + ":2: a report line needs its bytes");
  EXPECT_EQ(error_of(h + "1.000000 01\n0.500000 01\n"), path("r.hidrec") + ":3: time goes backwards");
  EXPECT_EQ(error_of(h + "1.000000 unplugged 01\n"), path("r.hidrec") + ":2: nothing may follow 'unplugged'");
  EXPECT_EQ(error_of(h + "-1.000000 01\n"), path("r.hidrec") + ":2: '-1.000000' is not a time in seconds with six decimals");
  EXPECT_EQ(error_of(""), path("r.hidrec") + ":0: empty file, not an mtcut HID recording");
  EXPECT_EQ(error_of(h), "no error");
}

TEST(HidSamplesBetween, TakesTheHalfOpenWindow) {
  std::vector<Sample> s(5);
  for (int k = 0; k < 5; ++k) s[static_cast<std::size_t>(k)].time_us = 10 * k;  // 0 10 20 30 40
  auto w = samples_between(s, 10, 30);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].time_us, 20);
  EXPECT_EQ(w[1].time_us, 30);
  EXPECT_EQ(samples_between(s, -1, 0).size(), 1u);
  EXPECT_EQ(samples_between(s, 40, 100).size(), 0u);
  EXPECT_EQ(samples_between(s, 11, 19).size(), 0u);
}

}  // namespace
}  // namespace mtcut::app::hid
