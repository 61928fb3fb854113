#include "app/view/scene_props.h"

#include <gtest/gtest.h>

namespace mtcut::app::view {
namespace {

TEST(SceneProps, FloorLiesOnItsPlaneUnderTheBox) {
  sim::Plane floor{engine::Vec3(0, 0, 1), -0.05};
  const auto tris = floor_triangles(floor, glm::dvec3(-0.08, -0.05, -0.035), glm::dvec3(0.08, 0.05, 0.035), 4);
  ASSERT_EQ(tris.size(), 4u * 4u * 6u);
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const PropVertex& v : tris) {
    EXPECT_NEAR(v.position.z, -0.05f, 1e-6f);
    EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  EXPECT_LT(lo.x, -0.08f);
  EXPECT_GT(hi.y, 0.05f);
  EXPECT_NEAR(lo.x + hi.x, 0.0f, 1e-6f);  // centred under the box
}

TEST(SceneProps, BladeRibbonSpansBaseToTipAndShowsEngagement) {
  sim::ScalpelPose pose{engine::Vec3(0, 0, 1), engine::Vec3(0, 0, 0), true};
  const auto tris = blade_triangles(pose, glm::dvec3(5, 0, 0.5), 0.01);
  ASSERT_EQ(tris.size(), 6u);
  for (const PropVertex& v : tris) {
    EXPECT_NEAR(std::abs(v.position.y), 0.005f, 1e-6f);  // sideways to the eye on +x
    EXPECT_NEAR(v.position.x, 0.0f, 1e-6f);
    EXPECT_EQ(v.color, kEngagedBladeColor);
  }
  pose.engaged = false;
  EXPECT_EQ(blade_triangles(pose, glm::dvec3(5, 0, 0.5), 0.01)[0].color, kBladeColor);
  pose.tip = pose.base;  // degenerate: still two finite triangles
  for (const PropVertex& v : blade_triangles(pose, glm::dvec3(5, 0, 0.5), 0.01))
    EXPECT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y));
}

}  // namespace
}  // namespace mtcut::app::view
