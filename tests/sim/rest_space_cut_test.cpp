// rest_space_polygon on point sets whose deformation is known: an affine
// deformation is undone exactly; only the vertices near the polygon fit the
// map (the tissue far from it may bend any way); a degenerate or inverted
// fit leaves the polygon as it is.

#include "sim/rest_space_cut.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

namespace mtcut::sim {
namespace {

// A grid of rest positions in the unit cube, n per side.
std::vector<Vec3> grid(int n) {
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) out.emplace_back(i / (n - 1.0), j / (n - 1.0), k / (n - 1.0));
  return out;
}

// A square across the cube at x = `x` (rest space).
cut::CutPolygon rest_square(double x = 0.5) {
  return cut::CutPolygon::from_points({Vec3(x, 0.2, 0.2), Vec3(x, 0.8, 0.2), Vec3(x, 0.8, 0.8), Vec3(x, 0.2, 0.8)});
}

cut::CutPolygon mapped(const cut::CutPolygon& p, const Eigen::Affine3d& map) {
  std::vector<Vec3> corners;
  for (const Vec3& c : p.corners()) corners.push_back(map * c);
  return cut::CutPolygon::from_points(corners);
}

double farthest_corner(const cut::CutPolygon& a, const cut::CutPolygon& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a.corners()[i] - b.corners()[i]).norm());
  return d;
}

// Rotated, sheared, stretched and moved: a polygon drawn on the deformed
// tissue lands where the same polygon lies in rest space.
TEST(RestSpaceCut, AnAffineDeformationIsUndoneExactly) {
  const std::vector<Vec3> rest = grid(6);
  Eigen::Affine3d map = Eigen::Affine3d::Identity();
  map.translate(Vec3(0.3, -0.2, 0.1));
  map.rotate(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
  shear(0, 1) = 0.4;
  shear(2, 2) = 1.3;
  map.linear() = map.linear() * shear;
  std::vector<Vec3> deformed;
  for (const Vec3& p : rest) deformed.push_back(map * p);
  const cut::CutPolygon in_rest = rest_space_polygon(mapped(rest_square(), map), rest, deformed);
  EXPECT_LT(farthest_corner(in_rest, rest_square()), 1e-12);
}

// The vertices beyond the reach (here: rest x < 0.2, moved at random, to
// x < 0.2 still) do not enter the fit: the polygon at x = 0.55 (between
// two layers of the grid, so that those within its reach span a volume),
// moved as the tissue around it (a translation), comes back exactly.
TEST(RestSpaceCut, OnlyTheTissueNearThePolygonFitsTheMap) {
  const std::vector<Vec3> rest = grid(11);
  const Vec3 move(0.05, 0.1, -0.02);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3), back(-0.3, 0.0);
  std::vector<Vec3> deformed;
  std::size_t scattered = 0;
  for (const Vec3& p : rest) {
    if (p.x() < 0.2) {
      deformed.push_back(p + Vec3(back(rng), u(rng), u(rng)));
      ++scattered;
    } else {
      deformed.push_back(p + move);
    }
  }
  ASSERT_GT(scattered, 100u);
  Eigen::Affine3d shift = Eigen::Affine3d::Identity();
  shift.translate(move);
  const RestSpaceCutDef def{.reach = 0.1, .min_points = 12};
  const cut::CutPolygon in_rest = rest_space_polygon(mapped(rest_square(0.55), shift), rest, deformed, def);
  EXPECT_LT(farthest_corner(in_rest, rest_square(0.55)), 1e-12);
  // With every vertex in reach the scattered ones pull the fit off.
  const cut::CutPolygon all = rest_space_polygon(mapped(rest_square(0.55), shift), rest, deformed, {.reach = 10.0});
  EXPECT_GT(farthest_corner(all, rest_square(0.55)), 1e-3);
}

// Vertices on one plane span no volume, and a mirrored tissue is no
// deformation: the polygon is returned as it is.
TEST(RestSpaceCut, ADegenerateOrInvertedFitLeavesThePolygon) {
  std::vector<Vec3> flat;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) flat.emplace_back(0.5, i / 5.0, j / 5.0);
  std::vector<Vec3> moved;
  for (const Vec3& p : flat) moved.push_back(p + Vec3(0.1, 0, 0));
  const cut::CutPolygon square = rest_square();
  EXPECT_EQ(farthest_corner(rest_space_polygon(square, flat, moved), square), 0.0);

  const std::vector<Vec3> rest = grid(5);
  std::vector<Vec3> mirrored;
  for (const Vec3& p : rest) mirrored.emplace_back(p.x(), 1.0 - p.y(), p.z());
  EXPECT_EQ(farthest_corner(rest_space_polygon(square, rest, mirrored, {.reach = 10.0}), square), 0.0);
}

}  // namespace
}  // namespace mtcut::sim
