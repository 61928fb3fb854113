// SpringSystem's SSOR-preconditioned conjugate gradients (Eisenstat's
// trick): a backward and a forward sweep over the particles per iteration,
// then one pass for the update (the system and its assembly:
// sim/spring_system.cpp, sim/system_assembly.cpp).
//
// SSOR with relaxation w: W = D / w + L, A = W + W^T - (2 / w - 1) D.
// CG on Ahat xhat = W^-1 b, Ahat = W^-1 A W^-T, preconditioned by D (z =
// D rhat): PCG on A with M ~ W D^-1 W^T. Eisenstat: with t = W^-T p (backward
// sweep), Ahat p = t + W^-1 (p - (2 / w - 1) D t) (forward sweep), and
// x = W^-T xhat moves by alpha t. Off-diagonal blocks are -B_s, so with
// sum_i = sum B_s t_o over i's row (o > i), t_i = w D_i^-1 (p_i + sum_i) and
// (p - (2 / w - 1) D t)_i = (w - 1) p_i - (2 - w) sum_i; in the forward
// sweep, each particle finds its column's sum (o < i) of what W^-1 gave the
// earlier particles in acc_, pushed there by them, and pushes its own.
//
// The start, rhat = W^-1 r, r = b - A x given (the assembly sums it), is
// one forward pass.
//
// The true residual r = W rhat = D rhat / w + L rhat costs a sweep, so it is
// computed only when rhat . D rhat, scaled by the ratio |r|^2 / rhat . D rhat
// at the last check, predicts convergence.

#include <algorithm>
#include <cstddef>

#include "sim/lanes2.h"
#include "sim/spring_system.h"

namespace mtcut::sim {

MTCUT_SPRING_LOOP CgStats SpringSystem::solve_gauss_seidel(const std::vector<Vec3>& r0, double tolerance2,
                                                           int max_iterations, std::vector<Vec3>& x_vec) {
  const std::size_t n = own_.size();
  const Sym3* diag = diag_.data();
  const Sym3* dinv = diag_inverse_.data();
  // t is pulled from: n + 1 entries, the last 0. acc (n + 1) takes the
  // forward sweeps' pushes; each particle reads its entry and zeroes it.
  Vec3 *x = x_vec.data(), *rhat = rhat_.data(), *z = z_.data(), *p = p_.data(), *t = t_.data(), *ut = ut_.data(),
       *q = q_.data(), *acc = acc_.data();
  // acc_i: the sum of i's column's pushes, then 0 again.
  const auto take = [acc](std::size_t i) {
    const Vec3 sum = acc[i];
    acc[i].setZero();
    return sum;
  };

  // The true residual |W rhat|^2, (W rhat)_i = D_i rhat_i / w - sum of i's
  // column blocks times rhat at their other ends.
  const auto true_residual2 = [&] {
    double rr = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 r = z[i] * (1 / kRelaxation) - take(i);
      rows_.push(i, rhat[i], acc);
      rr += r.squaredNorm();
    }
    return rr;
  };

  // One forward pass: rhat = W^-1 r0.
  double rr = 0, rz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    rr += r0[i].squaredNorm();
    rhat[i] = dinv[i] * (kRelaxation * (r0[i] + take(i)));
    rows_.push(i, rhat[i], acc);
    z[i] = diag[i] * rhat[i];
    p[i] = z[i];
    rz += rhat[i].dot(z[i]);
  }
  double ratio = rz > 0 ? rr / rz : 1.0;  // |r|^2 / rhat . D rhat at the last check
  bool rr_current = true;
  CgStats stats;
  double beta = 0;
  while (stats.iterations < max_iterations) {
    if (ratio * rz <= tolerance2) {
      if (!rr_current) {
        rr = true_residual2();
        ratio = rz > 0 ? rr / rz : 1.0;
        rr_current = true;
      }
      if (rr <= tolerance2) break;
    }
    for (std::size_t i = n; i-- > 0;) {  // p = z + beta p; t = W^-T p
      const Vec3 sum = rows_.pull(i, t);
      ut[i] = sum;
      p[i] = z[i] + beta * p[i];
      t[i] = dinv[i] * (kRelaxation * (p[i] + sum));
    }
    double pq = 0;
    for (std::size_t i = 0; i < n; ++i) {  // q = Ahat p = t + W^-1 (p - (2 / w - 1) D t)
      const Vec3 sum = take(i);
      const Vec3 sv = dinv[i] * (kRelaxation * (sum + (kRelaxation - 1) * p[i] - (2 - kRelaxation) * ut[i]));
      rows_.push(i, sv, acc);
      q[i] = t[i] + sv;
      pq += p[i].dot(q[i]);
    }
    if (!(pq > 0)) break;  // converged to round-off
    const double alpha = rz / pq;
    double rz_next = 0;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * t[i];
      rhat[i] -= alpha * q[i];
      z[i] = diag[i] * rhat[i];
      rz_next += rhat[i].dot(z[i]);
    }
    beta = rz_next / rz;
    rz = rz_next;
    rr_current = false;
    ++stats.iterations;
  }
  if (!rr_current) rr = true_residual2();
  stats.residual2 = rr;
  return stats;
}


}  // namespace mtcut::sim
