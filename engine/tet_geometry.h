#pragma once
// Measures of a single tetrahedron given its four corners: volume, dihedral
// angles, radius ratio, enclosing spheres. Free functions over plain points so
// the mesh, the MT and the cutter share one definition.

#include <array>

#include "engine/predicates.h"

namespace mtcut::engine {

// Local numbering of a tet's faces and edges, shared by every module.
// Face i is opposite vertex i, listed so that its normal points out of a
// positively oriented tet.
inline constexpr std::array<std::array<int, 3>, 4> kTetFaces = {{
    {1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
// Edge k = (kTetEdges[k][0], kTetEdges[k][1]); the LUT's e0..e5.
inline constexpr std::array<std::array<int, 2>, 6> kTetEdges = {{
    {0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

// Signed volume: positive when (a, b, c, d) is positively oriented.
double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Barycentric coordinates of p in the tet with corners c (summing to 1;
// some negative when p lies outside: the tet's affine map extended).
std::array<double, 4> barycentric(const std::array<Vec3, 4>& c, const Vec3& p);

// The six interior dihedral angles in radians, in kTetEdges order.
std::array<double, 6> dihedral_angles(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Smallest dihedral angle in degrees (0 for a degenerate tet).
double min_dihedral_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// 3 * inradius / circumradius: 1 for the regular tet, 0 for a degenerate one.
double radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Radius of the smallest sphere containing the four points.
double min_enclosing_radius(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace mtcut::engine
