#pragma once
// One symplectic Euler sub-step in a single pass over the springs.
//
// Why one pass. The springs are sorted by their first particle a, with
// a < b (build_spring_model's order). Every spring touching particle i is
// then either in i's run or in the run of an earlier particle, and no spring
// after i's run reads x_i or v_i. So when the pass reaches the end of i's
// run, i's force is complete and i can be integrated and pushed out of
// contacts at once. The springs of i's run hand their reaction to their
// second ends through `acc`, which each particle takes and zeroes in its
// turn. It is symplectic Euler exactly (every force at the sub-step's
// start), in one sweep where the plain form takes three (forces cleared,
// springs, integration), with each particle's own force summed in
// registers. A run's springs go two by two through the two lanes of an SSE2
// register (RunPairs), so one square root and one division serve two
// springs.

#include <cstdint>
#include <vector>

#include "sim/environment.h"
#include "sim/spring_model.h"
#include "sim/spring_pairs.h"
#include "sim/spring_state.h"

namespace mtcut::sim {

// The springs are sorted by first particle and each has a < b < n: the
// one-pass sub-step applies.
bool springs_in_run_order(const SpringModel& model);

// Two springs of a run, lane by lane.
struct SpringPair {
  Lanes2 stiffness, stiffness_rest, damping;  // k (N/m), k L (N), c (N s/m); 0 in a pad lane
};

// Each particle's run of springs in pairs, padded to an even count with a
// zero spring to the particle itself (it adds exactly 0). Filled from the
// model at every step (O(n_springs), next to the step's sub-steps), so it
// can never be stale; no allocation once the sizes are reached.
struct RunPairs {
  std::vector<std::int32_t> start;  // (n_particles + 1) particle i's pairs: [start[i], start[i + 1])
  std::vector<std::int32_t> other;  // (2 n_pairs) each lane's second particle
  std::vector<SpringPair> springs;  // (n_pairs)

  // Requires springs_in_run_order(model).
  void fill(const SpringModel& model);
};

// Advances `state` by h (v += h f / m, x += h v), then, when `contacts`,
// pushes free particles out of the floor and the tool; fixed particles keep
// v = 0. `acc` (n_particles) must be all zero on entry; it is left so.
// Requires springs_in_run_order(model).
// `pairs` filled from `model`.
void symplectic_substep(const SpringModel& model, const RunPairs& pairs, const Environment& env, bool contacts,
                        double h, SpringState& state, std::vector<Vec3>& acc);

}  // namespace mtcut::sim
