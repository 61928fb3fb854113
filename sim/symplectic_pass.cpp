#include "sim/symplectic_pass.h"

#include <cmath>
#include <cstdint>

#include "sim/contacts.h"
#include "sim/forces.h"
#include "sim/lanes2.h"

namespace mtcut::sim {

bool springs_in_run_order(const SpringModel& model) {
  const std::size_t m = model.num_springs();
  const auto n = static_cast<std::int32_t>(model.num_particles());
  const std::int32_t *a = model.spring_a.data(), *b = model.spring_b.data();
  bool ok = true;
  for (std::size_t s = 0; s < m; ++s) ok &= (0 <= a[s]) & (a[s] < b[s]) & (b[s] < n) & (s == 0 || a[s - 1] <= a[s]);
  return ok;
}

void RunPairs::fill(const SpringModel& model) {
  const std::size_t n = model.num_particles(), m = model.num_springs();
  start.resize(n + 1);
  other.clear();
  springs.clear();
  std::size_t s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    start[i] = static_cast<std::int32_t>(springs.size());
    while (s < m && static_cast<std::size_t>(model.spring_a[s]) == i) {
      const bool pad = s + 1 >= m || static_cast<std::size_t>(model.spring_a[s + 1]) != i;  // the run ends at s
      const std::size_t t = pad ? s : s + 1;
      const double on = pad ? 0.0 : 1.0;
      other.push_back(model.spring_b[s]);
      other.push_back(pad ? static_cast<std::int32_t>(i) : model.spring_b[t]);
      springs.push_back({Lanes2{model.stiffness[s], on * model.stiffness[t]},
                         Lanes2{model.stiffness[s] * model.rest_length[s],
                                on * model.stiffness[t] * model.rest_length[t]},
                         Lanes2{model.damping[s], on * model.damping[t]}});
      s += pad ? 1 : 2;
    }
  }
  start[n] = static_cast<std::int32_t>(springs.size());
}

MTCUT_SPRING_LOOP void symplectic_substep(const SpringModel& model, const RunPairs& pairs, const Environment& env,
                                          bool contacts, double h, SpringState& state, std::vector<Vec3>& acc_vec) {
  const std::size_t n = model.num_particles();
  if (!model.tet_particles.empty()) add_volume_forces(model, state, acc_vec);  // read x before it moves
  const std::int32_t *start = pairs.start.data(), *other = pairs.other.data();
  const SpringPair* springs = pairs.springs.data();
  const double *mass = model.mass.data(), *inv_mass = model.inv_mass.data();
  Vec3 *x = state.x.data(), *v = state.v.data(), *acc = acc_vec.data();
  const Vec3 gravity = env.gravity;
  const double mass_damping = model.mass_damping;
  const Lanes2 one = {1.0, 1.0}, tiny = {kTinyLength2, kTinyLength2};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 xi = x[i], vi = v[i];
    Vec3 fi = acc[i];
    acc[i].setZero();
    Lanes2 fx = {0, 0}, fy = {0, 0}, fz = {0, 0};
    for (std::int32_t k = start[i]; k < start[i + 1]; ++k) {
      const auto j0 = other[2 * k], j1 = other[2 * k + 1];
      const Vec3 &x0 = x[j0], &x1 = x[j1], &v0 = v[j0], &v1 = v[j1];
      const Lanes2 dx = Lanes2{x0.x(), x1.x()} - xi.x(), dy = Lanes2{x0.y(), x1.y()} - xi.y(),
                   dz = Lanes2{x0.z(), x1.z()} - xi.z();
      const Lanes2 ux = Lanes2{v0.x(), v1.x()} - vi.x(), uy = Lanes2{v0.y(), v1.y()} - vi.y(),
                   uz = Lanes2{v0.z(), v1.z()} - vi.z();
      // Hooke + dashpot along d, as one multiple of d: k (l - L) / l
      // + c (d . dv) / l^2 = k + (c (d . dv) - k L l) / l^2. In this form
      // the square root and the division both take l^2 and run side by side
      // (1 / sqrt(l^2) chains them: about 9% more time on the bench box,
      // whose steps are bound by that latency). + kTinyLength2 is exact for
      // any real spring; a zero-length one (and a pad) adds 0 (d = 0)
      // instead of dividing by 0.
      const Lanes2 length2 = dx * dx + dy * dy + dz * dz + tiny;
      const Lanes2 inv_length2 = one / length2, length = sqrt_lanes(length2);
      const SpringPair& sp = springs[k];
      const Lanes2 coef =
          sp.stiffness + (sp.damping * (dx * ux + dy * uy + dz * uz) - sp.stiffness_rest * length) * inv_length2;
      const Lanes2 gx = coef * dx, gy = coef * dy, gz = coef * dz;
      fx += gx;
      fy += gy;
      fz += gz;
      acc[j0] -= Vec3(gx[0], gy[0], gz[0]);
      acc[j1] -= Vec3(gx[1], gy[1], gz[1]);
    }
    fi += Vec3(fx[0] + fx[1], fy[0] + fy[1], fz[0] + fz[1]);
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
