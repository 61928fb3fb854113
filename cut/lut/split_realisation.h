#pragma once
// Positions for the labels of a configuration, without any mesh: a tet, a
// plane through it that puts its vertices on the configuration's sides,
// crossings where the plane meets the edges, face points on their section
// segments. Recipes are oriented in the fixed reference realisation and
// checked (by the piece filler and the tests) in random ones, planar or
// "bent" (crossings and face points anywhere on their edges and faces, as
// snapping makes them), so that no tet's orientation depends on where the
// cut points happen to be.

#include <array>
#include <random>

#include "cut/lut/cut_trace.h"

namespace mtcut::cut {

using LabelPositions = std::array<engine::Vec3, kLabelCount>;

// Six times the signed volume of the tet (a, b, c, d), in plain arithmetic:
// the generator evaluates it millions of times, also in debug builds.
inline double volume6(const engine::Vec3& a, const engine::Vec3& b, const engine::Vec3& c, const engine::Vec3& d) {
  const double* pa = a.data();
  const double* pb = b.data();
  const double* pc = c.data();
  const double* pd = d.data();
  const double bx = pb[0] - pa[0], by = pb[1] - pa[1], bz = pb[2] - pa[2];
  const double cx = pc[0] - pa[0], cy = pc[1] - pa[1], cz = pc[2] - pa[2];
  const double dx = pd[0] - pa[0], dy = pd[1] - pa[1], dz = pd[2] - pa[2];
  return bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
}

// The fixed generic realisation: a fixed tet, fixed distances to the plane.
LabelPositions reference_positions(const TetConfig& config, const CutTrace& trace);

// A random realisation: a random tet (not too flat); planar as above with
// random distances (face points at least 0.05 from their segment's ends, as
// the classifier places them), or bent, with parameters often near 0 and 1.
LabelPositions random_positions(const TetConfig& config, const CutTrace& trace, std::mt19937_64& rng, bool planar);

}  // namespace mtcut::cut
