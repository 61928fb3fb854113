#include "sim/symplectic_pass.h"

#include <cmath>
#include <cstdint>

#include "sim/contacts.h"
#include "sim/forces.h"

namespace mtcut::sim {
namespace {

constexpr double kTinyLength2 = 1e-300;  // m^2, below any real spring's

}  // namespace

bool springs_in_run_order(const SpringModel& model) {
  const std::size_t m = model.num_springs();
  const auto n = static_cast<std::int32_t>(model.num_particles());
  const std::int32_t *a = model.spring_a.data(), *b = model.spring_b.data();
  bool ok = true;
  for (std::size_t s = 0; s < m; ++s) ok &= (0 <= a[s]) & (a[s] < b[s]) & (b[s] < n) & (s == 0 || a[s - 1] <= a[s]);
  return ok;
}

void symplectic_substep(const SpringModel& model, const Environment& env, bool contacts, double h,
                        SpringState& state, std::vector<Vec3>& acc_vec) {
  const std::size_t n = model.num_particles(), m = model.num_springs();
  if (!model.tet_particles.empty()) add_volume_forces(model, state, acc_vec);  // read x before it moves
  const std::int32_t *spring_a = model.spring_a.data(), *spring_b = model.spring_b.data();
  const double *rest = model.rest_length.data(), *stiffness = model.stiffness.data(), *damping = model.damping.data();
  const double *mass = model.mass.data(), *inv_mass = model.inv_mass.data();
  Vec3 *x = state.x.data(), *v = state.v.data(), *acc = acc_vec.data();
  const Vec3 gravity = env.gravity;
  const double mass_damping = model.mass_damping;
  std::size_t s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 xi = x[i], vi = v[i];
    Vec3 fi = acc[i];
    acc[i].setZero();
    for (; s < m && static_cast<std::size_t>(spring_a[s]) == i; ++s) {
      const auto j = spring_b[s];
      const Vec3 d = x[j] - xi;
      const Vec3 dv = v[j] - vi;
      // Hooke + dashpot along d, as one multiple of d: k (l - L) / l
      // + c (d . dv) / l^2. + kTinyLength2 is exact for any real spring; a
      // zero-length one adds 0 (d = 0) instead of dividing by 0.
      const double inv_length = 1.0 / std::sqrt(d.squaredNorm() + kTinyLength2);
      const double coef =
          stiffness[s] * (1.0 - rest[s] * inv_length) + damping[s] * d.dot(dv) * (inv_length * inv_length);
      const Vec3 fs = coef * d;
      fi += fs;
      acc[j] -= fs;
    }
    fi += mass[i] * (gravity - mass_damping * vi);
    Vec3 vn = vi + (h * inv_mass[i]) * fi;
    Vec3 xn = xi + h * vn;
    if (contacts) {
      if (inv_mass[i] == 0) {
        vn.setZero();
      } else {
        push_out_of_contacts(env, xn, vn);
      }
    }
    x[i] = xn;
    v[i] = vn;
  }
}

}  // namespace mtcut::sim
