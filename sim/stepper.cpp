#include "sim/stepper.h"

#include <algorithm>
#include <cmath>

#include "sim/forces.h"
#include "sim/symplectic_pass.h"

namespace mtcut::sim {
namespace {

bool state_is_sane(const SpringState& state, double max_speed) {
  const double limit = max_speed * max_speed;
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    if (!state.x[i].allFinite() || !state.v[i].allFinite()) return false;
    if (state.v[i].squaredNorm() > limit) return false;
  }
  return true;
}

}  // namespace

void Stepper::restart_warm_start(std::size_t n) {
  for (auto* v : {&dv_, &dv_last_, &dv_before_}) v->assign(n, Vec3::Zero());
  extrapolation_ = 1.0;
  extrapolation2_ = 0.0;
}

std::vector<std::vector<Vec3>> Stepper::take_warm_start_history() {
  if (dv_.empty()) return {};
  std::vector<std::vector<Vec3>> history;
  history.reserve(3);
  for (auto* v : {&dv_, &dv_last_, &dv_before_}) {
    history.push_back(std::move(*v));
    v->clear();  // the extrapolation factors stay, for the history carried back
  }
  return history;
}

void Stepper::carry_warm_start(std::vector<std::vector<Vec3>> history) {
  const std::size_t n = history.empty() ? 0 : history[0].size();
  if (history.size() != 3 || history[1].size() != n || history[2].size() != n) {
    restart_warm_start(0);
    return;
  }
  dv_ = std::move(history[0]);
  dv_last_ = std::move(history[1]);
  dv_before_ = std::move(history[2]);
}

void Stepper::resize(const SpringModel& model) {
  const std::size_t n = model.num_particles();
  if (dv_.size() != n) restart_warm_start(n);  // a new model: no warm start
  for (auto* v : {&f_, &saved_x_, &saved_v_, &residual_, &dv_change_, &dv_change_before_}) v->resize(n);
}

StepReport Stepper::step(const SpringModel& model, const Environment& env, const IntegratorDef& def,
                         SpringState& state, double dt) {
  resize(model);
  std::copy(state.x.begin(), state.x.end(), saved_x_.begin());
  std::copy(state.v.begin(), state.v.end(), saved_v_.begin());
  for (std::size_t i = 0; i < model.num_particles(); ++i)
    if (model.inv_mass[i] == 0) state.v[i].setZero();  // pinned: no integrator moves them

  StepReport report;
  const int substeps = std::max(1, def.substeps);
  const double h = dt / substeps;
  const bool contacts = env.floor.has_value() || (env.tool.has_value() && env.tool->radius > 0);
  const bool one_pass = def.kind == IntegratorKind::kSymplecticEuler && springs_in_run_order(model);
  if (one_pass) {  // contacts resolved in the same pass
    run_lanes_.fill(model);
    symplectic_substeps(model, run_lanes_, env, contacts, h, substeps, state, pass_state_);
  } else {
    for (int k = 0; k < substeps; ++k) {
      if (def.kind == IntegratorKind::kSymplecticEuler) {
        substep_symplectic(model, env, state, h);
      } else {
        report.cg_iterations += substep_implicit(model, env, def, state, h, report.cg_residual);
      }
      if (contacts) apply_contacts(model, env, state);
    }
  }

  if (!state_is_sane(state, def.max_speed)) {
    std::copy(saved_x_.begin(), saved_x_.end(), state.x.begin());
    std::copy(saved_v_.begin(), saved_v_.end(), state.v.begin());
    restart_warm_start(dv_.size());
    ++refused_steps_;
    report.accepted = false;
  }
  return report;
}

void Stepper::substep_symplectic(const SpringModel& model, const Environment& env, SpringState& state, double h) {
  compute_forces(model, env, state, f_);
  const std::size_t n = model.num_particles();
  for (std::size_t i = 0; i < n; ++i) {
    state.v[i] += (h * model.inv_mass[i]) * f_[i];
    state.x[i] += h * state.v[i];
  }
}

int Stepper::substep_implicit(const SpringModel& model, const Environment& env, const IntegratorDef& def,
                              SpringState& state, double h, double& residual) {
  const std::size_t n = model.num_particles();
  // The warm start: dv extrapolated from the last three steps, last +
  // e (last - previous) + e2 (previous - the one before), e and e2 fitted
  // to the last step. A smooth motion (the bench box swinging) wants them
  // near the quadratic extrapolation's 2 and -1; one with jolts (contacts,
  // cuts: the default scenario) near 0, where the linear extrapolation
  // (1, 0) doubles the iterations.
  const double e = extrapolation_, e2 = extrapolation2_;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 last = dv_[i];
    dv_change_[i] = last - dv_last_[i];
    dv_change_before_[i] = dv_last_[i] - dv_before_[i];
    dv_before_[i] = dv_last_[i];
    dv_[i] = model.inv_mass[i] == 0 ? Vec3::Zero() : Vec3(last + e * dv_change_[i] + e2 * dv_change_before_[i]);
    dv_last_[i] = last;
  }

  // Preconditioned CG on A dv = b, from the warm start and its residual
  // (residual_: b - A dv, summed by the assembly).
  compute_body_forces(model, env, state, f_);
  system_.assemble(model, state, f_, h, dv_, residual_);
  // The scale the residual is measured against: the right-hand side, but
  // never less than the impulse of the body's weight over the step (near
  // equilibrium b tends to 0 and a purely relative test would chase
  // round-off; a force error below tol * weight is invisible).
  double weight_impulse2 = 0;
  const double gh2 = (h * env.gravity).squaredNorm();
  for (std::size_t i = 0; i < n; ++i)
    if (model.inv_mass[i] != 0) weight_impulse2 += model.mass[i] * model.mass[i] * gh2;
  const double scale2 = std::max(system_.rhs_norm2(), weight_impulse2);
  const double tolerance2 = def.cg_tolerance * def.cg_tolerance * scale2;
  const CgStats stats =
      system_.solve_from_residual(def.preconditioner, residual_, tolerance2, def.cg_max_iterations, dv_);
  const double rr = stats.residual2;
  residual = scale2 > 0 ? std::sqrt(rr / scale2) : 0.0;

  // The e, e2 that would have put the warm start nearest this solution:
  // argmin |dv - last - e change - e2 change_before|^2, the 2x2 normal
  // equations; e alone when the two changes are (nearly) parallel.
  double along = 0, along2 = 0, change2 = 0, c22 = 0, c12 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    state.v[i] += dv_[i];
    state.x[i] += h * state.v[i];
    const Vec3 err = dv_[i] - dv_last_[i];
    along += err.dot(dv_change_[i]);
    along2 += err.dot(dv_change_before_[i]);
    change2 += dv_change_[i].squaredNorm();
    c22 += dv_change_before_[i].squaredNorm();
    c12 += dv_change_[i].dot(dv_change_before_[i]);
  }
  const double det = change2 * c22 - c12 * c12;
  if (det > 1e-6 * change2 * c22) {
    extrapolation_ = std::clamp((along * c22 - along2 * c12) / det, 0.0, 2.0);
    extrapolation2_ = std::clamp((change2 * along2 - c12 * along) / det, -1.0, 1.0);
  } else if (change2 > 0) {
    extrapolation_ = std::clamp(along / change2, 0.0, 1.0);
    extrapolation2_ = 0;
  }
  return stats.iterations;
}

}  // namespace mtcut::sim
