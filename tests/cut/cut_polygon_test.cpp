// CutPolygon's box tests, which prune the cut's search: a box it rejects as
// off the plane must hold no point on the plane or across it, one it
// accepts as projecting inside no point projecting outside; where a
// segment last lies inside the polygon; its edges by their ends.
#include "cut/cut_polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/input_error.h"

namespace mtcut::cut {
namespace {

using engine::Aabb;

// A random point of the box grown by `slack`, corners included.
Vec3 point_in(const Aabb& box, double slack, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  std::bernoulli_distribution corner(0.3);
  Vec3 p;
  for (int k = 0; k < 3; ++k) {
    const double lo = box.lo[k] - slack, hi = box.hi[k] + slack;
    p[k] = corner(rng) ? (u(rng) < 0.5 ? lo : hi) : lo + u(rng) * (hi - lo);
  }
  return p;
}

TEST(CutPolygon, BoxesAwayFromThePlaneLieOnOneSide) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-1, 1), size(0, 0.4), slack_of(0, 0.05);
  std::size_t rejected = 0, kept = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 c(coord(rng), coord(rng), coord(rng));
    const Vec3 a = Vec3(coord(rng), coord(rng), coord(rng)).normalized();
    const Vec3 b = a.cross(Vec3(coord(rng), coord(rng), coord(rng))).normalized();
    const double h = 0.2 + size(rng);
    const CutPolygon polygon =
        CutPolygon::from_points({c + h * (a + b), c + h * (b - a), c - h * (a + b), c + h * (a - b)});
    Aabb box;
    box.extend(Vec3(coord(rng), coord(rng), coord(rng)));
    box.extend(Vec3(box.lo + Vec3(size(rng), size(rng), size(rng))));
    const double slack = trial % 2 ? slack_of(rng) : 0.0;
    if (polygon.box_may_touch_plane(box, slack)) {
      ++kept;
      continue;
    }
    ++rejected;
    const int side = polygon.side(box.lo - Vec3::Constant(slack));
    ASSERT_NE(side, 0) << trial;
    for (int i = 0; i < 50; ++i) ASSERT_EQ(polygon.side(point_in(box, slack, rng)), side) << trial;
  }
  // Both outcomes are exercised.
  EXPECT_GT(rejected, 200u);
  EXPECT_GT(kept, 200u);
}

// A box box_projects_inside accepts has every point projecting strictly
// inside (the exact projects_inside); one that holds a point projecting
// onto or outside the outline is never accepted.
TEST(CutPolygon, BoxesThatProjectInsideHoldNoPointOutside) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> coord(-1, 1), size(0, 0.6), slack_of(0, 0.05);
  std::size_t accepted = 0, refused = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a = Vec3(coord(rng), coord(rng), coord(rng)).normalized();
    const Vec3 b = a.cross(Vec3(coord(rng), coord(rng), coord(rng))).normalized();
    const double h = 0.5 + size(rng);
    const CutPolygon polygon = CutPolygon::from_points({h * (a + b), h * (b - a), -h * (a + b), h * (a - b)});
    Aabb box;
    box.extend(Vec3(coord(rng), coord(rng), coord(rng)) * 0.6);
    box.extend(Vec3(box.lo + Vec3(size(rng), size(rng), size(rng)) * 0.5));
    const double slack = trial % 2 ? slack_of(rng) : 0.0;
    bool outside = false;  // a sampled point projects onto or outside the outline
    for (int i = 0; i < 50 && !outside; ++i) outside = polygon.projects_inside(point_in(box, slack, rng)) <= 0;
    if (!polygon.box_projects_inside(box, slack)) {
      ++refused;
      continue;
    }
    ++accepted;
    ASSERT_FALSE(outside) << trial;
  }
  EXPECT_GT(accepted, 200u);
  EXPECT_GT(refused, 200u);
  // A box reaching past the outline, or empty, is refused; a tall box over
  // the inside (its section projects inside) is accepted.
  const CutPolygon square = CutPolygon::from_points({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  EXPECT_TRUE(square.box_projects_inside(Aabb{Vec3(0.2, 0.2, -5), Vec3(0.8, 0.8, 5)}));
  EXPECT_FALSE(square.box_projects_inside(Aabb{Vec3(0.2, 0.2, -5), Vec3(1.0, 0.8, 5)}));  // onto the outline
  EXPECT_FALSE(square.box_projects_inside(Aabb{Vec3(0.2, 0.2, 0), Vec3(0.8, 0.8, 0)}, 0.25));  // its slack reaches out
  EXPECT_FALSE(square.box_projects_inside(Aabb{}));
}

TEST(CutPolygon, BoxesAcrossOrOnThePlaneAreKept) {
  const CutPolygon polygon =
      CutPolygon::from_points({Vec3(0, 0, 0.5), Vec3(1, 0, 0.5), Vec3(1, 1, 0.5), Vec3(0, 1, 0.5)});
  Aabb across{Vec3(3, 3, 0.4), Vec3(4, 4, 0.6)};  // beyond the outline: the plane is what counts
  EXPECT_TRUE(polygon.box_may_touch_plane(across));
  Aabb touching{Vec3(0, 0, 0.5), Vec3(1, 1, 0.7)};
  EXPECT_TRUE(polygon.box_may_touch_plane(touching));
  Aabb above{Vec3(0, 0, 0.6), Vec3(1, 1, 0.7)};
  EXPECT_FALSE(polygon.box_may_touch_plane(above));
  EXPECT_TRUE(polygon.box_may_touch_plane(above, 0.1));  // its points may move down onto the plane
  EXPECT_FALSE(polygon.box_may_touch_plane(Aabb{}));     // empty
}

// The unit square in z = 0, counter-clockwise seen from +z: edges 0 (y = 0),
// 1 (x = 1), 2 (y = 1), 3 (x = 0).
CutPolygon unit_square() {
  return CutPolygon::from_points({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)});
}

TEST(CutPolygon, LastInsideParameterIsWhereTheSegmentLeavesWhereverItStarts) {
  const CutPolygon square = unit_square();
  int edge = -2;
  // From inside: what exit_parameter says, and the edge it leaves through.
  EXPECT_NEAR(square.last_inside_parameter(Vec3(0.5, 0.5, 0.3), Vec3(1.5, 0.5, -0.2), &edge), 0.5, 1e-12);
  EXPECT_NEAR(square.exit_parameter(Vec3(0.5, 0.5, 0.3), Vec3(1.5, 0.5, -0.2)), 0.5, 1e-12);
  EXPECT_EQ(edge, 1);
  // From outside, through the square: where it leaves, not 0.
  EXPECT_NEAR(square.last_inside_parameter(Vec3(-1, 0.5, 0), Vec3(2, 0.5, 0), &edge), 2.0 / 3, 1e-12);
  EXPECT_EQ(square.exit_parameter(Vec3(-1, 0.5, 0), Vec3(2, 0.5, 0)), 0.0);
  EXPECT_EQ(edge, 1);
  EXPECT_NEAR(square.last_inside_parameter(Vec3(0.5, -1, 0), Vec3(0.5, 3, 0), &edge), 0.5, 1e-12);
  EXPECT_EQ(edge, 2);  // from below, out through y = 1
  // Ending inside: 1, through no edge.
  EXPECT_EQ(square.last_inside_parameter(Vec3(-1, 0.5, 0), Vec3(0.5, 0.5, 0), &edge), 1.0);
  EXPECT_EQ(edge, -1);
  // Missing it: 0.
  EXPECT_EQ(square.last_inside_parameter(Vec3(-1, 2, 0), Vec3(2, 2.5, 0), &edge), 0.0);
  EXPECT_EQ(edge, -1);
}

// The filtered segment test gives line_crossing's exact answer on segments
// built to be hard for it: crossing points at every distance from the
// outline down to rounding, corners, segments nearly in the plane, and a
// polygon far from the origin.
TEST(CutPolygon, SegmentCrossingAgreesWithTheExactPredicate) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 1), sym(-1, 1);
  const Vec3 far(1234.5, -987.25, 401.125);
  const std::vector<CutPolygon> polygons = {
      CutPolygon::from_points({Vec3(-1, -1, 0.125), Vec3(1, -1, 0.25), Vec3(1, 1, 0.375), Vec3(-1, 1, 0.25)}),
      CutPolygon::from_points({Vec3(0, 0, 0), Vec3(0.75, 0.125, 0.25), Vec3(0.25, 0.875, -0.5)}),
      CutPolygon::from_points({far + Vec3(0, 0, 0), far + Vec3(2, 0, 1), far + Vec3(2, 3, 1), far + Vec3(0, 3, 0)})};
  std::size_t on_outline = 0, inside = 0, outside = 0;
  for (const CutPolygon& polygon : polygons) {
    const auto& c = polygon.corners();
    const double d = polygon.diameter();
    for (int k = 0; k < 20000; ++k) {
      // The crossing point: inside, on or near an edge or a corner, or outside.
      const std::size_t i = rng() % c.size();
      const Vec3 on_edge = c[i] + u(rng) * (c[(i + 1) % c.size()] - c[i]);
      const Vec3 centre = (c[0] + c[1] + c[2]) / 3.0;
      Vec3 x;
      switch (k % 4) {
        case 0: x = centre + u(rng) * (on_edge - centre); break;
        case 1: x = on_edge + std::pow(10.0, -16 * u(rng)) * d * sym(rng) * (on_edge - centre).normalized(); break;
        case 2: x = c[i]; break;
        default: x = centre + (1 + 2 * u(rng)) * (on_edge - centre); break;
      }
      // Through it, a direction tilted off the plane by 1 down to 1e-12;
      // through a corner, exactly: dyadic corners and offsets add exactly.
      Vec3 along(sym(rng), sym(rng), sym(rng));
      along -= along.dot(polygon.normal()) * polygon.normal();
      const Vec3 dir = along + std::pow(10.0, -12 * u(rng)) * polygon.normal();
      Vec3 a = x + (0.01 + 2 * u(rng)) * d * dir, b = x - (0.01 + 2 * u(rng)) * d * dir;
      if (k % 4 == 2) {
        const Vec3 offset = Vec3(std::ldexp(std::round(64 * sym(rng)), -6), std::ldexp(std::round(64 * sym(rng)), -6),
                                 std::ldexp(1 + std::round(64 * u(rng)), -6));
        a = x + offset;
        b = x - offset;
      }
      const int exact = polygon.line_crossing(a, b);
      ASSERT_EQ(polygon.segment_crossing(a, b, polygon.signed_distance(a), polygon.signed_distance(b)), exact)
          << "polygon " << &polygon - polygons.data() << " case " << k;
      (exact == 0 ? on_outline : exact > 0 ? inside : outside) += 1;
    }
  }
  // Every kind of answer was asked for.
  EXPECT_GT(on_outline, 100u);
  EXPECT_GT(inside, 1000u);
  EXPECT_GT(outside, 1000u);
}

TEST(CutPolygon, EdgeBetweenFindsAnOutlineEdgeByItsEnds) {
  const CutPolygon square = unit_square();
  EXPECT_EQ(square.edge_between(Vec3(1, 0, 0), Vec3(1, 1, 0)), 1);
  EXPECT_EQ(square.edge_between(Vec3(1, 1, 0), Vec3(1, 0, 0)), 1);  // either order
  EXPECT_EQ(square.edge_between(Vec3(0, 1, 0), Vec3(0, 0, 0)), 3);
  EXPECT_EQ(square.edge_between(Vec3(0, 0, 0), Vec3(1, 1, 0)), -1);  // a diagonal
  EXPECT_EQ(square.edge_between(Vec3(1, 0, 1e-6), Vec3(1, 1, 0)), -1);  // beyond 1e-9 of the diameter
}

// A polygon put on another's plane decides every side with that plane's
// frozen corners (the same exact answers), lies on it, and is ordered
// counter-clockwise about its normal whichever order its corners came in.
TEST(CutPolygon, OnPlaneOfKeepsThePlaneBitForBit) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 p0(0.1, 0.2, 0.3), e0(1.0, 0.05, 0.01), e1(-0.05, 0.9, 0.1);
  const CutPolygon plane = CutPolygon::from_points({p0, p0 + e0, p0 + e0 + e1, p0 + e1});
  for (int round = 0; round < 50; ++round) {
    // A quad near the plane (off it by up to 1e-3), either orientation.
    std::vector<Vec3> points;
    const Vec3 c(u(rng), u(rng), 0.3 + 0.1 * u(rng));
    const Vec3 a = plane.corners()[1] - plane.corners()[0], b = plane.corners()[3] - plane.corners()[0];
    for (const auto& [s, t] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}})
      points.push_back(c + s * a + t * b + 1e-3 * u(rng) * plane.normal());
    if (round % 2) std::reverse(points.begin(), points.end());
    const CutPolygon on = CutPolygon::on_plane_of(plane, points);
    EXPECT_TRUE(on.same_plane(plane));
    EXPECT_NEAR(on.normal().dot(plane.normal()), 1.0, 1e-15);
    for (const Vec3& corner : on.corners()) EXPECT_NEAR(plane.signed_distance(corner), 0.0, 1e-14);
    for (int k = 0; k < 20; ++k) {
      const Vec3 x(u(rng), u(rng), u(rng));
      EXPECT_EQ(on.side(x), plane.side(x));
    }
    // Its inside is where the quad is: the centre projects inside.
    EXPECT_EQ(on.projects_inside(c + 0.5 * (a + b)), 1);
  }
  // Corners that collapse onto a line once projected have no area there.
  EXPECT_THROW(CutPolygon::on_plane_of(plane, {Vec3(0, 0, 0), Vec3(0, 0, 0) + plane.normal(),
                                               Vec3(1, 1, 1) - (Vec3(1, 1, 1) - Vec3(0, 0, 0)).dot(plane.normal()) *
                                                                   plane.normal()}),
               engine::InputError);
}

// box_beyond holds every point of a grown polygon that its former one
// does not cover (beyond rounding), and no more than where it grew: a part
// grown at its front only gives a box no wider than the growth across the
// front.
TEST(CutPolygon, BoxBeyondHoldsWhatTheFormerPolygonDoesNotCover) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  std::size_t outside = 0, empty = 0;
  for (int round = 0; round < 300; ++round) {
    const Vec3 p0(u(rng), u(rng), u(rng));
    const Vec3 a = Vec3(u(rng), u(rng), u(rng)).normalized();
    const Vec3 b = a.cross(Vec3(u(rng), u(rng), u(rng))).normalized();
    std::vector<Vec3> points;
    for (int k = 0; k < 3 + round % 5; ++k) points.push_back(p0 + u(rng) * a + u(rng) * b);
    const CutPolygon inner = CutPolygon::on_plane_of(CutPolygon::from_points({p0, p0 + a, p0 + a + b}), points);
    // Grown by a few points (none in a tenth of the rounds).
    std::vector<Vec3> grown = inner.corners();
    if (round % 10 != 0)
      for (int k = 0; k < 1 + round % 3; ++k) grown.push_back(p0 + 1.5 * u(rng) * a + 1.5 * u(rng) * b);
    const CutPolygon outer = CutPolygon::on_plane_of(inner, grown);
    const engine::Aabb box = outer.box_beyond(inner);
    if (box.empty()) ++empty;
    const double tolerance = 1e-9 * outer.diameter();
    // Points of the outer polygon: on its fan's triangles, its corners and edges.
    const std::vector<Vec3>& c = outer.corners();
    for (int k = 0; k < 400; ++k) {
      const std::size_t i = 1 + static_cast<std::size_t>(w(rng) * static_cast<double>(c.size() - 2)) % (c.size() - 2);
      double s = w(rng), t = w(rng);
      if (s + t > 1) s = 1 - s, t = 1 - t;
      if (k % 4 == 0) t = 0;  // on an edge from the first corner
      const Vec3 x = c[0] + s * (c[i] - c[0]) + t * (c[i + 1] - c[0]);
      if (inner.distance_outside(x) <= 1e-6 * outer.diameter()) continue;  // covered, up to rounding
      ++outside;
      for (int d = 0; d < 3; ++d) {
        ASSERT_GE(x[d], box.lo[d] - tolerance) << round;
        ASSERT_LE(x[d], box.hi[d] + tolerance) << round;
      }
    }
  }
  EXPECT_GT(outside, 10000u);
  EXPECT_GT(empty, 20u);  // the rounds that did not grow, and some whose points fell inside

  // A rectangle grown at its front: the box spans the growth across the
  // front, not the edges the two share; the former rectangle facing either
  // way (its corners run clockwise in the grown one's frame when reversed).
  const CutPolygon before = CutPolygon::from_points({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const CutPolygon before_reversed = CutPolygon::from_points({{0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {0, 0, 0}});
  for (const CutPolygon* former : {&before, &before_reversed}) {
    const std::vector<Vec3> corners{{0, 0, 0}, {1.1, 0, 0}, {1.1, 1, 0}, {0, 1, 0}};
    const engine::Aabb front = CutPolygon::from_points(corners).box_beyond(*former);
    EXPECT_NEAR(front.lo.x(), 1.0, 1e-12);
    EXPECT_NEAR(front.hi.x(), 1.1, 1e-12);
    EXPECT_NEAR(front.lo.y(), 0.0, 1e-12);
    EXPECT_NEAR(front.hi.y(), 1.0, 1e-12);
  }
  EXPECT_TRUE(before.box_beyond(before).empty());
  EXPECT_TRUE(before.box_beyond(before_reversed).empty());
}

}  // namespace
}  // namespace mtcut::cut
