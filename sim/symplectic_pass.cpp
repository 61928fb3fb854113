#include "sim/symplectic_pass.h"

#include <cmath>
#include <cstdint>

#include "sim/contacts.h"
#include "sim/forces.h"
#include "sim/spring_law.h"

namespace mtcut::sim {
namespace {

// The lanes' other ends and springs of run [s, e), padded with springs of
// stiffness 0 to the run's own particle i.
template <int kLanes, class Group>
void append_group(const SpringModel& model, std::size_t s, std::size_t e, std::int32_t i,
                  std::vector<std::int32_t>& other, std::vector<Group>& groups) {
  Group g{};
  for (int l = 0; l < kLanes; ++l) {
    const std::size_t t = s + static_cast<std::size_t>(l);
    const bool real = t < e;
    other.push_back(real ? model.spring_b[t] : i);
    g.stiffness[l] = real ? model.stiffness[t] : 0.0;
    g.stiffness_rest[l] = real ? model.stiffness[t] * model.rest_length[t] : 0.0;
    g.damping[l] = real ? model.damping[t] : 0.0;
  }
  groups.push_back(g);
}

// One sub-step over the slots (the class comment in the header). The lanes'
// sums are in the same order in every build, so the SSE2 and AVX2 copies
// agree bit for bit; the square roots are correctly rounded in both.
MTCUT_SPRING_LOOP void pass(const SpringModel& model, const RunLanes& lanes, const Environment& env, bool contacts,
                            double h, PassState& s) {
  const std::size_t n = model.num_particles();
  const std::int32_t *quad_start = lanes.quad_start.data(), *quad_other = lanes.quad_other.data();
  const std::int32_t *pair_of = lanes.pair_of.data(), *pair_other = lanes.pair_other.data();
  const SpringQuad* quads = lanes.quads.data();
  const SpringPair* pairs = lanes.pairs.data();
  const double *mass = model.mass.data(), *inv_mass = model.inv_mass.data();
  Slot4 *x = s.x.data(), *v = s.v.data(), *acc = s.acc.data();
  const Lanes4 gravity = {env.gravity.x(), env.gravity.y(), env.gravity.z(), 0.0};
  const double mass_damping = model.mass_damping;
  const Lanes4 zero = {0, 0, 0, 0}, one = {1, 1, 1, 1};
  const Lanes4 tiny = {kTinyLength2, kTinyLength2, kTinyLength2, kTinyLength2};
  // Pairs of lanes from two slots: (a0, b0, a2, b2) and (a1, b1, a3, b3).
  const LaneIndex4 even = {0, 4, 2, 6}, odd = {1, 5, 3, 7};
  const LaneIndex4 low = {0, 1, 4, 5}, high = {2, 3, 6, 7};  // halves of two registers
  for (std::size_t i = 0; i < n; ++i) {
    const Lanes4 xi = x[i].p, vi = v[i].p;
    Lanes4 fi = acc[i].p;
    acc[i].p = zero;
    Lanes4 fx = zero, fy = zero, fz = zero;
    for (std::int32_t k = quad_start[i]; k < quad_start[i + 1]; ++k) {
      const std::int32_t* j = quad_other + 4 * k;
      const Lanes4 d0 = x[j[0]].p - xi, d1 = x[j[1]].p - xi, d2 = x[j[2]].p - xi, d3 = x[j[3]].p - xi;
      const Lanes4 u0 = v[j[0]].p - vi, u1 = v[j[1]].p - vi, u2 = v[j[2]].p - vi, u3 = v[j[3]].p - vi;
      // Transposed: lane l holds spring l's component.
      const Lanes4 d01e = __builtin_shuffle(d0, d1, even), d01o = __builtin_shuffle(d0, d1, odd);
      const Lanes4 d23e = __builtin_shuffle(d2, d3, even), d23o = __builtin_shuffle(d2, d3, odd);
      const Lanes4 dx = __builtin_shuffle(d01e, d23e, low), dy = __builtin_shuffle(d01o, d23o, low),
                   dz = __builtin_shuffle(d01e, d23e, high);
      const Lanes4 u01e = __builtin_shuffle(u0, u1, even), u01o = __builtin_shuffle(u0, u1, odd);
      const Lanes4 u23e = __builtin_shuffle(u2, u3, even), u23o = __builtin_shuffle(u2, u3, odd);
      const Lanes4 ux = __builtin_shuffle(u01e, u23e, low), uy = __builtin_shuffle(u01o, u23o, low),
                   uz = __builtin_shuffle(u01e, u23e, high);
      // The spring law as one multiple of d (spring_coefficient).
      // + kTinyLength2 is exact for any real spring; a zero-length one (and
      // a pad) adds 0 (d = 0) instead of dividing by 0.
      const Lanes4 length2 = dx * dx + dy * dy + dz * dz + tiny;
      Lanes4 length;
      for (int l = 0; l < 4; ++l) length[l] = std::sqrt(length2[l]);  // one vsqrtpd (-fno-math-errno)
      const Lanes4 inv_length2 = one / length2;
      const SpringQuad& q = quads[k];
      Lanes4 coef;
      spring_coefficient(q.stiffness, q.stiffness_rest, q.damping, dx * ux + dy * uy + dz * uz, length, inv_length2,
                         coef);
      fx += coef * dx;
      fy += coef * dy;
      fz += coef * dz;
      acc[j[0]].p -= __builtin_shuffle(coef, LaneIndex4{0, 0, 0, 0}) * d0;
      acc[j[1]].p -= __builtin_shuffle(coef, LaneIndex4{1, 1, 1, 1}) * d1;
      acc[j[2]].p -= __builtin_shuffle(coef, LaneIndex4{2, 2, 2, 2}) * d2;
      acc[j[3]].p -= __builtin_shuffle(coef, LaneIndex4{3, 3, 3, 3}) * d3;
    }
    if (const std::int32_t p = pair_of[i]; p >= 0) {
      // Two springs: the squares and products of (x, z) and (y, pad) lanes,
      // whose halves add up to each spring's sums.
      const std::int32_t* j = pair_other + 2 * p;
      const Lanes4 d0 = x[j[0]].p - xi, d1 = x[j[1]].p - xi, u0 = v[j[0]].p - vi, u1 = v[j[1]].p - vi;
      const Lanes4 de = __builtin_shuffle(d0, d1, even), dod = __builtin_shuffle(d0, d1, odd);
      const Lanes4 ue = __builtin_shuffle(u0, u1, even), uod = __builtin_shuffle(u0, u1, odd);
      const Lanes4 squares = de * de + dod * dod, products = de * ue + dod * uod;
      const Lanes2 length2 = Lanes2{squares[0], squares[1]} + Lanes2{squares[2], squares[3]} +
                             Lanes2{kTinyLength2, kTinyLength2};
      const Lanes2 dot = Lanes2{products[0], products[1]} + Lanes2{products[2], products[3]};
      const Lanes2 inv_length2 = Lanes2{1.0, 1.0} / length2, length = sqrt_lanes(length2);
      const SpringPair& sp = pairs[p];
      Lanes2 coef;
      spring_coefficient(sp.stiffness, sp.stiffness_rest, sp.damping, dot, length, inv_length2, coef);
      const Lanes4 g0 = coef[0] * d0, g1 = coef[1] * d1;
      fi += g0 + g1;
      acc[j[0]].p -= g0;
      acc[j[1]].p -= g1;
    }
    fi += Lanes4{fx[0] + fx[1] + fx[2] + fx[3], fy[0] + fy[1] + fy[2] + fy[3], fz[0] + fz[1] + fz[2] + fz[3], 0.0};
    fi += mass[i] * (gravity - mass_damping * vi);
    Lanes4 vn = vi + (h * inv_mass[i]) * fi;
    Lanes4 xn = xi + h * vn;
    if (contacts) {
      Vec3 cx(xn[0], xn[1], xn[2]), cv(vn[0], vn[1], vn[2]);
      if (inv_mass[i] == 0) {
        cv.setZero();
      } else {
        push_out_of_contacts(env, cx, cv);
      }
      xn = Lanes4{cx.x(), cx.y(), cx.z(), 0.0};
      vn = Lanes4{cv.x(), cv.y(), cv.z(), 0.0};
    }
    x[i].p = xn;
    v[i].p = vn;
  }
}

void load_slots(const std::vector<Vec3>& from, std::vector<Slot4>& to) {
  to.resize(from.size());
  for (std::size_t i = 0; i < from.size(); ++i) to[i].p = Lanes4{from[i].x(), from[i].y(), from[i].z(), 0.0};
}

void store_slots(const std::vector<Slot4>& from, std::vector<Vec3>& to) {
  for (std::size_t i = 0; i < from.size(); ++i) to[i] = Vec3(from[i].p[0], from[i].p[1], from[i].p[2]);
}

}  // namespace

bool springs_in_run_order(const SpringModel& model) {
  const std::size_t m = model.num_springs();
  const auto n = static_cast<std::int32_t>(model.num_particles());
  const std::int32_t *a = model.spring_a.data(), *b = model.spring_b.data();
  bool ok = true;
  for (std::size_t s = 0; s < m; ++s) ok &= (0 <= a[s]) & (a[s] < b[s]) & (b[s] < n) & (s == 0 || a[s - 1] <= a[s]);
  return ok;
}

void RunLanes::fill(const SpringModel& model) {
  const std::size_t n = model.num_particles(), m = model.num_springs();
  quad_start.resize(n + 1);
  pair_of.resize(n);
  quad_other.clear();
  quads.clear();
  pair_other.clear();
  pairs.clear();
  std::size_t s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t e = s;
    while (e < m && static_cast<std::size_t>(model.spring_a[e]) == i) ++e;
    const std::size_t left = (e - s) % 4;
    const std::size_t quads_end = left == 1 || left == 2 ? e - left : e;
    const auto particle = static_cast<std::int32_t>(i);
    quad_start[i] = static_cast<std::int32_t>(quads.size());
    for (std::size_t q = s; q < quads_end; q += 4) append_group<4>(model, q, quads_end, particle, quad_other, quads);
    pair_of[i] = -1;
    if (quads_end != e) {
      pair_of[i] = static_cast<std::int32_t>(pairs.size());
      append_group<2>(model, quads_end, e, particle, pair_other, pairs);
    }
    s = e;
  }
  quad_start[n] = static_cast<std::int32_t>(quads.size());
}

void symplectic_substeps(const SpringModel& model, const RunLanes& lanes, const Environment& env, bool contacts,
                         double h, int substeps, SpringState& state, PassState& scratch) {
  const std::size_t n = model.num_particles();
  load_slots(state.x, scratch.x);
  load_slots(state.v, scratch.v);
  // Zero at every call, not only the first: a step that went NaN leaves NaN
  // here (a pad lane's reaction lands on its own particle after its turn),
  // and the next step, from the state the guard restored, must not read it.
  scratch.acc.assign(n, Slot4{Lanes4{0, 0, 0, 0}});
  for (int k = 0; k < substeps; ++k) {
    if (!model.tet_particles.empty()) {  // from x at the sub-step's start, like the springs
      store_slots(scratch.x, state.x);
      scratch.volume.assign(n, Vec3::Zero());
      add_volume_forces(model, state, scratch.volume);
      for (std::size_t i = 0; i < n; ++i)
        scratch.acc[i].p += Lanes4{scratch.volume[i].x(), scratch.volume[i].y(), scratch.volume[i].z(), 0.0};
    }
    pass(model, lanes, env, contacts, h, scratch);
  }
  store_slots(scratch.x, state.x);
  store_slots(scratch.v, state.v);
}

}  // namespace mtcut::sim
