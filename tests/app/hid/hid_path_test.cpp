// The HID path: keyframes on the input's clock from the decoder's initial
// pose, the last sample of a microsecond winning, and a live evaluation that
// forgets old keyframes yet gives bit for bit what sim::ScalpelPath gives
// over all of them.

#include "app/hid/hid_path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "app/hid/profile_file.h"

namespace mtcut::app::hid {
namespace {

Sample sample(std::int64_t us, double x, bool engaged) {
  Sample s;
  s.time_us = us;
  s.pose.tip = engine::Vec3(x, 0.1 * x, -0.02);
  s.pose.base = engine::Vec3(x, 0.3 * x, 0.08);
  s.pose.engaged = engaged;
  return s;
}

bool same(const sim::ScalpelPose& a, const sim::ScalpelPose& b) {
  return a.tip == b.tip && a.base == b.base && a.engaged == b.engaged;
}

TEST(HidPath, KeyframesStartAtTheInitialPoseAndKeepTheInputsClock) {
  const Profile profile = load_profile("pen_tablet");
  const std::vector<Sample> s = {sample(500000, 0.01, true), sample(508000, 0.02, false),
                                 sample(508000, 0.03, true), sample(1500000, 0.04, true)};
  const auto keys = to_keyframes(profile, s);
  ASSERT_EQ(keys.size(), 4u);
  EXPECT_EQ(keys[0].time, 0.0);
  EXPECT_TRUE(same(keys[0].pose, initial_pose(profile)));
  EXPECT_FALSE(keys[0].pose.engaged);
  EXPECT_EQ(keys[1].time, 0.5);
  EXPECT_EQ(keys[2].time, 0.508);
  EXPECT_TRUE(same(keys[2].pose, s[2].pose));  // the last of its microsecond
  EXPECT_EQ(keys[3].time, 1.5);
  EXPECT_EQ(to_keyframes(profile, {}).size(), 1u);
}

TEST(HidPath, ASampleAtTimeZeroReplacesTheInitialPose) {
  const auto keys = to_keyframes(load_profile("spacemouse"), std::vector<Sample>{sample(0, 0.05, true)});
  ASSERT_EQ(keys.size(), 1u);
  EXPECT_TRUE(keys[0].pose.engaged);
}

TEST(HidPath, LiveEvaluationIsTheWholePathsBitForBit) {
  const Profile profile = load_profile("pen_tablet");
  std::vector<Sample> samples;
  for (int k = 0; k < 200; ++k) samples.push_back(sample(3000 + 7919 * k + (k % 3) * 1000, 0.001 * k * k, k % 17 != 0));
  const sim::ScalpelPath whole(to_keyframes(profile, samples));
  HidPath live(initial_pose(profile));
  std::size_t added = 0;
  // Frames at 1/60 s, exact keyframe times included; samples join as they arrive.
  std::vector<double> times;
  for (int f = 0; f < 100; ++f) times.push_back(f / 60.0);
  times.push_back(samples[10].time());
  times.push_back(samples[150].time());
  std::sort(times.begin(), times.end());
  for (const double t : times) {
    while (added < samples.size() && samples[added].time() <= t + 1.0 / 60.0) live.add(samples[added++]);
    EXPECT_TRUE(same(live.pose_at(t), whole.pose_at(t))) << "t = " << t;
  }
  EXPECT_LT(live.keyframes().size(), 10u);  // old keyframes forgotten
}

TEST(HidPath, LiveFrameSamplesAreTheWholePathsBitForBit) {
  const Profile profile = load_profile("pen_tablet");
  std::vector<Sample> samples;
  for (int k = 0; k < 200; ++k) samples.push_back(sample(3000 + 2917 * k + (k % 3) * 1000, 0.001 * k * k, k % 17 != 0));
  const auto keys = to_keyframes(profile, samples);
  const sim::ScalpelPath whole(keys);
  HidPath live(initial_pose(profile));
  std::size_t added = 0;
  // Frames at 1/60 s, two at exact keyframe times; samples join as they arrive.
  std::vector<double> times;
  for (int f = 0; f < 40; ++f) times.push_back(f / 60.0);
  times.push_back(keys[10].time);
  times.push_back(keys[150].time);
  std::sort(times.begin(), times.end());
  double after = -std::numeric_limits<double>::infinity();
  std::vector<sim::ScalpelKeyframe> handed;
  for (const double t : times) {
    while (added < samples.size() && samples[added].time() <= t + 1.0 / 60.0) live.add(samples[added++]);
    const auto got = live.samples_between(after, t);
    const auto want = whole.samples_between(after, t);
    ASSERT_EQ(got.size(), want.size()) << "t = " << t;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].time, want[i].time);
      EXPECT_TRUE(same(got[i].pose, want[i].pose)) << "t = " << t << ", sample " << i;
    }
    // The frame's samples: after the last frame, up to t, the last one at t.
    ASSERT_FALSE(got.empty());
    EXPECT_EQ(got.back().time, t);
    EXPECT_TRUE(same(got.back().pose, whole.pose_at(t)));
    EXPECT_GT(got.front().time, after);
    handed.insert(handed.end(), got.begin(), got.end());
    after = t;
  }
  // Every keyframe up to the last frame reached a frame, once, in order.
  std::size_t found = 0;
  for (const auto& h : handed) {
    if (found < keys.size() && h.time == keys[found].time) {
      EXPECT_TRUE(same(h.pose, keys[found].pose)) << "t = " << h.time;
      ++found;
    }
  }
  EXPECT_GT(found, 100u);
  EXPECT_TRUE(found == keys.size() || keys[found].time > times.back());
  EXPECT_LT(live.keyframes().size(), 10u);  // old keyframes forgotten
}

}  // namespace
}  // namespace mtcut::app::hid
