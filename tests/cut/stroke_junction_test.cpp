// StrokeJunction: when a polygon continues another across a shared edge,
// and which side of the junction a point is on.
#include "cut/stroke_junction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mtcut::cut {
namespace {

// A vertical quad of a blade from x = x0 to x = x1 along y = slope * x.
CutPolygon blade_quad(double x0, double x1, double slope0, double slope1) {
  return CutPolygon::from_points(
      {Vec3(x0, slope0 * x0, 1), Vec3(x1, slope1 * x1, 1), Vec3(x1, slope1 * x1, -1), Vec3(x0, slope0 * x0, -1)});
}

TEST(StrokeJunction, AQuadStartingAtTheLastOnesEdgeContinuesIt) {
  const CutPolygon first = blade_quad(0, 1, 0, 0);
  // Turning by ~17 degrees at x = 1 (the second quad leaves y = 0 there).
  const CutPolygon second = CutPolygon::from_points(
      {Vec3(1, 0, 1), Vec3(2, 0.3, 1), Vec3(2, 0.3, -1), Vec3(1, 0, -1)});
  const auto junction = StrokeJunction::between(first, second);
  ASSERT_TRUE(junction.has_value());
  // The second quad is ahead, the first behind, the shared edge (x = 1) on
  // the divider.
  EXPECT_EQ(junction->ahead(Vec3(1.5, 0.15, 0)), 1);
  EXPECT_EQ(junction->ahead(Vec3(0.5, 0, 0)), -1);
  EXPECT_EQ(junction->ahead(Vec3(1, 0, 0.25)), 0);
  // Points just off the junction on either plane's side agree: the divider
  // bisects the angle, so a point above both planes near it is ahead or
  // behind by its position along the stroke only.
  EXPECT_EQ(junction->ahead(Vec3(1.01, 0.2, 0)), 1);
  EXPECT_EQ(junction->ahead(Vec3(0.99, -0.2, 0)), -1);
}

TEST(StrokeJunction, NoJunctionWithoutASharedEdgeOrWhenTheStrokeFoldsBack) {
  const CutPolygon first = blade_quad(0, 1, 0, 0);
  EXPECT_FALSE(StrokeJunction::between(first, blade_quad(1.1, 2, 0, 0)).has_value());  // a gap
  // Folding back: the blade sweeps from x = 1 back to x = 0.5 (corners in
  // blade_quad's order), so the quad faces the other way.
  const CutPolygon back = CutPolygon::from_points(
      {Vec3(1, 0, 1), Vec3(0.5, 0.1, 1), Vec3(0.5, 0.1, -1), Vec3(1, 0, -1)});
  EXPECT_LT(first.normal().dot(back.normal()), 0);
  EXPECT_FALSE(StrokeJunction::between(first, back).has_value());
}

TEST(CutContinuation, APointIsSidedByThePolygonItLiesBehind) {
  // Three quads turning at x = 1 and x = 2; junctions[j] joins quad j to j + 1.
  const CutPolygon q0 = blade_quad(0, 1, 0, 0);
  const CutPolygon q1 = CutPolygon::from_points({Vec3(1, 0, 1), Vec3(2, 0.2, 1), Vec3(2, 0.2, -1), Vec3(1, 0, -1)});
  const CutPolygon q2 = CutPolygon::from_points({Vec3(2, 0.2, 1), Vec3(3, 0.6, 1), Vec3(3, 0.6, -1), Vec3(2, 0.2, -1)});
  const std::vector<StrokeJunction> junctions = {*StrokeJunction::between(q0, q1), *StrokeJunction::between(q1, q2)};
  CutContinuation continuation;
  continuation.junctions = junctions;
  EXPECT_EQ(&continuation.last(), &junctions.back());
  const auto normal_of = [](const CutPolygon& p) { return p.normal(); };
  EXPECT_EQ(normal_of(continuation.polygon_behind(Vec3(1.5, 0.1, 0))), normal_of(q1));
  EXPECT_EQ(normal_of(continuation.polygon_behind(Vec3(0.5, 0, 0))), normal_of(q0));
  EXPECT_EQ(normal_of(continuation.polygon_behind(Vec3(-3, 0, 0))), normal_of(q0));  // behind them all
}

}  // namespace
}  // namespace mtcut::cut
