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
// The start, rhat = W^-1 (b - A x), is one forward pass: A x's row sums
// pulled, its column sums and W^-1's pushed from the same blocks (push2),
// in the order multiply adds them (the same r, bit for bit).
//
// The true residual r = W rhat = D rhat / w + L rhat costs a sweep, so it is
// computed only when rhat . D rhat, scaled by the ratio |r|^2 / rhat . D rhat
// at the last check, predicts convergence.

#include <algorithm>
#include <cstddef>

#include "sim/lanes2.h"
#include "sim/spring_system.h"

namespace mtcut::sim {

MTCUT_SPRING_LOOP CgStats SpringSystem::solve_gauss_seidel(const std::vector<Vec3>& b, double tolerance2,
                                                           int max_iterations, std::vector<Vec3>& x_vec) {
  const std::size_t n = own_.size();
  const Sym3* diag = diag_.data();
  const Sym3* dinv = diag_inverse_.data();
  // t is pulled from: n + 1 entries, the last 0. acc (n + 1) takes the
  // forward sweeps' pushes; each particle reads its entry and zeroes it.
  Vec3 *x = x_vec.data(), *rhat = rhat_.data(), *z = z_.data(), *p = p_.data(), *t = t_.data(), *ut = ut_.data(),
       *q = q_.data(), *sv = s_.data(), *acc = acc_.data();
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

  // One forward pass: r = b - A x, as multiply computes it (x's row pulled
  // from the padded copy u, its column pushed into acc_x by the earlier
  // particles), and rhat = W^-1 r, both pushes from the same blocks.
  std::copy(x_vec.begin(), x_vec.begin() + static_cast<std::ptrdiff_t>(n), u_.begin());  // u_[n] stays 0
  const Vec3* u = u_.data();
  Vec3* acc_x = acc_x_.data();
  double rr = 0, rz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 self = dinv[i].xx == 0 ? Vec3(own_[i] * u[i]) : Vec3(diag[i] * u[i]);
    Vec3 ax = self - rows_.pull(i, u);
    ax -= acc_x[i];
    acc_x[i].setZero();
    const Vec3 r = b[i] - ax;
    rr += r.squaredNorm();
    rhat[i] = dinv[i] * (kRelaxation * (r + take(i)));
    rows_.push2(i, u[i], acc_x, rhat[i], acc);
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
      sv[i] = dinv[i] * (kRelaxation * (sum + (kRelaxation - 1) * p[i] - (2 - kRelaxation) * ut[i]));
      rows_.push(i, sv[i], acc);
      q[i] = t[i] + sv[i];
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
