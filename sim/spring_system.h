#pragma once
// The linear system of one implicit Euler step (Baraff & Witkin 1998) and
// the preconditioned conjugate gradients that solve it.
//
//   A dv = b,  A = M (1 + h alpha) - h D - h^2 K,  b = h (f0 + h K v0).
//
// Why this shape. A is kept in per-spring form, never as a sparse matrix:
// spring s = (a, b) adds the symmetric block
//   B_s = w_s w_s^T + across_s I,   w_s = sqrt(along_s) n_s,
// to the diagonal blocks of a and b and -B_s to the two off-diagonal ones
// (along_s = h c + h^2 k (1 - t), across_s = h^2 k t, t = max(0, 1 - L / l):
// the transverse term of a compressed spring is dropped so A stays SPD).
// Everything is rebuilt per step in O(n + m) from the model and the state:
// nothing is factorized, so a cut or an LOD change costs no stall.
//
// A spring touching a fixed particle is "masked": its block joins the free
// end's diagonal and its off-diagonal blocks are 0, so fixed rows are
// decoupled (their dv is held at 0) without a test in the hot loops.
//
// Two preconditioners:
//  - block Jacobi: the exact inverse 3x3 diagonal blocks D_i^-1;
//  - block SSOR (symmetric Gauss-Seidel over-relaxed by kRelaxation),
//    M ~ (D / w + L) D^-1 (D / w + L^T), with L the strictly lower
//    off-diagonal blocks in particle order, applied with Eisenstat's trick
//    (CG on W^-1 A W^-T, W = D / w + L): one backward and one forward sweep
//    over the springs per iteration, about the cost of a product with A,
//    for well under half the iterations. The backward sweep pulls each
//    particle's sum from its springs to later particles; the forward sweep
//    pushes each particle's share to them (sim/spring_pairs.h); they need
//    the springs sorted by spring_a with a < b (build_spring_model's
//    order); otherwise the solver falls back to block Jacobi.
// Both stop on the true residual |b - A x|, so they are equally accurate.
// Scratch and the paired layout are rebuilt when the model's springs change
// (their ends are compared at each assembly, O(n_springs)), never otherwise.

#include <cstdint>
#include <vector>

#include "sim/spring_model.h"
#include "sim/spring_pairs.h"
#include "sim/spring_state.h"

namespace mtcut::sim {

enum class PreconditionerKind { kBlockJacobi, kSymmetricGaussSeidel };

// The SSOR relaxation factor w (1 = symmetric Gauss-Seidel). On the bench
// box 1.2 saves ~6% of the iterations over 1; the optimum grows with the
// stiffness, and anything in (0, 2) keeps the preconditioner SPD.
inline constexpr double kRelaxation = 1.2;

// A symmetric 3x3 matrix (xx, xy, xz, yy, yz, zz).
struct Sym3 {
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;

  static Sym3 scaled_identity(double s) { return {s, 0, 0, s, 0, s}; }
  Vec3 operator*(const Vec3& u) const {
    return {xx * u.x() + xy * u.y() + xz * u.z(), xy * u.x() + yy * u.y() + yz * u.z(),
            xz * u.x() + yz * u.y() + zz * u.z()};
  }
  // The inverse; the matrix must be non-singular.
  Sym3 inverse() const;
};

// Spring s's block B_s = w w^T + across I.
struct SpringBlock {
  Vec3 w = Vec3::Zero();
  double across = 0;

  Vec3 operator*(const Vec3& u) const { return across * u + w.dot(u) * w; }
};

struct CgStats {
  int iterations = 0;
  double residual2 = 0;  // |b - A x|^2 at the end
};

class SpringSystem {
 public:
  // Builds A at state.x for a step of h seconds and writes b (n_particles;
  // 0 at fixed particles). `f` (n_particles) are the forces at the state
  // other than the springs' (compute_body_forces); the spring forces are
  // added here, in the same pass as the blocks.
  void assemble(const SpringModel& model, const SpringState& state, const std::vector<Vec3>& f, double h,
                std::vector<Vec3>& b);
  // The same, but writes the residual r = b - A x0 at a start x0 (0 at
  // fixed particles), each spring's share of A x0 taken in the pass that
  // builds its block: what solve_from_residual continues from, with no pass
  // of its own for the residual.
  void assemble(const SpringModel& model, const SpringState& state, const std::vector<Vec3>& f, double h,
                const std::vector<Vec3>& x0, std::vector<Vec3>& r);
  // |b|^2 of the last assembly (CG's stopping scale).
  double rhs_norm2() const { return rhs_norm2_; }

  // Solves A x = b from the given x (0 at fixed particles) until
  // |b - A x|^2 <= tolerance2 or max_iterations.
  CgStats solve(PreconditionerKind kind, const std::vector<Vec3>& b, double tolerance2, int max_iterations,
                std::vector<Vec3>& x);
  // The same from x with its residual r = b - A x given (assemble's).
  CgStats solve_from_residual(PreconditionerKind kind, const std::vector<Vec3>& r, double tolerance2,
                              int max_iterations, std::vector<Vec3>& x);

  // out = A u (n_particles). Not const: u is copied into scratch with the pads' dummy.
  void multiply(const std::vector<Vec3>& u, std::vector<Vec3>& out);

  // The system's exact diagonal blocks and their inverses (0 at fixed
  // particles), for tests.
  const std::vector<Sym3>& diagonal() const { return diag_; }
  // Springs sorted by their first particle: the Gauss-Seidel sweeps can run.
  bool rows_sorted() const { return rows_sorted_; }

 private:
  // Both continue from x with its residual r.
  CgStats solve_block_jacobi(const std::vector<Vec3>& r, double tolerance2, int max_iterations, std::vector<Vec3>& x);
  CgStats solve_gauss_seidel(const std::vector<Vec3>& r, double tolerance2, int max_iterations, std::vector<Vec3>& x);
  void resize(std::size_t n, std::size_t m);
  // Lays the springs out in pairs when their ends changed since the last call.
  void update_layout(const SpringModel& model);

  // The springs' ends the layout was built for (n_springs each).
  std::vector<std::int32_t> layout_a_, layout_b_;
  std::size_t layout_n_ = 0;
  // The springs' masked blocks by first particle (rows: the other end is
  // later when the springs are sorted).
  PairedSide rows_;
  bool rows_sorted_ = false;
  // (n_particles) the mass term plus masked springs' blocks (what the
  // per-spring form of A misses), the full diagonal blocks, their inverses.
  std::vector<Sym3> own_, diag_, diag_inverse_;
  // b while an assembly sums it (n_particles), |b|^2 once it has.
  std::vector<Vec3> b_;
  double rhs_norm2_ = 0;
  // CG scratch: (n_particles + 1, the last entry the pads' dummy, kept 0)
  // for the vectors the sweeps pull from and the pushes' accumulator (all 0
  // between sweeps), (n_particles) for the others (zero_: all 0, the start
  // of assemble without one).
  std::vector<Vec3> rhat_, t_, u_, acc_;
  std::vector<Vec3> r_, z_, p_, ut_, q_, zero_;
};

}  // namespace mtcut::sim
