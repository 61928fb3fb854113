#include "engine/mt/segment_distance.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/engine/mt/random_box.h"

namespace mtcut::engine {
namespace {

using mtcut::test::random_box;

Segment random_segment(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  return {Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng))};
}

Vec3 at(const Segment& s, double t) { return s.a + t * (s.b - s.a); }

// The box's distance to the segment by golden-section search over the
// parameter (the distance to a convex set is convex along a line), with
// no knowledge of the box's slabs.
double searched_min_distance(const Aabb& box, const Segment& s) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double m1 = hi - ratio * (hi - lo), m2 = lo + ratio * (hi - lo);
    if (box.min_distance(at(s, m1)) <= box.min_distance(at(s, m2))) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  return std::min({box.min_distance(s.a), box.min_distance(s.b), box.min_distance(at(s, 0.5 * (lo + hi)))});
}

TEST(SegmentDistance, NearestDistanceIsTheSearchedOne) {
  std::mt19937 rng(3);
  for (int i = 0; i < 2000; ++i) {
    const Aabb box = random_box(rng, i % 2 ? 0.5 : 0.01);
    const Segment s = random_segment(rng);
    const double searched = searched_min_distance(box, s);
    EXPECT_NEAR(min_distance(box, s), searched, 1e-9) << i;
  }
}

TEST(SegmentDistance, ASegmentThroughTheBoxIsAtDistanceZero) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> t(0.0, 1.0), u(-3.0, 3.0);
  for (int i = 0; i < 500; ++i) {
    const Aabb box = random_box(rng, 0.5);
    const Vec3 inside = box.lo + (box.hi - box.lo).cwiseProduct(Vec3(t(rng), t(rng), t(rng)));
    const Vec3 direction(u(rng), u(rng), u(rng));
    const Segment s{inside - t(rng) * direction, inside + t(rng) * direction};
    EXPECT_EQ(min_distance(box, s), 0.0) << i;
  }
}

TEST(SegmentDistance, APointSegmentGivesThePointDistancesBits) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 500; ++i) {
    const Aabb box = random_box(rng, 0.5);
    const Vec3 p(u(rng), u(rng), u(rng));
    EXPECT_EQ(min_distance(box, Segment::point(p)), box.min_distance(p));
    EXPECT_NEAR(max_distance(box, Segment::point(p)), box.max_distance(p), 1e-15);
  }
}

TEST(SegmentDistance, DistanceToAPointIsTheNearestSegmentPoints) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 300; ++i) {
    const Segment s = random_segment(rng);
    const Vec3 p(u(rng), u(rng), u(rng));
    double sampled = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 20000; ++k) sampled = std::min(sampled, (at(s, k / 20000.0) - p).norm());
    EXPECT_LE(distance(s, p), sampled + 1e-15);
    EXPECT_GT(distance(s, p), sampled - 1e-3 * (s.b - s.a).norm());
  }
}

// The farthest distance bounds every point of the box, and a box inside
// another is never nearer than it nor farther: the bounds selective
// refinement prunes with (up to its margin for rounding).
TEST(SegmentDistance, DistancesBoundEveryPointAndInnerBox) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> t(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Aabb box = random_box(rng, 0.5);
    const Segment s = random_segment(rng);
    const double near = min_distance(box, s), far = max_distance(box, s);
    for (int k = 0; k < 20; ++k) {
      const Vec3 q = box.lo + (box.hi - box.lo).cwiseProduct(Vec3(t(rng), t(rng), t(rng)));
      EXPECT_LE(near, distance(s, q) + 1e-12);
      EXPECT_GE(far, distance(s, q) - 1e-12);
    }
    Aabb inner;
    inner.extend(box.lo + t(rng) * (box.hi - box.lo));
    inner.extend(box.lo + t(rng) * (box.hi - box.lo));
    EXPECT_LE(near, min_distance(inner, s) + 1e-12);
    EXPECT_GE(far, max_distance(inner, s) - 1e-12);
  }
}

}  // namespace
}  // namespace mtcut::engine
