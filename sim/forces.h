#pragma once
// Forces and energies of the spring model, shared by both integrators and by
// the tests that check them.

#include <vector>

#include "sim/environment.h"
#include "sim/spring_model.h"
#include "sim/spring_state.h"

namespace mtcut::sim {

// f = spring forces (Hooke + dashpot along the spring) + volume terms
// + gravity + air drag. `f` is resized to n_particles and overwritten.
void compute_forces(const SpringModel& model, const Environment& env, const SpringState& state,
                    std::vector<Vec3>& f);

// f = gravity + air drag + volume terms: every force but the springs'.
// `f` is resized to n_particles and overwritten.
void compute_body_forces(const SpringModel& model, const Environment& env, const SpringState& state,
                         std::vector<Vec3>& f);

// Adds the volume-preserving forces of the tets (model.tet_particles) to f
// (n_particles): -volume_modulus (V - V0) / V0 dV/dx_i.
void add_volume_forces(const SpringModel& model, const SpringState& state, std::vector<Vec3>& f);

// Kinetic + elastic (springs and volume terms) + gravitational potential.
double total_energy(const SpringModel& model, const Environment& env, const SpringState& state);

// Sum of m v.
Vec3 linear_momentum(const SpringModel& model, const SpringState& state);

// The largest time step symplectic Euler is stable at, estimated per
// particle from its springs' summed stiffness and damping (dashpots shrink
// it: stiffness-proportional damping makes explicit steps very small).
double critical_time_step(const SpringModel& model);

// A state at rest in the rest shape.
SpringState rest_state(const SpringModel& model);

}  // namespace mtcut::sim
