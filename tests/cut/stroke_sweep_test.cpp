#include "cut/stroke_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace mtcut::cut {
namespace {

// Area of a planar convex polygon (fan from its first corner).
double area(const CutPolygon& p) {
  double a = 0;
  const auto& c = p.corners();
  for (std::size_t i = 1; i + 1 < c.size(); ++i) a += 0.5 * (c[i] - c[0]).cross(c[i + 1] - c[0]).norm();
  return a;
}

// Pose counts of one stroke: a frame's pose at 60 Hz, and a haptic stylus's
// at 1 kHz (thousands per part, which the part's plane and hull follow
// incrementally: stroke_sweep.h).
constexpr int kPoseCounts[] = {60, 2000};

TEST(StrokeSweep, StraightStrokeIsOnePolygonCoveringEverySweep) {
  for (int poses : kPoseCounts) {
    SCOPED_TRACE(std::to_string(poses) + " poses");
    StrokeSweep stroke;
    // A vertical blade drawn along y with rounding noise in x, as a keyframed
    // path interpolated over the poses gives.
    for (int f = 0; f <= poses; ++f) {
      const double y = -0.06 + 0.12 * f / poses, noise = (f % 3 - 1) * 1e-17;
      ASSERT_TRUE(stroke.add(Vec3(0.04 + noise, y, 0.06), Vec3(0.04, y, -0.045)).empty()) << "pose " << f;
    }
    EXPECT_TRUE(stroke.active());
    const auto polygons = stroke.finish();
    EXPECT_FALSE(stroke.active());
    ASSERT_EQ(polygons.size(), 1u);
    EXPECT_EQ(polygons[0].size(), 4u);
    EXPECT_NEAR(area(polygons[0]), 0.12 * 0.105, 1e-12);
    EXPECT_NEAR(std::abs(polygons[0].normal().x()), 1.0, 1e-12);
    for (const Vec3& c : polygons[0].corners()) {
      EXPECT_NEAR(c.x(), 0.04, 1e-12);
      EXPECT_NEAR(std::abs(c.y()), 0.06, 1e-12);
    }
  }
}

TEST(StrokeSweep, BladeThatDoesNotMoveCutsNothing) {
  StrokeSweep stroke;
  for (int f = 0; f < 5; ++f) EXPECT_TRUE(stroke.add(Vec3(0, 0, 1), Vec3(0, 0, 0)).empty());
  EXPECT_TRUE(stroke.finish().empty());
  // A plunge (the blade moving along itself) sweeps no area either.
  for (int f = 0; f < 5; ++f) stroke.add(Vec3(0, 0, 1 - 0.1 * f), Vec3(0, 0, -0.1 * f));
  EXPECT_TRUE(stroke.finish().empty());
}

// The polygon among `polygons` nearest x: its plane's distance when x
// projects inside it, else infinity.
double distance_to_cut(const std::vector<CutPolygon>& polygons, const Vec3& x) {
  double best = std::numeric_limits<double>::infinity();
  for (const CutPolygon& p : polygons)
    if (p.projects_inside(x) >= 0) best = std::min(best, std::abs(p.signed_distance(x)));
  return best;
}

TEST(StrokeSweep, TurnEndsThePartAndTheNextOverlapsIt) {
  StrokeSweep stroke;
  // Along +y in the plane x = 0, then along +x in the plane y = 1.
  for (int f = 0; f <= 10; ++f) EXPECT_TRUE(stroke.add(Vec3(0, 0.1 * f, 1), Vec3(0, 0.1 * f, 0)).empty());
  std::vector<CutPolygon> polygons = stroke.add(Vec3(0.1, 1.0, 1), Vec3(0.1, 1.0, 0));
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_NEAR(area(polygons[0]), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(polygons[0].normal().x()), 1.0, 1e-12);
  // The part in progress starts half a sweep back (y = 0.95), then the
  // first part's last pose, then the new one.
  ASSERT_TRUE(stroke.current().has_value());
  EXPECT_EQ(stroke.part_poses(), 3u);
  for (int f = 2; f <= 10; ++f)
    for (auto& p : stroke.add(Vec3(0.1 * f, 1.0, 1), Vec3(0.1 * f, 1.0, 0))) polygons.push_back(std::move(p));
  for (auto& p : stroke.finish()) polygons.push_back(std::move(p));
  EXPECT_FALSE(stroke.current().has_value());
  // The last part runs along y = 1 to x = 1; the path's every point, the
  // corner too, lies on some polygon (nothing between parts is left uncut).
  EXPECT_NEAR(std::abs(polygons.back().normal().y()), 1.0, 1e-3);
  for (int i = 0; i <= 40; ++i) {
    const double s = i / 20.0;  // along the L
    const Vec3 x = s <= 1 ? Vec3(0, s, 0.5) : Vec3(s - 1, 1, 0.5);
    EXPECT_LT(distance_to_cut(polygons, x), 1e-3) << "s = " << s;
  }
}

// A blade drawn along y, then pulled out along itself (the liver
// scenario's lift-out): the draw is one polygon, and the lift sweeps no
// area of its own, so it has none (its hull would be the half sweep it
// overlaps the draw by, tissue the draw cut already). Moved across once out,
// the blade makes a part again, overlap and all.
TEST(StrokeSweep, ABladePulledOutAlongItselfAfterATurnCutsNothingMore) {
  for (int poses : kPoseCounts) {
    SCOPED_TRACE(std::to_string(poses) + " poses");
    StrokeSweep stroke;
    std::vector<CutPolygon> polygons;
    const auto add = [&](const Vec3& base, const Vec3& tip) {
      for (auto& p : stroke.add(base, tip)) polygons.push_back(std::move(p));
    };
    for (int f = 0; f <= poses; ++f) add(Vec3(0, 0.1 * f / poses, 1), Vec3(0, 0.1 * f / poses, 0));
    ASSERT_TRUE(polygons.empty());
    // The draw's part takes the lift's first poses while its hull stays
    // within hull_excess of what it swept; from the pose that ends it, the
    // lift has no polygon.
    for (int f = 1; f <= poses; ++f) {
      add(Vec3(0, 0.1, 1 + 0.5 * f / poses), Vec3(0, 0.1, 0.5 * f / poses));
      if (!polygons.empty()) {
        EXPECT_FALSE(stroke.current().has_value()) << "lift pose " << f;
      }
    }
    ASSERT_EQ(polygons.size(), 1u);
    EXPECT_GE(area(polygons[0]), 0.1 - 1e-12);
    EXPECT_LE(area(polygons[0]), 0.1 * (1 + StrokeSweepDef{}.hull_excess));
    for (auto& p : stroke.finish()) polygons.push_back(std::move(p));
    EXPECT_EQ(polygons.size(), 1u) << "the lift has a polygon of its own";

    // The same lift, then a move across: that part is cut.
    StrokeSweep moved;
    for (int f = 0; f <= poses; ++f) moved.add(Vec3(0, 0.1 * f / poses, 1), Vec3(0, 0.1 * f / poses, 0));
    for (int f = 1; f <= poses; ++f) moved.add(Vec3(0, 0.1, 1 + 0.5 * f / poses), Vec3(0, 0.1, 0.5 * f / poses));
    EXPECT_FALSE(moved.current().has_value());
    for (int f = 1; f <= poses; ++f) moved.add(Vec3(0, 0.1 + 0.1 * f / poses, 1.5), Vec3(0, 0.1 + 0.1 * f / poses, 0.5));
    ASSERT_TRUE(moved.current().has_value());
    EXPECT_GT(area(*moved.current()), 0.09);
  }
}

// Parts with little or no area of their own: the blade drawn along +y is
// lifted while it drifts on, lifted straight (the draw's part ends: its
// hull grows, its sweep does not), lifted drifting a fiftieth as far, and
// moved along +x out of the plane. A part has no polygon while its own
// sweeps are under hull_excess of its overlap, and none at all if it ends
// so, yet every point the blade swept lies on some polygon.
TEST(StrokeSweep, PartsWithLittleAreaOfTheirOwnLeaveNoSweepUncut) {
  const auto blade = [](double x, double y, double lift) {
    return std::pair<Vec3, Vec3>(Vec3(x, y, 1 + lift), Vec3(x, y, lift));
  };
  std::vector<std::pair<Vec3, Vec3>> poses;
  for (int f = 0; f <= 10; ++f) poses.push_back(blade(0, 0.1 * f, 0));
  for (const auto& b : {blade(0, 1.02, 0.05), blade(0, 1.02, 0.15), blade(0, 1.0202, 0.25), blade(0, 1.0204, 0.35),
                        blade(0.05, 1.0204, 0.35), blade(0.1, 1.0204, 0.35)})
    poses.push_back(b);
  StrokeSweep stroke;
  std::vector<CutPolygon> polygons;
  for (const auto& [base, tip] : poses)
    for (auto& p : stroke.add(base, tip)) polygons.push_back(std::move(p));
  for (auto& p : stroke.finish()) polygons.push_back(std::move(p));
  ASSERT_FALSE(polygons.empty());
  for (std::size_t i = 0; i + 1 < poses.size(); ++i)
    for (int a = 1; a < 8; ++a)  // inside the sweep: its outline is a polygon's to rounding
      for (int b = 1; b < 8; ++b) {
        const double s = a / 8.0, t = b / 8.0;
        const Vec3 base = (1 - s) * poses[i].first + s * poses[i + 1].first;
        const Vec3 tip = (1 - s) * poses[i].second + s * poses[i + 1].second;
        const Vec3 x = (1 - t) * base + t * tip;
        EXPECT_LT(distance_to_cut(polygons, x), 1e-3) << "sweep " << i << " at " << s << ", " << t;
      }
}

TEST(StrokeSweep, APartThatEndsWhereTheBladeTurnsBackSaysSo) {
  // A vertical blade along +y, then turning by `degrees` in xy (a frame of
  // five poses at a time): the first part ends at the turn, flagged turned
  // back exactly when the heading turned by more than 120 degrees (a V's
  // planes are closer than an L's); the stroke's last part, ended by the
  // blade lifting, is not.
  for (const double degrees : {30.0, 60.0, 100.0, 115.0, 125.0, 140.0, 150.0, 170.0, -150.0}) {
    SCOPED_TRACE(std::to_string(degrees) + " degrees");
    const double a = degrees * std::acos(-1.0) / 180;
    const Vec3 along(std::sin(a), std::cos(a), 0);
    std::vector<BladePose> path;
    for (int f = 0; f <= 10; ++f) path.push_back({Vec3(0, 0.1 * f, 1), Vec3(0, 0.1 * f, 0), true});
    for (int f = 1; f <= 10; ++f) {
      const Vec3 at = Vec3(0, 1, 0) + 0.1 * f * along;
      path.push_back({at + Vec3(0, 0, 1), at, true});
    }
    path.push_back({path.back().base, path.back().tip, false});
    StrokeSweep stroke;
    std::vector<std::uint8_t> flags;
    std::size_t ended = 0;
    for (std::size_t k = 0; k < path.size(); k += 5) {
      const std::size_t n = std::min<std::size_t>(5, path.size() - k);
      const StrokeAdvance advance = stroke.advance(std::span(path).subspan(k, n));
      ASSERT_EQ(advance.turned_back.size(), advance.ended.size());
      flags.insert(flags.end(), advance.turned_back.begin(), advance.turned_back.end());
      ended += advance.ended.size();
    }
    ASSERT_GE(flags.size(), 2u);
    EXPECT_EQ(flags.front(), std::abs(degrees) > 120 ? 1 : 0);
    EXPECT_EQ(flags.back(), 0);
  }
}

TEST(StrokeSweep, CurvedStrokeInOnePlaneIsSplitWhereItStopsBeingConvex) {
  for (int poses : kPoseCounts) {
    SCOPED_TRACE(std::to_string(poses) + " poses");
    StrokeSweep stroke;
    // A short blade along a half circle in the plane z = 0: the hull of the
    // whole arc would cut far more than the blade swept.
    std::size_t parts = 0;
    double cut_area = 0;
    for (int f = 0; f <= poses; ++f) {
      const double a = 3.14159 * f / poses;
      const Vec3 dir(std::cos(a), std::sin(a), 0);
      for (const auto& p : stroke.add(0.9 * dir, 1.1 * dir)) ++parts, cut_area += area(p);
    }
    for (const auto& p : stroke.finish()) ++parts, cut_area += area(p);
    EXPECT_GT(parts, 1u);
    // Each part after the first overlaps the last by half a sweep, and its
    // hull exceeds its sweeps by at most hull_excess.
    const double swept = 0.5 * 3.14159 * (1.1 * 1.1 - 0.9 * 0.9);
    EXPECT_LT(cut_area, 1.05 * swept * (1.0 + 0.5 * static_cast<double>(parts) / poses));
    EXPECT_GT(cut_area, 0.7 * swept);
  }
}

TEST(StrokeSweep, TurnOutOfThePlaneEndsThePartWhereverThePoseRate) {
  for (int poses : kPoseCounts) {
    SCOPED_TRACE(std::to_string(poses) + " poses");
    StrokeSweep turning;
    for (int f = 0; f <= poses; ++f)
      ASSERT_TRUE(turning.add(Vec3(0, 1.0 * f / poses, 1), Vec3(0, 1.0 * f / poses, 0)).empty()) << "pose " << f;
    std::size_t ended_at = 0;
    for (int f = 1; f <= poses && ended_at == 0; ++f)
      if (!turning.add(Vec3(1.0 * f / poses, 1.0, 1), Vec3(1.0 * f / poses, 1.0, 0)).empty()) ended_at = f;
    // The turned part's poses leave its plane beyond 2% of its diameter
    // (about 1.4) once the blade is ~0.03 along x, at any pose rate.
    EXPECT_GT(ended_at, 0u);
    EXPECT_NEAR(1.0 * ended_at / poses, 0.03, 0.02);
  }
}

TEST(StrokeSweep, SweepAreaOfATranslatedBlade) {
  EXPECT_NEAR(sweep_area(Vec3(0, 0, 0), Vec3(0, 0, 2), Vec3(3, 0, 0), Vec3(3, 0, 2)), 6.0, 1e-12);
  EXPECT_NEAR(sweep_area(Vec3(0, 0, 0), Vec3(0, 0, 2), Vec3(0, 0, 1), Vec3(0, 0, 3)), 0.0, 1e-12);
}

// Once a part's polygon is wide enough its plane is fixed: every later
// polygon of the part is on it, bit for bit, and the part ends where a pose
// leaves it.
TEST(StrokeSweep, APartsPlaneIsFixedOnceItIsWide) {
  StrokeSweep stroke;
  const auto pose = [](int f) {
    const double y = -0.06 + 0.002 * f;
    return std::pair{Vec3(0.04, y, 0.06), Vec3(0.04, y, -0.045)};
  };
  std::optional<CutPolygon> first;
  for (int f = 0; f <= 40; ++f) {
    const auto [base, tip] = pose(f);
    ASSERT_TRUE(stroke.add(base, tip).empty()) << "pose " << f;
    const std::optional<CutPolygon> now = stroke.current();
    if (!stroke.plane_fixed()) {
      EXPECT_LT(f, 10) << "the plane is not fixed after " << f << " poses";
      continue;
    }
    ASSERT_TRUE(now.has_value());
    if (!first) first = now;
    EXPECT_TRUE(now->same_plane(*first)) << "pose " << f;
  }
  ASSERT_TRUE(first.has_value());
  // A pose well off the plane (a tenth of the part's size sideways) ends
  // the part there.
  const auto [base, tip] = pose(41);
  const Vec3 aside(0.1 * (base - pose(0).first).norm(), 0, 0);
  EXPECT_EQ(stroke.add(base + aside, tip + aside).size(), 1u) << "the part did not end as the blade left its plane";
  // The new part, one pose further, is not on the old plane.
  const auto [base2, tip2] = pose(42);
  stroke.add(base2 + aside, tip2 + aside);
  const std::optional<CutPolygon> now = stroke.current();
  ASSERT_TRUE(now.has_value());
  EXPECT_FALSE(now->same_plane(*first));
}

}  // namespace
}  // namespace mtcut::cut
