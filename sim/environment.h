#pragma once
// What acts on the tissue from outside: gravity, a floor plane that pieces
// land on, and the scalpel's body pushing tissue it touches (a capsule
// around the blade segment; it cuts only through the cutter, never here).

#include <optional>

#include "engine/predicates.h"

namespace mtcut::sim {

using engine::Vec3;

struct Plane {
  Vec3 normal = Vec3(0, 0, 1);  // unit, pointing to the free side
  double offset = 0.0;          // points x with normal . x >= offset are free
};

struct Capsule {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();  // segment ends (blade base, tip)
  double radius = 0.0;                      // m; 0 disables contact
};

struct Environment {
  Vec3 gravity = Vec3(0, 0, -9.81);  // m/s^2
  std::optional<Plane> floor;        // none = no floor
  double floor_friction = 0.5;       // share of tangential speed removed on contact, 0..1
  std::optional<Capsule> tool;       // the scalpel's body, when it pushes
};

}  // namespace mtcut::sim
