#include "sim/stepper.h"

#include <algorithm>
#include <cmath>

#include "sim/forces.h"

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

void Stepper::resize(const SpringModel& model) {
  const std::size_t n = model.num_particles(), m = model.num_springs();
  if (dv_.size() != n) dv_.assign(n, Vec3::Zero());  // a new model: no warm start
  for (auto* v : {&f_, &saved_x_, &saved_v_, &r_, &z_, &p_, &ap_}) v->resize(n);
  diag_mass_.resize(n);
  block_inverse_.resize(n);
  dir_.resize(m);
  along_.resize(m);
  across_.resize(m);
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
  for (int k = 0; k < substeps; ++k) {
    if (def.kind == IntegratorKind::kSymplecticEuler) {
      substep_symplectic(model, env, state, h);
    } else {
      report.cg_iterations += substep_implicit(model, env, def, state, h, report.cg_residual);
    }
    if (contacts) apply_contacts(model, env, state);
  }

  if (!state_is_sane(state, def.max_speed)) {
    std::copy(saved_x_.begin(), saved_x_.end(), state.x.begin());
    std::copy(saved_v_.begin(), saved_v_.end(), state.v.begin());
    std::fill(dv_.begin(), dv_.end(), Vec3::Zero());
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

// out = A u with A = M (1 + h alpha) + sum_s B_s, where for spring s = (a, b)
// B_s = along_s n n^T + across_s I acts on u_a - u_b (and its negative on b).
double Stepper::multiply_system(const SpringModel& model, const std::vector<Vec3>& u, std::vector<Vec3>& out) const {
  const std::size_t n = model.num_particles(), m = model.num_springs();
  for (std::size_t i = 0; i < n; ++i) out[i] = diag_mass_[i] * u[i];
  for (std::size_t s = 0; s < m; ++s) {
    const auto a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 du = u[a] - u[b];
    const Vec3 t = (along_[s] * dir_[s].dot(du)) * dir_[s] + across_[s] * du;
    out[a] += t;
    out[b] -= t;
  }
  double uau = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (model.inv_mass[i] == 0) out[i].setZero();  // fixed: dv is held at 0
    uau += u[i].dot(out[i]);
  }
  return uau;
}

int Stepper::substep_implicit(const SpringModel& model, const Environment& env, const IntegratorDef& def,
                              SpringState& state, double h, double& residual) {
  const std::size_t n = model.num_particles(), m = model.num_springs();
  compute_forces(model, env, state, f_);

  // The system's spring blocks at x0 (the transverse stiffness is clamped at
  // 0 for compressed springs: SPD), its diagonal blocks, and the right-hand
  // side b = h f0 + h^2 K v0 with K v0 = -sum_s J_s (v_a - v_b),
  // J_s = k (n n^T + t (I - n n^T)), t = max(0, 1 - L / l).
  const double h2 = h * h;
  const double mass_factor = 1.0 + h * model.mass_damping;
  std::vector<Eigen::Matrix3d>& blocks = block_inverse_;  // filled, then inverted in place
  for (std::size_t i = 0; i < n; ++i) {
    diag_mass_[i] = model.mass[i] * mass_factor;
    blocks[i] = diag_mass_[i] * Eigen::Matrix3d::Identity();
    r_[i] = h * f_[i];
  }
  for (std::size_t s = 0; s < m; ++s) {
    const auto a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 d = state.x[b] - state.x[a];
    const double length = d.norm();
    const Vec3 dir = length > 0 ? Vec3(d / length) : Vec3::UnitX();
    const double t = length > 0 ? std::max(0.0, 1.0 - model.rest_length[s] / length) : 0.0;
    const double k = model.stiffness[s];
    dir_[s] = dir;
    along_[s] = h * model.damping[s] + h2 * k * (1.0 - t);
    across_[s] = h2 * k * t;
    const Eigen::Matrix3d block = along_[s] * dir * dir.transpose() + across_[s] * Eigen::Matrix3d::Identity();
    blocks[a] += block;
    blocks[b] += block;
    const Vec3 dv0 = state.v[a] - state.v[b];
    const Vec3 j_dv = (h2 * k) * ((1.0 - t) * dir.dot(dv0) * dir + t * dv0);
    r_[a] -= j_dv;
    r_[b] += j_dv;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (model.inv_mass[i] == 0) {
      r_[i].setZero();
      dv_[i].setZero();
    }
    blocks[i] = blocks[i].inverse().eval();
  }

  // Preconditioned CG on A dv = b, warm-started from the previous dv.
  // The scale the residual is measured against: the right-hand side, but
  // never less than the impulse of the body's weight over the step (near
  // equilibrium b tends to 0 and a purely relative test would chase
  // round-off; a force error below tol * weight is invisible).
  double b_norm2 = 0, weight_impulse2 = 0;
  const double gh2 = (h * env.gravity).squaredNorm();
  for (std::size_t i = 0; i < n; ++i) {
    b_norm2 += r_[i].squaredNorm();
    if (model.inv_mass[i] != 0) weight_impulse2 += model.mass[i] * model.mass[i] * gh2;
  }
  const double scale2 = std::max(b_norm2, weight_impulse2);
  multiply_system(model, dv_, ap_);
  double rz = 0, rr = 0;
  for (std::size_t i = 0; i < n; ++i) {
    r_[i] -= ap_[i];
    z_[i] = block_inverse_[i] * r_[i];
    p_[i] = z_[i];
    rz += r_[i].dot(z_[i]);
    rr += r_[i].squaredNorm();
  }
  const double tolerance2 = def.cg_tolerance * def.cg_tolerance * scale2;
  int iterations = 0;
  while (rr > tolerance2 && iterations < def.cg_max_iterations) {
    const double pap = multiply_system(model, p_, ap_);
    if (!(pap > 0)) break;  // converged to round-off
    const double alpha = rz / pap;
    double rz_next = 0;
    rr = 0;
    for (std::size_t i = 0; i < n; ++i) {
      dv_[i] += alpha * p_[i];
      r_[i] -= alpha * ap_[i];
      z_[i] = block_inverse_[i] * r_[i];
      rz_next += r_[i].dot(z_[i]);
      rr += r_[i].squaredNorm();
    }
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t i = 0; i < n; ++i) p_[i] = z_[i] + beta * p_[i];
    ++iterations;
  }
  residual = scale2 > 0 ? std::sqrt(rr / scale2) : 0.0;

  for (std::size_t i = 0; i < n; ++i) {
    state.v[i] += dv_[i];
    state.x[i] += h * state.v[i];
  }
  return iterations;
}

}  // namespace mtcut::sim
