#pragma once
// Helpers for the HID tests: little-endian report bytes, pose comparison.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "app/hid/sample.h"

namespace mtcut::test {

// Appends `value` as `n` little-endian bytes.
inline void put_le(std::vector<std::uint8_t>& bytes, std::int64_t value, int n) {
  for (int k = 0; k < n; ++k) bytes.push_back(static_cast<std::uint8_t>((static_cast<std::uint64_t>(value) >> (8 * k)) & 0xff));
}

// A SpaceMouse report: id, then three int16 LE.
inline std::vector<std::uint8_t> spacemouse_report(int id, int a, int b, int c) {
  std::vector<std::uint8_t> r{static_cast<std::uint8_t>(id)};
  put_le(r, a, 2);
  put_le(r, b, 2);
  put_le(r, c, 2);
  return r;
}

// A pen_tablet report (id 2).
inline std::vector<std::uint8_t> pen_report(bool tip, int x, int y, int pressure, int tilt_x, int tilt_y) {
  std::vector<std::uint8_t> r{2, static_cast<std::uint8_t>(tip ? 1 : 0)};
  put_le(r, x, 2);
  put_le(r, y, 2);
  put_le(r, pressure, 2);
  put_le(r, tilt_x, 1);
  put_le(r, tilt_y, 1);
  return r;
}

inline void expect_near(const engine::Vec3& a, const engine::Vec3& b, const char* what) {
  EXPECT_LT((a - b).norm(), 1e-12) << what << ": " << a.transpose() << " vs " << b.transpose();
}

inline void expect_pose(const sim::ScalpelPose& pose, const engine::Vec3& tip, const engine::Vec3& base, bool engaged) {
  expect_near(pose.tip, tip, "tip");
  expect_near(pose.base, base, "base");
  EXPECT_EQ(pose.engaged, engaged);
}

// Exact equality: a replay must decode bit for bit as the live run.
inline bool same_samples(const std::vector<app::hid::Sample>& a, const std::vector<app::hid::Sample>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].time_us != b[i].time_us || a[i].pose.tip != b[i].pose.tip || a[i].pose.base != b[i].pose.base ||
        a[i].pose.engaged != b[i].pose.engaged)
      return false;
  return true;
}

}  // namespace mtcut::test
