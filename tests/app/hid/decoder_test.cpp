// Decoding recorded report bytes with each shipped profile gives the expected
// poses; malformed reports are rejected, counted, and leave the pose alone.

#include "app/hid/decoder.h"

#include <gtest/gtest.h>

#include <cmath>

#include "app/hid/profile_file.h"
#include "tests/app/hid/hid_test_util.h"

namespace mtcut::app::hid {
namespace {
using engine::Vec3;
using test::expect_pose;
using test::pen_report;
using test::spacemouse_report;

RawEvent report(std::int64_t time_us, std::vector<std::uint8_t> bytes) {
  return {time_us, RawEvent::Kind::report, std::move(bytes)};
}

TEST(HidDecoder, SpaceMouseIntegratesTranslationAndRotationAndTogglesTheBlade) {
  Decoder decoder(load_profile("spacemouse"));
  const Vec3 up(0, 0, 0.1);  // tip -> base with the blade vertical
  // Full push right: the first report only sets the velocity.
  auto s = decoder.feed(report(0, spacemouse_report(1, 350, 0, 0)));
  ASSERT_TRUE(s);
  expect_pose(s->pose, Vec3(0.04, 0, 0.06), Vec3(0.04, 0, 0.06) + up, false);
  // 10 ms at 0.1 m/s.
  s = decoder.feed(report(10000, spacemouse_report(1, 350, 0, 0)));
  expect_pose(s->pose, Vec3(0.041, 0, 0.06), Vec3(0.041, 0, 0.06) + up, false);
  // Left button: toggles on, stays on when released, toggles off on the next press.
  s = decoder.feed(report(20000, {3, 0x01}));
  expect_pose(s->pose, Vec3(0.042, 0, 0.06), Vec3(0.042, 0, 0.06) + up, true);
  s = decoder.feed(report(30000, {3, 0x00}));
  EXPECT_TRUE(s->pose.engaged);
  s = decoder.feed(report(40000, {3, 0x01}));
  EXPECT_FALSE(s->pose.engaged);
  // Full rx (1.5 rad/s); then the cap is released: 10 ms more of both.
  s = decoder.feed(report(50000, spacemouse_report(2, 350, 0, 0)));
  expect_pose(s->pose, Vec3(0.045, 0, 0.06), Vec3(0.045, 0, 0.06) + up, false);
  s = decoder.feed(report(60000, spacemouse_report(1, 0, 0, 0)));
  const double angle = 0.015;
  const Vec3 tip(0.046, 0, 0.06);
  expect_pose(s->pose, tip, tip - 0.1 * Vec3(0, std::sin(angle), -std::cos(angle)), false);
  // Smoothing 0.5 halves tx; the dead zone (0.05) rescales it: v = 0.1 * 0.45 / 0.95.
  s = decoder.feed(report(70000, spacemouse_report(1, 0, 0, 0)));
  EXPECT_NEAR(s->pose.tip.x(), 0.046 + 0.01 * 0.1 * 0.45 / 0.95, 1e-15);
  // Device y (towards the user) and z (down) map to world -y and -z.
  Decoder axes(load_profile("spacemouse"));
  axes.feed(report(0, spacemouse_report(1, 0, 350, -350)));
  s = axes.feed(report(20000, spacemouse_report(1, 0, 350, -350)));
  test::expect_near(s->pose.tip, Vec3(0.04, -0.002, 0.062), "tip");
  EXPECT_EQ(decoder.counts().accepted, 8);
  EXPECT_EQ(decoder.counts().rejected(), 0);
}

TEST(HidDecoder, SpaceMouseNegativeValuesAndAGapLongerThanMaxDt) {
  Decoder decoder(load_profile("spacemouse"));
  decoder.feed(report(0, spacemouse_report(1, -350, 0, 0)));
  // A 2 s silence integrates only max_dt (0.05 s): 0.1 m/s * 0.05 s.
  const auto s = decoder.feed(report(2000000, spacemouse_report(1, -350, 0, 0)));
  EXPECT_NEAR(s->pose.tip.x(), 0.04 - 0.005, 1e-15);
}

TEST(HidDecoder, MalformedReportsAreRejectedAndCounted) {
  Decoder decoder(load_profile("spacemouse"));
  decoder.feed(report(0, spacemouse_report(1, 350, 0, 0)));
  EXPECT_FALSE(decoder.feed(report(1000, {0x01, 0x10})));  // too short
  EXPECT_NE(decoder.last_reject().find("2 bytes, needs 7"), std::string::npos) << decoder.last_reject();
  EXPECT_FALSE(decoder.feed(report(2000, {})));  // empty
  EXPECT_FALSE(decoder.feed(report(3000, {0x07, 0, 0, 0, 0, 0, 0})));  // unknown id
  EXPECT_NE(decoder.last_reject().find("unknown report id 7"), std::string::npos);
  EXPECT_FALSE(decoder.feed(report(4000, spacemouse_report(1, 400, 0, 0))));  // out of range
  EXPECT_NE(decoder.last_reject().find("'tx' = 400 outside [-350, 350]"), std::string::npos);
  EXPECT_FALSE(decoder.feed(report(5000, spacemouse_report(2, 0, -351, 0))));
  const DecodeCounts& c = decoder.counts();
  EXPECT_EQ(c.accepted, 1);
  EXPECT_EQ(c.too_short, 2);
  EXPECT_EQ(c.unknown_report, 1);
  EXPECT_EQ(c.out_of_range, 2);
  EXPECT_EQ(c.rejected(), 5);
  // Rejected reports changed nothing: the next good one integrates from the first.
  const auto s = decoder.feed(report(10000, spacemouse_report(1, 350, 0, 0)));
  test::expect_near(s->pose.tip, Vec3(0.041, 0, 0.06), "tip");
  // A longer report than needed is fine (extra bytes ignored).
  auto longer = spacemouse_report(1, 350, 0, 0);
  longer.resize(13, 0);
  EXPECT_TRUE(decoder.feed(report(20000, longer)));
}

TEST(HidDecoder, PenTabletIsAbsoluteWithPressureDepthTipSwitchAndTilt) {
  Decoder decoder(load_profile("pen_tablet"));
  // Top-left corner of the tablet (towards +y in the world), full pressure, pen upright.
  auto s = decoder.feed(report(0, pen_report(true, 32767, 0, 8191, 0, 0)));
  ASSERT_TRUE(s);
  expect_pose(s->pose, Vec3(0.1, 0.1, 0.04 - 0.11), Vec3(0.1, 0.1, 0.04 - 0.11 + 0.13), true);
  // Pen lifted: tip switch off, no pressure; smoothing 0.2 keeps a fifth of the old value.
  s = decoder.feed(report(5000, pen_report(false, 32767, 0, 0, 0, 0)));
  expect_pose(s->pose, Vec3(0.1, 0.1, 0.04 - 0.2 * 0.11), Vec3(0.1, 0.1, 0.04 - 0.2 * 0.11 + 0.13), false);
  // Tilted 60 degrees towards +x: the base leans to +x.
  Decoder tilted(load_profile("pen_tablet"));
  s = tilted.feed(report(0, pen_report(true, 16384, 16384, 0, 127, 0)));
  const double c = 1.0 / 32767;  // 16384 is half a step right of the centre
  const Vec3 tip(0.1 * c, -0.1 * c, 0.04);
  const Vec3 axis = Vec3(std::tan(1.0472), 0, 1).normalized();
  expect_pose(s->pose, tip, tip + 0.13 * axis, true);
  EXPECT_GT(s->pose.base.x(), s->pose.tip.x());
  // Malformed: wrong id, short, pressure beyond 8191.
  EXPECT_FALSE(decoder.feed(report(6000, spacemouse_report(1, 0, 0, 0))));
  EXPECT_FALSE(decoder.feed(report(7000, {2, 1, 0, 0})));
  EXPECT_FALSE(decoder.feed(report(8000, pen_report(true, 0, 0, 9000, 0, 0))));
  EXPECT_EQ(decoder.counts().unknown_report, 1);
  EXPECT_EQ(decoder.counts().too_short, 1);
  EXPECT_EQ(decoder.counts().out_of_range, 1);
}

TEST(HidDecoder, GamepadUnnumberedReportsWithDeadZoneAndHoldButton) {
  Decoder decoder(load_profile("gamepad"));
  // Left stick full right, the rest centred (128 is inside the dead zone), button 1 held.
  auto s = decoder.feed(report(0, {255, 128, 128, 128, 0x01}));
  ASSERT_TRUE(s);
  expect_pose(s->pose, Vec3(0.04, 0, 0.06), Vec3(0.04, 0, 0.16), true);
  s = decoder.feed(report(20000, {255, 128, 128, 128, 0x01}));
  expect_pose(s->pose, Vec3(0.04 + 0.02 * 0.08, 0, 0.06), Vec3(0.04 + 0.02 * 0.08, 0, 0.16), true);
  // Button released: hold mode disengages at once.
  s = decoder.feed(report(30000, {128, 128, 128, 128, 0x00}));
  EXPECT_FALSE(s->pose.engaged);
  // Right stick y pushed up (0) raises the scalpel.
  Decoder up(load_profile("gamepad"));
  up.feed(report(0, {128, 128, 128, 0, 0}));
  s = up.feed(report(10000, {128, 128, 128, 0, 0}));
  EXPECT_NEAR(s->pose.tip.z(), 0.06 + 0.01 * 0.08, 1e-15);
  EXPECT_FALSE(decoder.feed(report(40000, {255, 128, 128, 128})));  // too short
  EXPECT_EQ(decoder.counts().too_short, 1);
}

TEST(HidDecoder, UnplugDisengagesAndStopsAHeldDeflection) {
  Decoder decoder(load_profile("gamepad"));
  decoder.feed(report(0, {255, 128, 128, 128, 0x01}));
  auto s = decoder.feed({10000, RawEvent::Kind::unplugged, {}});
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->pose.engaged);
  const Vec3 held = s->pose.tip;
  // After reconnection the first report starts a new integration, from rest.
  s = decoder.feed(report(5000000, {128, 128, 128, 128, 0x00}));
  test::expect_near(s->pose.tip, held, "tip");
}

}  // namespace
}  // namespace mtcut::app::hid
