// SpringSystem's assembly: the paired layout kept up to date with the
// model's springs, then A's blocks, diagonal and b built in one pass over
// the pairs (the system and its solvers: sim/spring_system.cpp).

#include "sim/spring_system.h"

#include <algorithm>

#include "sim/lanes2.h"
#include "sim/spring_law.h"

namespace mtcut::sim {
namespace {

// A pair of springs' geometry at the state, for the assembly's second step.
struct PairGeometry {
  Lanes2 nx, ny, nz;               // unit direction a -> c
  Lanes2 along, across, root;      // the block's terms, sqrt(along)
  Lanes2 stiffness, rest, length;  // h k, L, l
};

void add_block(Sym3& d, const SpringBlock& blk) {
  const Vec3& w = blk.w;
  d.xx += w.x() * w.x() + blk.across;
  d.xy += w.x() * w.y();
  d.xz += w.x() * w.z();
  d.yy += w.y() * w.y() + blk.across;
  d.yz += w.y() * w.z();
  d.zz += w.z() * w.z() + blk.across;
}

}  // namespace

void SpringSystem::update_layout(const SpringModel& model) {
  const std::size_t n = model.num_particles(), m = model.num_springs();
  if (layout_n_ == n && layout_a_ == model.spring_a && layout_b_ == model.spring_b) return;
  resize(n, m);
  layout_n_ = n;
  layout_a_ = model.spring_a;
  layout_b_ = model.spring_b;
  rows_sorted_ = true;
  for (std::size_t s = 0; s < m; ++s)
    if (model.spring_a[s] >= model.spring_b[s] || (s > 0 && model.spring_a[s - 1] > model.spring_a[s]))
      rows_sorted_ = false;
  rows_.build(n, model.spring_a, model.spring_b);
}

void SpringSystem::assemble(const SpringModel& model, const SpringState& state, const std::vector<Vec3>& f, double h,
                            std::vector<Vec3>& b) {
  zero_.assign(model.num_particles(), Vec3::Zero());
  assemble(model, state, f, h, zero_, b);
}

// b = h (f0 + h K v0), K v0 = -sum_s J_s (v_a - v_b), J_s = k (n n^T + t (I - n n^T)).
// Spring s adds g_s to b_a and -g_s to b_b: its force (sim/spring_law.h)
// times h, minus h^2 J_s (v_a - v_b). A x0 = M' x0 + the sum over the
// springs of B_s (x0_a - x0_b) at a and its opposite at b, so r = b - A x0
// takes g_s - B_s (x0_a - x0_b) where b takes g_s (a masked spring's block
// included: x0 is 0 at its fixed end, so that is its share of the free
// end's own block times x0).
MTCUT_SPRING_LOOP void SpringSystem::assemble(const SpringModel& model, const SpringState& state,
                                              const std::vector<Vec3>& f, double h, const std::vector<Vec3>& dv0,
                                              std::vector<Vec3>& r) {
  const std::size_t n = model.num_particles();
  update_layout(model);
  const double h2 = h * h;

  const double mass_factor = 1.0 + h * model.mass_damping;
  const double* inv_mass = model.inv_mass.data();
  for (std::size_t i = 0; i < n; ++i) {
    own_[i] = Sym3::scaled_identity(model.mass[i] * mass_factor);
    diag_[i] = own_[i];
    b_[i] = h * f[i];
    r[i] = b_[i] - own_[i].xx * dv0[i];
  }

  // One pass over each particle a's pairs of springs (a, c): B_s into the
  // diagonal blocks and the layout, g_s into b; springs at fixed particles
  // masked. Two springs per SSE2 register: one sqrtpd and one divpd serve
  // both. a's shares of its diagonal block and of b are summed in
  // registers, lane by lane. A pad lane repeats lane 0's other end with
  // stiffness and damping 0: everything it adds is exactly 0.
  //
  // In two steps over up to kChunk pairs at a time: first each pair's
  // geometry (gathered positions, direction, the two roots and the
  // division), then the rest. One pair's ~240 instructions in one go leave
  // the CPU's out-of-order window little room to overlap a pair's loads and
  // roots with the next pair's; a short first loop overlaps them across a
  // particle's pairs (the bench box's assembly: 1.91 -> 1.65 ms with warm
  // caches, ~4% after a solve). Same operations in the same order: same bits.
  const std::int32_t *start = rows_.start.data(), *other = rows_.other.data(), *lane_spring = rows_.lane_spring.data();
  BlockPair* blocks = rows_.blocks.data();
  const Vec3 *x = state.x.data(), *v = state.v.data(), *start_x = dv0.data();
  Vec3* b = b_.data();
  const double *rest_length = model.rest_length.data(), *stiffness = model.stiffness.data(),
               *damping = model.damping.data();
  const Lanes2 one = {1.0, 1.0}, tiny = {kTinyLength2, kTinyLength2};
  constexpr std::int32_t kChunk = 16;
  constexpr std::size_t kAhead = 4;  // 2 to 8 measured alike
  PairGeometry geometry[kChunk];
  for (std::size_t a = 0; a < n; ++a) {
    // The other ends' entries of particle a + kAhead, asked for now: within
    // a row they are scattered over the particles ahead (not a stream the
    // CPU's prefetcher follows), and after a solve they are out of L2.
    if (a + kAhead < n) {
      for (std::int32_t k = start[a + kAhead]; k < start[a + kAhead + 1]; ++k) {
        for (int lane = 0; lane < 2; ++lane) {
          const std::int32_t c = other[2 * k + lane];  // n for a pad: one past the end, never read
          __builtin_prefetch(x + c);
          __builtin_prefetch(v + c);
          __builtin_prefetch(start_x + c);
          __builtin_prefetch(b + c, 1);
          __builtin_prefetch(r.data() + c, 1);
          __builtin_prefetch(diag_.data() + c, 1);
        }
      }
    }
    const Vec3 xa = x[a], va = v[a], sa = start_x[a];
    const bool a_fixed = inv_mass[a] == 0;
    Lanes2 bx = {0, 0}, by = {0, 0}, bz = {0, 0}, rx = {0, 0}, ry = {0, 0}, rz = {0, 0};
    Lanes2 dxx = {0, 0}, dxy = {0, 0}, dxz = {0, 0}, dyy = {0, 0}, dyz = {0, 0}, dzz = {0, 0};
    for (std::int32_t first = start[a]; first < start[a + 1]; first += kChunk) {
      const std::int32_t last = std::min(first + kChunk, start[a + 1]);
      for (std::int32_t k = first; k < last; ++k) {
        const std::int32_t c0 = other[2 * k], s0 = lane_spring[2 * k];
        const bool pad = lane_spring[2 * k + 1] < 0;
        const std::int32_t c1 = pad ? c0 : other[2 * k + 1], s1 = pad ? s0 : lane_spring[2 * k + 1];
        const double on = pad ? 0.0 : 1.0;
        const Vec3 &x0 = x[c0], &x1 = x[c1];
        const Lanes2 dx = Lanes2{x0.x(), x1.x()} - xa.x(), dy = Lanes2{x0.y(), x1.y()} - xa.y(),
                     dz = Lanes2{x0.z(), x1.z()} - xa.z();
        // + kTinyLength2 is exact for any real spring, and a zero-length one
        // gets n = 0 and adds nothing; t = max(0, 1 - L / l), branch-free.
        const Lanes2 length2 = dx * dx + dy * dy + dz * dz;
        const Lanes2 inv_length = one / sqrt_lanes(length2 + tiny);
        const Lanes2 k_s = Lanes2{stiffness[s0], on * stiffness[s1]};
        const Lanes2 rest = Lanes2{rest_length[s0], rest_length[s1]};
        const Lanes2 t = positive_part(one - rest * inv_length);
        PairGeometry& g = geometry[k - first];
        g.nx = dx * inv_length, g.ny = dy * inv_length, g.nz = dz * inv_length;
        g.along = h * Lanes2{damping[s0], on * damping[s1]} + h2 * k_s * (one - t);
        g.across = h2 * k_s * t;
        g.stiffness = h * k_s, g.rest = rest, g.length = length2 * inv_length;  // l = |d|^2 / |d|
        g.root = sqrt_lanes(g.along);
      }
      for (std::int32_t k = first; k < last; ++k) {
        const PairGeometry& g = geometry[k - first];
        const Lanes2 nx = g.nx, ny = g.ny, nz = g.nz, along = g.along, across = g.across;
        const std::int32_t c0 = other[2 * k];
        const std::int32_t c1 = lane_spring[2 * k + 1] < 0 ? c0 : other[2 * k + 1];
        const Vec3 &v0 = v[c0], &v1 = v[c1];
        const Lanes2 ux = va.x() - Lanes2{v0.x(), v1.x()}, uy = va.y() - Lanes2{v0.y(), v1.y()},
                     uz = va.z() - Lanes2{v0.z(), v1.z()};
        const Lanes2 dn = nx * ux + ny * uy + nz * uz;
        // g_s = h f_a - h^2 J_s u, u = v_a - v_c: along n, the spring law at
        // h k, with J's n n^T part h^2 k (1 - t) folded into the dashpot's
        // h c (along), at n . (v_c - v_a) = -dn; across u, the rest of J.
        const Lanes2 coef = spring_tension(g.stiffness, g.rest, along, g.length, -dn);
        const Lanes2 gx = coef * nx - across * ux, gy = coef * ny - across * uy, gz = coef * nz - across * uz;
        bx += gx;
        by += gy;
        bz += gz;
        b[c0] -= Vec3(gx[0], gy[0], gz[0]);
        b[c1] -= Vec3(gx[1], gy[1], gz[1]);
        BlockPair blk = {g.root * nx, g.root * ny, g.root * nz, across};
        // g_s - B_s (x0_a - x0_c).
        const Vec3 &e0 = start_x[c0], &e1 = start_x[c1];
        const Lanes2 ex = sa.x() - Lanes2{e0.x(), e1.x()}, ey = sa.y() - Lanes2{e0.y(), e1.y()},
                     ez = sa.z() - Lanes2{e0.z(), e1.z()};
        const Lanes2 ew = blk.wx * ex + blk.wy * ey + blk.wz * ez;
        const Lanes2 hx = gx - (across * ex + ew * blk.wx), hy = gy - (across * ey + ew * blk.wy),
                     hz = gz - (across * ez + ew * blk.wz);
        rx += hx;
        ry += hy;
        rz += hz;
        r[c0] -= Vec3(hx[0], hy[0], hz[0]);
        r[c1] -= Vec3(hx[1], hy[1], hz[1]);
        const Lanes2 bxx = blk.wx * blk.wx + across, bxy = blk.wx * blk.wy, bxz = blk.wx * blk.wz,
                     byy = blk.wy * blk.wy + across, byz = blk.wy * blk.wz, bzz = blk.wz * blk.wz + across;
        dxx += bxx;
        dxy += bxy;
        dxz += bxz;
        dyy += byy;
        dyz += byz;
        dzz += bzz;
        for (int lane = 0; lane < 2; ++lane) {
          Sym3& d = diag_[static_cast<std::size_t>(lane ? c1 : c0)];
          d.xx += bxx[lane];
          d.xy += bxy[lane];
          d.xz += bxz[lane];
          d.yy += byy[lane];
          d.yz += byz[lane];
          d.zz += bzz[lane];
        }
        if (a_fixed || inv_mass[c0] == 0 || inv_mass[c1] == 0) [[unlikely]] {  // masked: fixed rows decouple
          for (int lane = 0; lane < 2; ++lane) {
            const auto c = static_cast<std::size_t>(lane ? c1 : c0);
            if (!a_fixed && inv_mass[c] != 0) continue;
            const SpringBlock one_block{Vec3(blk.wx[lane], blk.wy[lane], blk.wz[lane]), blk.across[lane]};
            if (!a_fixed) add_block(own_[a], one_block);
            if (inv_mass[c] != 0) add_block(own_[c], one_block);
            blk.wx[lane] = blk.wy[lane] = blk.wz[lane] = blk.across[lane] = 0;
          }
        }
        blocks[k] = blk;
      }
    }
    b[a] += Vec3(bx[0] + bx[1], by[0] + by[1], bz[0] + bz[1]);
    r[a] += Vec3(rx[0] + rx[1], ry[0] + ry[1], rz[0] + rz[1]);
    Sym3& d = diag_[a];
    d.xx += dxx[0] + dxx[1];
    d.xy += dxy[0] + dxy[1];
    d.xz += dxz[0] + dxz[1];
    d.yy += dyy[0] + dyy[1];
    d.yz += dyz[0] + dyz[1];
    d.zz += dzz[0] + dzz[1];
  }
  double b_norm2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (inv_mass[i] == 0) {
      r[i].setZero();
      diag_inverse_[i] = Sym3{};
    } else {
      b_norm2 += b[i].squaredNorm();
      diag_inverse_[i] = diag_[i].inverse();
    }
  }
  rhs_norm2_ = b_norm2;
}

}  // namespace mtcut::sim
