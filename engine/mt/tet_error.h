#pragma once
// The error of a tetrahedron in the MT, and the measures the simplifier uses.
//
// Error (paper, section 3.1: "proportional to its volume and/or the radius of
// the smallest sphere containing it"). mtcut uses the radius alone:
//
//     e(t) = R(t),  R(t) = radius of the smallest sphere enclosing t's corners
//
// in the units of the positions (metres). A length, so that the selective
// refinement threshold can grow with the distance from the scalpel and be
// compared with it directly; it grows with the size of the tet, is zero only
// for a point, and (unlike the volume) does not call a long sliver "fine".
// A fragment's error is the largest error of the tets it creates.

#include "engine/predicates.h"

namespace mtcut::engine {

// R(t): the closed-form smallest enclosing sphere of four points (the longest
// edge's diametral sphere, a face's circumcircle or the circumsphere, the
// smallest one that holds all four). Same value as min_enclosing_radius in
// tet_geometry.h, without allocation: the builder calls it millions of times.
double enclosing_radius(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// e(t) as stored in the MT.
inline float tet_error(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return static_cast<float>(enclosing_radius(a, b, c, d));
}

// Shape quality 6 sqrt(2) V / L^3, L the longest edge: 1 for the regular tet,
// near 0 for slivers and needles; negative for inverted tets. Cheap guard
// against collapses that would make degenerate springs.
double tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Euclidean distance from p to the triangle (a, b, c).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace mtcut::engine
