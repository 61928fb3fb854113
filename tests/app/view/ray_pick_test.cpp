#include "app/view/ray_pick.h"

#include <gtest/gtest.h>

#include <vector>

namespace mtcut::app::view {
namespace {

// Two unit triangles in the planes z = 0 and z = -1, over the origin.
std::vector<glm::vec3> two_layers() {
  return {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {-1, -1, -1}, {0, 1, -1}, {1, -1, -1}};
}

TEST(RayPick, NearestFaceFromAboveAndBelow) {
  const auto corners = two_layers();
  const auto down = pick_surface(Ray{{0, 0, 5}, {0, 0, -1}}, corners);
  ASSERT_TRUE(down);
  EXPECT_EQ(down->face, 0);
  EXPECT_NEAR(down->t, 5.0, 1e-12);
  EXPECT_NEAR(down->point.z, 0.0, 1e-12);
  const auto up = pick_surface(Ray{{0, 0, -5}, {0, 0, 1}}, corners);  // the second face's back side
  ASSERT_TRUE(up);
  EXPECT_EQ(up->face, 1);
  EXPECT_NEAR(up->t, 4.0, 1e-12);
}

TEST(RayPick, MissesBesideBehindAndAlong) {
  const auto corners = two_layers();
  EXPECT_FALSE(pick_surface(Ray{{3, 0, 5}, {0, 0, -1}}, corners));   // beside
  EXPECT_FALSE(pick_surface(Ray{{0, 0, 5}, {0, 0, 1}}, corners));    // pointing away
  EXPECT_FALSE(pick_surface(Ray{{-5, 0, 0}, {1, 0, 0}}, std::vector<glm::vec3>(corners.begin(), corners.begin() + 3)));
  EXPECT_FALSE(pick_surface(Ray{{0, 0, 5}, {0, 0, -1}}, {}));
}

TEST(RayPick, EdgeHitCountsAndOffAxisRayLandsOnThePlane) {
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(intersect_triangle(Ray{{0.5, 0, 1}, {0, 0, -1}}, a, b, c));
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.1, 0.2, -1));
  const auto t = intersect_triangle(Ray{{0.1, 0.1, 1}, dir}, a, b, c);
  ASSERT_TRUE(t);
  EXPECT_NEAR((glm::dvec3(0.1, 0.1, 1) + *t * dir).z, 0.0, 1e-12);
}

}  // namespace
}  // namespace mtcut::app::view
