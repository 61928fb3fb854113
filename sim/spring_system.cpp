#include "sim/spring_system.h"

#include <algorithm>
#include <cmath>

namespace mtcut::sim {

Sym3 Sym3::inverse() const {
  const double cxx = yy * zz - yz * yz, cxy = xz * yz - xy * zz, cxz = xy * yz - xz * yy;
  const double cyy = xx * zz - xz * xz, cyz = xy * xz - xx * yz, czz = xx * yy - xy * xy;
  const double inv_det = 1.0 / (xx * cxx + xy * cxy + xz * cxz);
  return {cxx * inv_det, cxy * inv_det, cxz * inv_det, cyy * inv_det, cyz * inv_det, czz * inv_det};
}

void SpringSystem::resize(std::size_t n, std::size_t) {
  for (auto* v : {&own_, &diag_, &diag_inverse_}) v->resize(n);
  for (auto* v : {&rhat_, &t_, &u_, &acc_}) v->assign(n + 1, Vec3::Zero());  // [n] = 0: the pads' dummy
  for (auto* v : {&b_, &r_, &z_, &p_, &ut_, &q_}) v->resize(n);
}

// (A u)_i = own_i u_i + sum over i's springs of B_s (u_i - u_o) = own_i u_i
// + (sum B_s) u_i - the row's pull - the pushes of i's column, with sum B_s
// = diag_i - own_i (masked springs are 0 in the layout and in own_, not in
// diag_, at their fixed end). Any spring order: the pushes are added once
// every particle has pushed; acc_ is left all 0 but for its dummy.
void SpringSystem::multiply(const std::vector<Vec3>& u, std::vector<Vec3>& out) {
  const std::size_t n = own_.size();
  std::copy(u.begin(), u.begin() + static_cast<std::ptrdiff_t>(n), u_.begin());  // u_[n] stays 0
  std::fill(acc_.begin(), acc_.end(), Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 self = diag_inverse_[i].xx == 0 ? Vec3(own_[i] * u_[i]) : Vec3(diag_[i] * u_[i]);
    out[i] = self - rows_.pull(i, u_.data());
    rows_.push(i, u_[i], acc_.data());
  }
  for (std::size_t i = 0; i < n; ++i) {
    out[i] -= acc_[i];
    acc_[i].setZero();
  }
}

CgStats SpringSystem::solve(PreconditionerKind kind, const std::vector<Vec3>& b, double tolerance2,
                            int max_iterations, std::vector<Vec3>& x) {
  multiply(x, r_);
  for (std::size_t i = 0; i < b.size(); ++i) r_[i] = b[i] - r_[i];
  return solve_from_residual(kind, r_, tolerance2, max_iterations, x);
}

CgStats SpringSystem::solve_from_residual(PreconditionerKind kind, const std::vector<Vec3>& r, double tolerance2,
                                          int max_iterations, std::vector<Vec3>& x) {
  if (kind == PreconditionerKind::kSymmetricGaussSeidel && rows_sorted_)
    return solve_gauss_seidel(r, tolerance2, max_iterations, x);
  return solve_block_jacobi(r, tolerance2, max_iterations, x);
}

CgStats SpringSystem::solve_block_jacobi(const std::vector<Vec3>& r, double tolerance2, int max_iterations,
                                         std::vector<Vec3>& x) {
  const std::size_t n = own_.size();
  std::vector<Vec3>& ap = q_;
  double rz = 0, rr = 0;
  for (std::size_t i = 0; i < n; ++i) {
    r_[i] = r[i];
    z_[i] = diag_inverse_[i] * r_[i];
    p_[i] = z_[i];
    rz += r_[i].dot(z_[i]);
    rr += r_[i].squaredNorm();
  }
  CgStats stats;
  while (rr > tolerance2 && stats.iterations < max_iterations) {
    multiply(p_, ap);
    double pap = 0;
    for (std::size_t i = 0; i < n; ++i) pap += p_[i].dot(ap[i]);
    if (!(pap > 0)) break;  // converged to round-off
    const double alpha = rz / pap;
    double rz_next = 0;
    rr = 0;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * p_[i];
      r_[i] -= alpha * ap[i];
      z_[i] = diag_inverse_[i] * r_[i];
      rz_next += r_[i].dot(z_[i]);
      rr += r_[i].squaredNorm();
    }
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t i = 0; i < n; ++i) p_[i] = z_[i] + beta * p_[i];
    ++stats.iterations;
  }
  stats.residual2 = rr;
  return stats;
}

}  // namespace mtcut::sim
