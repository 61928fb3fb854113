// HID samples become strictly increasing keyframes starting at 0.

#include "app/hid/keyframes.h"

#include <gtest/gtest.h>

namespace mtcut::app::hid {
namespace {

TEST(HidKeyframes, StartAtZeroAndKeepTheLastSampleOfAMicrosecond) {
  std::vector<Sample> s(4);
  s[0].time_us = 500000;
  s[1].time_us = 508000;
  s[2].time_us = 508000;
  s[2].pose.engaged = true;
  s[3].time_us = 1500000;
  const auto keys = to_keyframes(s);
  ASSERT_EQ(keys.size(), 3u);
  EXPECT_EQ(keys[0].time, 0.0);
  EXPECT_DOUBLE_EQ(keys[1].time, 0.008);
  EXPECT_TRUE(keys[1].pose.engaged);
  EXPECT_DOUBLE_EQ(keys[2].time, 1.0);
  EXPECT_TRUE(to_keyframes({}).empty());
}

}  // namespace
}  // namespace mtcut::app::hid
