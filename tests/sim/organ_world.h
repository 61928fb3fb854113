#pragma once
// The organ the World's tests cut: the builtin ellipsoid, held at its back
// (x <= -6 cm), simulated finely within 2 cm of the blade; the flap stroke
// through its front end, on a floor that holds it up to the blade.

#include <vector>

#include "sim/scalpel.h"
#include "sim/world_def.h"

namespace mtcut::sim::test {

inline WorldDef organ_def() {
  WorldDef def;
  def.fixed.kind = FixedRegion::Kind::kHalfSpace;  // the back of the organ
  def.fixed.normal = Vec3(1, 0, 0);
  def.fixed.offset = -0.06;
  def.lod.near_radius = 0.02;
  def.lod.near_error = 0.0;
  def.lod.far_radius = 0.06;
  def.lod.far_error = 1.0;
  return def;
}

// A stroke through the front end of the organ (fixed at its back, on a
// floor), from y = -6 cm to +6 cm at x = 4 cm in `seconds`, engaged; then the
// blade disengages where it is.
inline ScalpelPath flap_stroke(double seconds) {
  std::vector<ScalpelKeyframe> keys = {
      {0.0, {Vec3(0.04, -0.06, 0.06), Vec3(0.04, -0.06, -0.07), true}},
      {seconds, {Vec3(0.04, 0.06, 0.06), Vec3(0.04, 0.06, -0.07), true}},
      {seconds + 1e-3, {Vec3(0.04, 0.06, 0.06), Vec3(0.04, 0.06, -0.07), false}}};
  return ScalpelPath(keys);
}

// organ_def() on a floor 5 cm below the organ's centre: without it the
// free front end sags below the blade's reach.
inline WorldDef flap_def() {
  WorldDef def = organ_def();
  def.environment.floor = Plane{Vec3(0, 0, 1), -0.05};
  return def;
}

}  // namespace mtcut::sim::test
