#pragma once
// Contact of one free particle with the floor and the tool (the per-particle
// part of apply_contacts, shared with the one-pass explicit sub-step).

#include "sim/environment.h"

namespace mtcut::sim {

// Pushes the particle at x out of the floor and the tool's capsule, removing
// the velocity that points into them (and the floor's friction share of the
// tangential one). For a free particle only: fixed ones are not moved.
void push_out_of_contacts(const Environment& env, Vec3& x, Vec3& v);

}  // namespace mtcut::sim
