#pragma once
// One simulation step over a constant SpringModel and a mutable SpringState,
// as named stages: save the state, integrate (sub-steps), resolve contacts,
// check. A NaN or an exploding state is detected, counted and reported; the
// step is then refused and the saved state restored, never propagated.
//
// Two integrators:
//  - symplectic Euler, explicit, with sub-steps: the fast baseline, stable
//    for dt below ~ sqrt(m / k) of the stiffest spring; one pass over the
//    springs per sub-step when they are in run order (sim/symplectic_pass.h);
//  - implicit Euler (Baraff & Witkin 1998): one Newton step of the backward
//    Euler equations, (M - h D - h^2 K) dv = h (f + h K v), solved by a
//    matrix-free preconditioned conjugate gradient (sim/spring_system.h:
//    block SSOR by default, block Jacobi on request), warm-started from the
//    last two steps' dv extrapolated. The spring Jacobian drops the
//    negative part of its transverse term (compressed springs) so the system
//    stays SPD. Nothing is factorized, so a cut or an LOD change costs no stall.
// Buffers are allocated when the model's size changes, never per step.

#include <cstdint>
#include <vector>

#include "sim/environment.h"
#include "sim/spring_model.h"
#include "sim/spring_state.h"
#include "sim/spring_system.h"
#include "sim/symplectic_pass.h"

namespace mtcut::sim {

enum class IntegratorKind { kSymplecticEuler, kImplicitEuler };

struct IntegratorDef {
  IntegratorKind kind = IntegratorKind::kImplicitEuler;
  int substeps = 1;              // each step is split in this many equal sub-steps
  // CG stops when the residual falls below this fraction of the larger of
  // the right-hand side and the particles' weight impulse over the step
  // (interactive accuracy: the error left is an A-norm-minimal velocity
  // correction; it damps rather than destabilises).
  double cg_tolerance = 1e-3;
  int cg_max_iterations = 100;
  PreconditionerKind preconditioner = PreconditionerKind::kSymmetricGaussSeidel;
  double max_speed = 100.0;      // m/s; a faster particle means the state exploded
};

struct StepReport {
  bool accepted = true;     // false: NaN or explosion, state restored
  int cg_iterations = 0;    // summed over sub-steps (implicit only)
  double cg_residual = 0;   // relative to the stopping scale, last sub-step
};

class Stepper {
 public:
  // Advances `state` by dt seconds. `state` must have model.num_particles() entries.
  StepReport step(const SpringModel& model, const Environment& env, const IntegratorDef& def, SpringState& state,
                  double dt);

  std::uint64_t refused_steps() const { return refused_steps_; }
  // Forgets the warm start (call when particles are renumbered).
  void reset_warm_start() { restart_warm_start(0); }
  // The implicit warm start's history, per particle (dv of the last three
  // steps, latest first; empty before the first implicit step), moved out
  // to carry across a change of the model (state_transfer.h); the stepper
  // is left without one (its next step starts from 0 unless it is carried
  // back) ...
  std::vector<std::vector<Vec3>> take_warm_start_history();
  // ... and to take back, for the new model's particles (the extrapolation
  // factors are kept). A history of the wrong size is a restart.
  void carry_warm_start(std::vector<std::vector<Vec3>> history);

 private:
  // dv's history (n entries, zero) and the extrapolation factors back to
  // their start: the first step after it extrapolates nothing.
  void restart_warm_start(std::size_t n);
  void substep_symplectic(const SpringModel& model, const Environment& env, SpringState& state, double h);
  // Returns CG iterations; writes the final relative residual.
  int substep_implicit(const SpringModel& model, const Environment& env, const IntegratorDef& def,
                       SpringState& state, double h, double& residual);
  void resize(const SpringModel& model);

  std::uint64_t refused_steps_ = 0;
  // Scratch (n_particles): forces, saved state, the implicit step's dv, the
  // one before (the warm start extrapolates them) and the system's residual
  // at the warm start.
  std::vector<Vec3> f_, saved_x_, saved_v_, dv_, dv_last_, residual_;
  // (n_particles) the dv before dv_last_, and the last two changes of dv,
  // along which the warm start extrapolates.
  std::vector<Vec3> dv_before_, dv_change_, dv_change_before_;
  // The warm start's factors along dv_change_ and dv_change_before_: those
  // that would have predicted the last solution best (least squares),
  // clamped to [0, 2] and [-1, 1] (linear: 1, 0; quadratic: 2, -1).
  double extrapolation_ = 1.0, extrapolation2_ = 0.0;
  RunLanes run_lanes_;  // the model's springs in lanes for the one-pass sub-steps
  PassState pass_state_;  // their state in slots and scratch
  SpringSystem system_;  // the implicit step's linear system and its solvers
};

// Pins fixed particles, then pushes particles out of the floor and the tool,
// removing the velocity that points into them.
void apply_contacts(const SpringModel& model, const Environment& env, SpringState& state);

}  // namespace mtcut::sim
