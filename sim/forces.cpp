#include "sim/forces.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>

#include "engine/tet_geometry.h"
#include "sim/spring_law.h"

namespace mtcut::sim {
void add_volume_forces(const SpringModel& model, const SpringState& state, std::vector<Vec3>& f) {
  for (std::size_t t = 0; t < model.tet_particles.size(); ++t) {
    const auto& p = model.tet_particles[t];
    const Vec3 &x0 = state.x[p[0]], &x1 = state.x[p[1]], &x2 = state.x[p[2]], &x3 = state.x[p[3]];
    const double volume = engine::signed_volume(x0, x1, x2, x3);
    const double pressure = -model.volume_modulus * (volume - model.rest_volume[t]) / model.rest_volume[t];
    // dV/dx_i = (1/6) * outward area vector of the face opposite i, negated.
    const Vec3 g1 = (x2 - x0).cross(x3 - x0) / 6.0;
    const Vec3 g2 = (x3 - x0).cross(x1 - x0) / 6.0;
    const Vec3 g3 = (x1 - x0).cross(x2 - x0) / 6.0;
    f[p[1]] += pressure * g1;
    f[p[2]] += pressure * g2;
    f[p[3]] += pressure * g3;
    f[p[0]] -= pressure * (g1 + g2 + g3);
  }
}

void compute_forces(const SpringModel& model, const Environment& env, const SpringState& state,
                    std::vector<Vec3>& f) {
  const std::size_t n = model.num_particles();
  f.resize(n);
  for (std::size_t i = 0; i < n; ++i) f[i] = model.mass[i] * (env.gravity - model.mass_damping * state.v[i]);
  // A run of springs with the same first particle a (all of a's, as
  // build_spring_model sorts them) sums a's force in registers, not through
  // memory spring after spring.
  const std::size_t m = model.num_springs();
  const std::int32_t *spring_a = model.spring_a.data(), *spring_b = model.spring_b.data();
  const Vec3 *x = state.x.data(), *v = state.v.data();
  for (std::size_t s = 0; s < m;) {
    const auto a = spring_a[s];
    const Vec3 xa = x[a], va = v[a];
    Vec3 fa = Vec3::Zero();
    for (; s < m && spring_a[s] == a; ++s) {
      const auto b = spring_b[s];
      const Vec3 d = x[b] - xa;
      const double length = d.norm();
      if (length <= 0) continue;
      const Vec3 dir = d / length;
      const double magnitude =
          spring_tension(model.stiffness[s], model.rest_length[s], model.damping[s], length, dir.dot(v[b] - va));
      fa += magnitude * dir;
      f[b] -= magnitude * dir;
    }
    f[a] += fa;
  }
  if (!model.tet_particles.empty()) add_volume_forces(model, state, f);
}

void compute_body_forces(const SpringModel& model, const Environment& env, const SpringState& state,
                         std::vector<Vec3>& f) {
  const std::size_t n = model.num_particles();
  f.resize(n);
  for (std::size_t i = 0; i < n; ++i) f[i] = model.mass[i] * (env.gravity - model.mass_damping * state.v[i]);
  if (!model.tet_particles.empty()) add_volume_forces(model, state, f);
}

double total_energy(const SpringModel& model, const Environment& env, const SpringState& state) {
  double e = 0;
  for (std::size_t i = 0; i < model.num_particles(); ++i)
    e += 0.5 * model.mass[i] * state.v[i].squaredNorm() - model.mass[i] * env.gravity.dot(state.x[i]);
  for (std::size_t s = 0; s < model.num_springs(); ++s) {
    const double stretch = (state.x[model.spring_b[s]] - state.x[model.spring_a[s]]).norm() - model.rest_length[s];
    e += 0.5 * model.stiffness[s] * stretch * stretch;
  }
  for (std::size_t t = 0; t < model.tet_particles.size(); ++t) {
    const auto& p = model.tet_particles[t];
    const double dv = engine::signed_volume(state.x[p[0]], state.x[p[1]], state.x[p[2]], state.x[p[3]]) -
                      model.rest_volume[t];
    e += 0.5 * model.volume_modulus * dv * dv / model.rest_volume[t];
  }
  return e;
}

Vec3 linear_momentum(const SpringModel& model, const SpringState& state) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < model.num_particles(); ++i) p += model.mass[i] * state.v[i];
  return p;
}

double critical_time_step(const SpringModel& model) {
  std::vector<double> k_sum(model.num_particles(), 0.0), c_sum(model.num_particles(), 0.0);
  for (std::size_t s = 0; s < model.num_springs(); ++s) {
    for (const auto p : {model.spring_a[s], model.spring_b[s]}) {
      k_sum[p] += model.stiffness[s];
      c_sum[p] += model.damping[s];
    }
  }
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < model.num_particles(); ++i) {
    if (model.inv_mass[i] == 0 || k_sum[i] == 0) continue;
    // x'' + 2a x' + w^2 x = 0 under symplectic Euler is stable for
    // h <= 2 (sqrt(a^2 + w^2) - a) / w^2 (= 2 / w without damping).
    const double w2 = k_sum[i] / model.mass[i];
    const double a = 0.5 * (c_sum[i] / model.mass[i] + model.mass_damping);
    dt = std::min(dt, 2.0 * (std::sqrt(a * a + w2) - a) / w2);
  }
  return dt;
}

SpringState rest_state(const SpringModel& model) {
  return {model.rest_position, std::vector<Vec3>(model.num_particles(), Vec3::Zero())};
}

}  // namespace mtcut::sim
