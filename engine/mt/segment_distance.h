#pragma once
// Distances between an axis-aligned box and a segment: the scalpel's blade
// as the focus of selective refinement (selective_refinement.h), so that
// the tissue along the whole blade is fine, not only around its tip.

#include "engine/mt/bvh.h"

namespace mtcut::engine {

// The segment from a to b (a point when a == b).
struct Segment {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();

  static Segment point(const Vec3& p) { return {p, p}; }
};

// Distance from the segment to the nearest point of the box: the box's
// distance to the segment point nearest it (found between the parameters
// where the segment crosses the box's slab planes, where the squared
// distance is one quadratic of the parameter). For a point (a == b), the
// same bits as box.min_distance(a). It is the distance to a point of the
// segment: within rounding of the exact distance, and not below it but for
// rounding.
double min_distance(const Aabb& box, const Segment& s);
// Distance from the segment to the farthest point of the box (at a
// corner: the distance to a segment is convex). No box inside `box` is
// farther from the segment than this.
double max_distance(const Aabb& box, const Segment& s);
// Distance from p to the nearest point of the segment.
double distance(const Segment& s, const Vec3& p);

}  // namespace mtcut::engine
