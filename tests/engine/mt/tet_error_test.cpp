#include "engine/mt/tet_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/tet_geometry.h"

namespace mtcut::engine {
namespace {

TEST(TetError, EnclosingRadiusMatchesTheReferenceOnRandomTets) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 3000; ++i) {
    Vec3 p[4];
    for (auto& q : p) q = Vec3(u(rng), u(rng), u(rng));
    if (i % 3 == 1) p[3] = 0.5 * (p[0] + p[1]) + 0.01 * Vec3(u(rng), u(rng), u(rng));  // flat, obtuse
    if (i % 3 == 2) p[3] = p[0] + 1e-3 * Vec3(u(rng), u(rng), u(rng));               // needle-ish
    const double ref = min_enclosing_radius(p[0], p[1], p[2], p[3]);
    EXPECT_NEAR(enclosing_radius(p[0], p[1], p[2], p[3]), ref, 1e-9 * ref) << "tet " << i;
  }
}

TEST(TetError, RegularTetHasJungsRadiusAndQualityOne) {
  const Vec3 a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);  // edge 2 sqrt 2
  const double edge = std::sqrt(8.0);
  EXPECT_NEAR(enclosing_radius(a, b, c, d), std::sqrt(3.0 / 8.0) * edge, 1e-12);
  const double q = tet_quality(a, b, c, d);
  EXPECT_NEAR(std::abs(q), 1.0, 1e-12);
  EXPECT_NEAR(tet_quality(a, b, d, c), -q, 1e-12);  // orientation gives the sign
  EXPECT_EQ(tet_error(a, b, c, d), static_cast<float>(enclosing_radius(a, b, c, d)));
}

TEST(TetError, ErrorGrowsWithSize) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, 0, 1);
  EXPECT_NEAR(enclosing_radius(2 * a, 2 * b, 2 * c, 2 * d), 2 * enclosing_radius(a, b, c, d), 1e-12);
  EXPECT_LT(tet_quality(a, b, c, Vec3(0.3, 0.3, 1e-4)), 1e-3);  // a sliver
}

TEST(TetError, PointTriangleDistanceByRegion) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_NEAR(point_triangle_distance(Vec3(0.5, 0.5, 3), a, b, c), 3.0, 1e-12);      // face
  EXPECT_NEAR(point_triangle_distance(Vec3(-1, -1, 0), a, b, c), std::sqrt(2.0), 1e-12);  // vertex a
  EXPECT_NEAR(point_triangle_distance(Vec3(1, -2, 0), a, b, c), 2.0, 1e-12);         // edge ab
  EXPECT_NEAR(point_triangle_distance(Vec3(2, 2, 0), a, b, c), std::sqrt(2.0), 1e-12);  // edge bc
  EXPECT_NEAR(point_triangle_distance(Vec3(3, 0, 0), a, b, c), 1.0, 1e-12);          // vertex b
}

}  // namespace
}  // namespace mtcut::engine
