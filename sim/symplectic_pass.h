#pragma once
// Symplectic Euler sub-steps, each a single pass over the springs.
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
// registers.
//
// Why four lanes and padded particles. The pass is bound by instructions,
// not by memory (the bench box's 10k particles fit in L2): a spring's ends
// were gathered coordinate by coordinate into two-lane registers, and its
// reactions taken apart again. Here each particle is one 32-byte slot
// (x, y, z, 0) that one load reads and one store writes; a run's springs go
// four by four (SpringQuad): their four slots are transposed into x, y and
// z lanes, and one square root and one division serve four springs. A run's
// last one or two springs go as a pair (SpringPair), which wastes fewer
// lanes than a padded quad (93% of the lanes hold a spring on the bench
// box, against 81%). The slots are loaded from the SpringState once per
// step of many sub-steps and stored back after the last.

#include <cstdint>
#include <vector>

#include "sim/environment.h"
#include "sim/lanes2.h"
#include "sim/lanes4.h"
#include "sim/spring_model.h"
#include "sim/spring_state.h"

namespace mtcut::sim {

// The springs are sorted by first particle and each has a < b < n: the
// one-pass sub-step applies.
bool springs_in_run_order(const SpringModel& model);

// Four springs of a run, lane by lane: k (N/m), k L (N), c (N s/m); 0 in a
// pad lane, whose other end is the run's own particle (it adds exactly 0).
struct SpringQuad {
  Lanes4 stiffness, stiffness_rest, damping;
};
static_assert(alignof(SpringQuad) == 32);

// The last one or two springs of a run, as SpringQuad.
struct SpringPair {
  Lanes2 stiffness, stiffness_rest, damping;
};

// Each particle's run of springs: quads, then at most one pair (a run of
// 4q + 1 or 4q + 2 springs ends in a pair, one of 4q + 3 in a padded quad).
// Filled from the model at every step (O(n_springs), next to the step's
// sub-steps), so it can never be stale; no allocation once the sizes are
// reached.
struct RunLanes {
  std::vector<std::int32_t> quad_start;  // (n_particles + 1) particle i's quads: [quad_start[i], quad_start[i + 1])
  std::vector<std::int32_t> quad_other;  // (4 n_quads) each lane's second particle
  std::vector<SpringQuad> quads;
  std::vector<std::int32_t> pair_of;     // (n_particles) particle i's pair, -1 if none
  std::vector<std::int32_t> pair_other;  // (2 n_pairs)
  std::vector<SpringPair> pairs;

  // Requires springs_in_run_order(model).
  void fill(const SpringModel& model);
};

// The sub-steps' state in slots, and their scratch.
struct PassState {
  std::vector<Slot4> x, v;   // (n_particles)
  std::vector<Slot4> acc;    // (n_particles) reactions handed forward: zeroed per call, zero between sub-steps
  std::vector<Vec3> volume;  // (n_particles) the volume terms' forces (models with them)
};

// Advances `state` by `substeps` sub-steps of h (v += h f / m, x += h v),
// each followed, when `contacts`, by free particles pushed out of the floor
// and the tool; fixed particles keep v = 0. Requires
// springs_in_run_order(model) and `lanes` filled from `model`.
void symplectic_substeps(const SpringModel& model, const RunLanes& lanes, const Environment& env, bool contacts,
                         double h, int substeps, SpringState& state, PassState& scratch);

}  // namespace mtcut::sim
