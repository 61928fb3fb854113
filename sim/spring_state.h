#pragma once
// The mutable state of a step (MuJoCo's mjData): positions and velocities of
// the particles of a SpringModel, in the same order.

#include <vector>

#include "engine/predicates.h"

namespace mtcut::sim {

struct SpringState {
  std::vector<engine::Vec3> x;  // (n_particles) deformed positions, m
  std::vector<engine::Vec3> v;  // (n_particles) velocities, m/s
};

}  // namespace mtcut::sim
