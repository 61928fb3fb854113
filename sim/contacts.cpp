#include <algorithm>
#include <cmath>
#include <utility>

#include "sim/contacts.h"
#include "sim/stepper.h"

namespace mtcut::sim {
namespace {

// The direction in which p leaves the capsule around [a, b] fastest, and its
// distance to the segment. Beside the segment the direction is radial, with
// the axial part removed exactly (round-off in the closest point must not
// tilt it along the axis); a point on the axis gets some radial direction.
std::pair<Vec3, double> exit_direction(const Vec3& a, const Vec3& b, const Vec3& p) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0.0;
  if (t <= 0 || t >= 1 || len2 == 0) {  // an end cap: spherical
    const Vec3 d = p - (t <= 0 ? a : b);
    const double dist = d.norm();
    return {dist > 0 ? Vec3(d / dist) : Vec3::UnitZ(), dist};
  }
  const Vec3 axis = ab / std::sqrt(len2);
  Vec3 d = (p - a) - (p - a).dot(axis) * axis;
  const double dist = d.norm();
  if (dist > 0) return {d / dist, dist};
  d = axis.cross(std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY());
  return {d.normalized(), 0.0};
}

}  // namespace

void push_out_of_contacts(const Environment& env, Vec3& x, Vec3& v) {
  if (env.floor) {
    const Plane& floor = *env.floor;
    const double depth = floor.normal.dot(x) - floor.offset;
    if (depth < 0) {
      x -= depth * floor.normal;
      const double vn = floor.normal.dot(v);
      Vec3 tangential = v - vn * floor.normal;
      tangential *= 1.0 - env.floor_friction;
      v = tangential + std::max(vn, 0.0) * floor.normal;
    }
  }
  if (env.tool && env.tool->radius > 0) {
    const Capsule& tool = *env.tool;
    const auto [normal, dist] = exit_direction(tool.a, tool.b, x);
    if (dist < tool.radius) {
      x += (tool.radius - dist) * normal;
      const double vn = normal.dot(v);
      if (vn < 0) v -= vn * normal;
    }
  }
}

void apply_contacts(const SpringModel& model, const Environment& env, SpringState& state) {
  const std::size_t n = model.num_particles();
  for (std::size_t i = 0; i < n; ++i) {
    if (model.inv_mass[i] == 0) {
      state.v[i].setZero();
      continue;
    }
    push_out_of_contacts(env, state.x[i], state.v[i]);
  }
}

}  // namespace mtcut::sim
