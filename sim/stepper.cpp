#include "sim/stepper.h"

#include <algorithm>
#include <cmath>

#include "sim/forces.h"

namespace mtcut::sim {
namespace {

double dot(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i].dot(b[i]);
  return sum;
}

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
  diag_.resize(n);
  dir_.resize(m);
  transverse_.resize(m);
}

StepReport Stepper::step(const SpringModel& model, const Environment& env, const IntegratorDef& def,
                         SpringState& state, double dt) {
  resize(model);
  std::copy(state.x.begin(), state.x.end(), saved_x_.begin());
  std::copy(state.v.begin(), state.v.end(), saved_v_.begin());

  StepReport report;
  const int substeps = std::max(1, def.substeps);
  const double h = dt / substeps;
  for (int k = 0; k < substeps; ++k) {
    if (def.kind == IntegratorKind::kSymplecticEuler) {
      substep_symplectic(model, env, state, h);
    } else {
      report.cg_iterations += substep_implicit(model, env, def, state, h, report.cg_residual);
    }
    apply_contacts(model, env, state);
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
// B_s = (h c + h^2 k) n n^T + h^2 k t (I - n n^T) acts on u_a - u_b.
void Stepper::multiply_system(const SpringModel& model, double h, const std::vector<Vec3>& u,
                              std::vector<Vec3>& out) const {
  const std::size_t n = model.num_particles();
  const double mass_factor = 1.0 + h * model.mass_damping;
  for (std::size_t i = 0; i < n; ++i) out[i] = (model.mass[i] * mass_factor) * u[i];
  const double h2 = h * h;
  const std::size_t m = model.num_springs();
  for (std::size_t s = 0; s < m; ++s) {
    const auto a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 du = u[a] - u[b];
    const Vec3& dir = dir_[s];
    const double along = dir.dot(du);
    const double k_t = h2 * model.stiffness[s] * transverse_[s];
    const Vec3 t = (h * model.damping[s] + h2 * model.stiffness[s] - k_t) * along * dir + k_t * du;
    out[a] += t;
    out[b] -= t;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (model.inv_mass[i] == 0) out[i].setZero();  // fixed: dv is held at 0
}

int Stepper::substep_implicit(const SpringModel& model, const Environment& env, const IntegratorDef& def,
                              SpringState& state, double h, double& residual) {
  const std::size_t n = model.num_particles(), m = model.num_springs();
  compute_forces(model, env, state, f_);

  // Per-spring Jacobian data at x0, and the Jacobi preconditioner.
  const double h2 = h * h;
  const double mass_factor = 1.0 + h * model.mass_damping;
  for (std::size_t i = 0; i < n; ++i) diag_[i] = model.mass[i] * mass_factor;
  for (std::size_t s = 0; s < m; ++s) {
    const auto a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 d = state.x[b] - state.x[a];
    const double length = d.norm();
    dir_[s] = length > 0 ? Vec3(d / length) : Vec3::UnitX();
    transverse_[s] = length > 0 ? std::max(0.0, 1.0 - model.rest_length[s] / length) : 0.0;
    // Trace / 3 of B_s: one third along, two thirds across.
    const double d_s = (h * model.damping[s] + h2 * model.stiffness[s] + 2.0 * h2 * model.stiffness[s] * transverse_[s]) / 3.0;
    diag_[a] += d_s;
    diag_[b] += d_s;
  }

  // Right-hand side b = h f0 + h^2 K v0, with K v0 = -sum_s J_s (v_a - v_b) at a
  // and J_s = k (n n^T + t (I - n n^T)) the (clamped) spring stiffness.
  for (std::size_t i = 0; i < n; ++i) r_[i] = h * f_[i];
  for (std::size_t s = 0; s < m; ++s) {
    const auto a = model.spring_a[s], b = model.spring_b[s];
    const Vec3 du = state.v[a] - state.v[b];
    const double along = dir_[s].dot(du);
    const double t = transverse_[s];
    const Vec3 j_du = (h2 * model.stiffness[s]) * ((1.0 - t) * along * dir_[s] + t * du);
    r_[a] -= j_du;
    r_[b] += j_du;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (model.inv_mass[i] == 0) r_[i].setZero();

  // Preconditioned CG on A dv = b, warm-started from the previous dv.
  for (std::size_t i = 0; i < n; ++i)
    if (model.inv_mass[i] == 0) dv_[i].setZero();
  multiply_system(model, h, dv_, ap_);
  const double b_norm = std::sqrt(dot(r_, r_));
  for (std::size_t i = 0; i < n; ++i) r_[i] -= ap_[i];
  for (std::size_t i = 0; i < n; ++i) z_[i] = r_[i] / diag_[i];
  p_ = z_;
  double rz = dot(r_, z_);
  int iterations = 0;
  residual = b_norm > 0 ? std::sqrt(dot(r_, r_)) / b_norm : 0.0;
  while (residual > def.cg_tolerance && iterations < def.cg_max_iterations) {
    multiply_system(model, h, p_, ap_);
    const double pap = dot(p_, ap_);
    if (!(pap > 0)) break;  // converged to round-off or lost definiteness
    const double alpha = rz / pap;
    for (std::size_t i = 0; i < n; ++i) {
      dv_[i] += alpha * p_[i];
      r_[i] -= alpha * ap_[i];
      z_[i] = r_[i] / diag_[i];
    }
    const double rz_next = dot(r_, z_);
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t i = 0; i < n; ++i) p_[i] = z_[i] + beta * p_[i];
    ++iterations;
    residual = std::sqrt(dot(r_, r_)) / b_norm;
  }

  for (std::size_t i = 0; i < n; ++i) {
    state.v[i] += dv_[i];
    state.x[i] += h * state.v[i];
  }
  return iterations;
}

}  // namespace mtcut::sim
