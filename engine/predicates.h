#pragma once
// Exact geometric predicates (Shewchuk's adaptive arithmetic, as shipped in
// TetGen). Signs follow the right-hand rule used everywhere in mtcut: a tet
// (a, b, c, d) is positive when d lies on the side of the plane (a, b, c)
// towards which (b - a) x (c - a) points.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products are defined here

namespace mtcut::engine {

using Vec3 = Eigen::Vector3d;

// +1, 0 or -1: the exact sign of det[b-a, c-a, d-a] (6 x the signed volume).
int orient3d_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The same determinant, adaptive-exact in sign, approximate in magnitude.
double orient3d_value(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace mtcut::engine
