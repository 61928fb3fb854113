#include "app/view/mouse_scalpel.h"

#include <gtest/gtest.h>

namespace mtcut::app::view {
namespace {

glm::dvec3 to_glm(const engine::Vec3& v) { return {v.x(), v.y(), v.z()}; }

TEST(MouseScalpel, APressOffTheSurfaceStartsNothing) {
  MouseScalpel s;
  EXPECT_FALSE(s.press(Ray{{0, 0, 1}, {0, 0, -1}}, std::nullopt));
  EXPECT_FALSE(s.active());
}

TEST(MouseScalpel, BladeAlongTheRayFromLiftToDepthEngagedFromTheSecondFrame) {
  MouseScalpel s({0.03, 0.01});
  const Ray ray{{0, 0, 1}, {0, 0, -1}};
  ASSERT_TRUE(s.press(ray, SurfaceHit{0.9, 0, glm::dvec3(0, 0, 0.1)}));
  const sim::ScalpelPose first = s.take_pose();
  EXPECT_FALSE(first.engaged);  // placing only
  EXPECT_NEAR(glm::length(to_glm(first.base) - glm::dvec3(0, 0, 0.11)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(to_glm(first.tip) - glm::dvec3(0, 0, 0.07)), 0.0, 1e-12);
  EXPECT_TRUE(s.take_pose().engaged);
  s.release();
  EXPECT_FALSE(s.active());
}

TEST(MouseScalpel, DragMovesTheEntryInThePlaneFacingTheCamera) {
  MouseScalpel s({0.02, 0.0});
  ASSERT_TRUE(s.press(Ray{{0, 0, 1}, {0, 0, -1}}, SurfaceHit{1.0, 0, glm::dvec3(0, 0, 0)}));
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.5, 0, -1));
  s.drag(Ray{{0, 0, 1}, dir});
  const sim::ScalpelPose pose = s.take_pose();
  EXPECT_NEAR(pose.base.z(), 0.0, 1e-12);  // the entry stays on z = 0
  EXPECT_NEAR(pose.base.x(), 0.5, 1e-12);
  const glm::dvec3 blade = to_glm(pose.tip) - to_glm(pose.base);
  EXPECT_NEAR(glm::length(blade), 0.02, 1e-12);
  EXPECT_NEAR(glm::dot(glm::normalize(blade), dir), 1.0, 1e-12);  // along the new ray
  s.drag(Ray{{0, 0, 1}, {1, 0, 0}});  // parallel to the plane: ignored
  EXPECT_NEAR(s.take_pose().base.x(), 0.5, 1e-12);
}

}  // namespace
}  // namespace mtcut::app::view
