#include "engine/tet_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mtcut::engine {
namespace {

const Vec3 kO(0, 0, 0), kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);

TEST(TetGeometry, SignedVolumeFollowsRightHandRule) {
  EXPECT_DOUBLE_EQ(signed_volume(kO, kX, kY, kZ), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(signed_volume(kO, kY, kX, kZ), -1.0 / 6.0);
  EXPECT_EQ(orient3d_sign(kO, kX, kY, kZ), 1);
  EXPECT_EQ(orient3d_sign(kO, kY, kX, kZ), -1);
  EXPECT_EQ(orient3d_sign(kO, kX, kY, Vec3(0.3, 0.4, 0)), 0);
}

TEST(TetGeometry, ExactOrientationOnNearlyCoplanarPoints) {
  // A perturbation far below double round-off of the naive determinant.
  const Vec3 d(0.5, 0.5, 1e-300);
  EXPECT_EQ(orient3d_sign(kO, kX, kY, d), 1);
}

TEST(TetGeometry, FacesPointOutwards) {
  const std::array<Vec3, 4> p = {kO, kX, kY, kZ};
  const Vec3 centroid = (kO + kX + kY + kZ) / 4;
  for (int f = 0; f < 4; ++f) {
    const auto& lf = kTetFaces[f];
    const Vec3 n = (p[lf[1]] - p[lf[0]]).cross(p[lf[2]] - p[lf[0]]);
    EXPECT_LT(n.dot(centroid - p[lf[0]]), 0) << "face " << f;
    for (int k : lf) EXPECT_NE(k, f);
  }
}

TEST(TetGeometry, RegularTetHasKnownAnglesAndRatio) {
  const Vec3 a(1, 1, 1), b(-1, 1, -1), c(1, -1, -1), d(-1, -1, 1);
  ASSERT_GT(signed_volume(a, b, c, d), 0);
  const double expected = std::acos(1.0 / 3.0) * 180 / M_PI;  // 70.53 degrees
  EXPECT_NEAR(min_dihedral_deg(a, b, c, d), expected, 1e-9);
  EXPECT_NEAR(radius_ratio(a, b, c, d), 1.0, 1e-12);
  EXPECT_NEAR(min_enclosing_radius(a, b, c, d), std::sqrt(3.0), 1e-12);
}

TEST(TetGeometry, CornerTetAnglesAndEnclosingSphere) {
  const auto angles = dihedral_angles(kO, kX, kY, kZ);
  // The three edges at the origin are right angles.
  EXPECT_NEAR(angles[0], M_PI / 2, 1e-12);
  EXPECT_NEAR(angles[1], M_PI / 2, 1e-12);
  EXPECT_NEAR(angles[2], M_PI / 2, 1e-12);
  // Smallest sphere: the circle through X, Y, Z contains O too.
  EXPECT_NEAR(min_enclosing_radius(kO, kX, kY, kZ), std::sqrt(2.0 / 3.0), 1e-12);
}

TEST(TetGeometry, ObtuseTetEnclosingSphereIsTheLongestEdgeSphere) {
  // A flat tet whose smallest sphere has the long edge as diameter.
  const Vec3 a(-1, 0, 0), b(1, 0, 0), c(0, 0.1, 0), d(0, 0, 0.1);
  EXPECT_NEAR(min_enclosing_radius(a, b, c, d), 1.0, 1e-12);
}

TEST(TetGeometry, DegenerateTetHasZeroQuality) {
  EXPECT_EQ(min_dihedral_deg(kO, kX, kY, Vec3(1, 1, 0)), 0.0);
  EXPECT_EQ(radius_ratio(kO, kX, kY, Vec3(1, 1, 0)), 0.0);
}

}  // namespace
}  // namespace mtcut::engine
