#include "app/view/orbit_camera.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace mtcut::app::view {
namespace {

OrbitCamera framed() {
  OrbitCamera c;
  c.frame(glm::dvec3(-0.08, -0.05, -0.035), glm::dvec3(0.08, 0.05, 0.035));
  return c;
}

TEST(OrbitCamera, FramingKeepsEveryCornerOfTheBoxInView) {
  const OrbitCamera c = framed();
  const glm::dmat4 vp = c.projection(16.0 / 9.0) * c.view();
  for (int i = 0; i < 8; ++i) {
    const glm::dvec4 p(i & 1 ? 0.08 : -0.08, i & 2 ? 0.05 : -0.05, i & 4 ? 0.035 : -0.035, 1.0);
    const glm::dvec4 clip = vp * p;
    ASSERT_GT(clip.w, 0.0);
    EXPECT_LE(std::abs(clip.x / clip.w), 1.0) << "corner " << i;
    EXPECT_LE(std::abs(clip.y / clip.w), 1.0) << "corner " << i;
    EXPECT_LE(std::abs(clip.z / clip.w), 1.0) << "corner " << i;
  }
}

TEST(OrbitCamera, CentrePixelRayPointsAtTheTarget) {
  const OrbitCamera c = framed();
  const Ray r = c.ray_through(640, 360, 1280, 720);
  EXPECT_NEAR(glm::length(r.direction), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(r.direction, c.forward()), 1.0, 1e-9);
  EXPECT_NEAR(glm::length(r.origin - c.eye()), 0.0, 1e-12);
}

TEST(OrbitCamera, PixelRaysFollowScreenAxes) {
  const OrbitCamera c = framed();
  const Ray left = c.ray_through(100, 360, 1280, 720), right = c.ray_through(1180, 360, 1280, 720);
  const Ray top = c.ray_through(640, 50, 1280, 720);
  const glm::dvec3 screen_right = glm::cross(c.forward(), glm::dvec3(0, 0, 1));
  EXPECT_GT(glm::dot(right.direction - left.direction, screen_right), 0.0);
  EXPECT_GT(top.direction.z, c.forward().z);  // the top of the window looks higher
}

TEST(OrbitCamera, OrbitKeepsTheTargetAndDistanceAndResetReturns) {
  OrbitCamera c = framed();
  const glm::dvec3 eye = c.eye();
  c.orbit(200, 50);
  EXPECT_NEAR(glm::length(c.eye() - c.target()), c.distance(), 1e-12);
  EXPECT_GT(glm::length(c.eye() - eye), 1e-3);
  c.orbit(0, 100000);  // pitch is clamped below the pole
  EXPECT_LT(std::abs(c.forward().z), 1.0);
  c.reset();
  EXPECT_NEAR(glm::length(c.eye() - eye), 0.0, 1e-12);
}

TEST(OrbitCamera, PanMovesTheTargetAcrossTheViewAndZoomIsClamped) {
  OrbitCamera c = framed();
  const glm::dvec3 target = c.target();
  c.pan(30, -20, 720);
  EXPECT_GT(glm::length(c.target() - target), 0.0);
  EXPECT_NEAR(glm::dot(c.target() - target, c.forward()), 0.0, 1e-12);
  const double d = c.distance();
  c.zoom(1);
  EXPECT_NEAR(c.distance(), 0.9 * d, 1e-12);
  c.zoom(1000);
  EXPECT_GT(c.distance(), 0.0);
  EXPECT_NEAR(c.distance(), 0.02 * c.radius(), 1e-12);
}

}  // namespace
}  // namespace mtcut::app::view
