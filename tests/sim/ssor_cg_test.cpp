// The SSOR-preconditioned CG (sim/ssor_cg.cpp) against a plain,
// unpreconditioned reference CG on the same random system: same solution
// from a cold or a warm start, the true residual reported, and x complete
// when the iterations run out.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>

#include "sim/forces.h"
#include "sim/spring_system.h"
#include "tests/sim/test_box.h"

namespace mtcut::sim {
namespace {

using test::kDt;

double dot(const std::vector<Vec3>& u, const std::vector<Vec3>& w) {
  double sum = 0;
  for (std::size_t i = 0; i < u.size(); ++i) sum += u[i].dot(w[i]);
  return sum;
}

// A random SPD spring system: the fixed test box with every spring's
// stiffness and damping scaled by a random factor in [0.1, 10], jittered
// and moving, assembled at dt = 1/60.
test::JitteredSystem random_system(unsigned seed) {
  SpringModel model = test::fixed_test_box();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> log_scale(std::log(0.1), std::log(10.0));
  for (std::size_t s = 0; s < model.num_springs(); ++s) {
    const double scale = std::exp(log_scale(rng));
    model.stiffness[s] *= scale;
    model.damping[s] *= scale;
  }
  EXPECT_TRUE(model.validate().ok());
  test::JitteredSystem c = test::jittered_system(std::move(model), rng, kDt);
  EXPECT_TRUE(c.system.rows_sorted());
  return c;
}

// Textbook CG on A x = b from x = 0 with the system's product, to |r|^2 <= tolerance2.
std::vector<Vec3> reference_cg(SpringSystem& system, const std::vector<Vec3>& b, double tolerance2) {
  const std::size_t n = b.size();
  std::vector<Vec3> x(n, Vec3::Zero()), r = b, p = b, ap(n);
  double rr = dot(r, r);
  for (int k = 0; k < 100000 && rr > tolerance2; ++k) {
    system.multiply(p, ap);
    const double alpha = rr / dot(p, ap);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * p[i];
      r[i] -= alpha * ap[i];
    }
    const double rr_next = dot(r, r);
    for (std::size_t i = 0; i < n; ++i) p[i] = r[i] + (rr_next / rr) * p[i];
    rr = rr_next;
  }
  return x;
}

// |b - A x|^2.
double residual2(SpringSystem& system, const std::vector<Vec3>& b, const std::vector<Vec3>& x) {
  std::vector<Vec3> ax(x.size());
  system.multiply(x, ax);
  double rr = 0;
  for (std::size_t i = 0; i < x.size(); ++i) rr += (b[i] - ax[i]).squaredNorm();
  return rr;
}

// From 0 and from a random warm start, to a tight tolerance: the plain
// CG's solution, and the residual reported is the true one.
TEST(SsorCg, GivesTheReferenceCgsSolution) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    test::JitteredSystem c = random_system(seed);
    const std::size_t n = c.b.size();
    const double tolerance2 = 1e-24 * dot(c.b, c.b);
    const std::vector<Vec3> expected = reference_cg(c.system, c.b, tolerance2);
    std::mt19937 rng(seed + 100);
    std::normal_distribution<double> g(0.0, 0.01);
    for (const bool warm : {false, true}) {
      std::vector<Vec3> x(n, Vec3::Zero());
      if (warm)
        for (std::size_t i = 0; i < n; ++i)
          if (c.model.inv_mass[i] != 0) x[i] = Vec3(g(rng), g(rng), g(rng));
      const CgStats stats = c.system.solve(PreconditionerKind::kSymmetricGaussSeidel, c.b, tolerance2, 1000, x);
      EXPECT_LT(stats.iterations, 1000) << seed;
      EXPECT_LE(stats.residual2, tolerance2);
      // The same residual summed two ways: at |r| ~ 1e-12 |b| they agree to
      // round-off in A x, ~1e-16 |b| (1e-3 of the tolerance in |r|^2).
      const double rr = residual2(c.system, c.b, x);
      EXPECT_NEAR(rr, stats.residual2, 1e-2 * tolerance2) << seed;
      double diff = 0;
      for (std::size_t i = 0; i < n; ++i) diff += (x[i] - expected[i]).squaredNorm();
      EXPECT_LT(std::sqrt(diff), 1e-9 * std::sqrt(dot(expected, expected))) << seed << (warm ? " warm" : " cold");
    }
  }
}

// From a warm start with the residual the assembly sums there (assemble
// with a start), both solvers reach |b - A x|^2 <= tolerance2, measured with
// multiply, and the reference CG's solution.
TEST(SsorCg, ContinuesFromTheAssemblysResidual) {
  for (const auto kind : {PreconditionerKind::kSymmetricGaussSeidel, PreconditionerKind::kBlockJacobi}) {
    test::JitteredSystem c = random_system(5);
    const std::size_t n = c.b.size();
    const double tolerance2 = 1e-20 * dot(c.b, c.b);
    const std::vector<Vec3> expected = reference_cg(c.system, c.b, 1e-28 * dot(c.b, c.b));
    std::mt19937 rng(55);
    std::normal_distribution<double> g(0.0, 0.01);
    std::vector<Vec3> x(n, Vec3::Zero()), f, r(n);
    for (std::size_t i = 0; i < n; ++i)
      if (c.model.inv_mass[i] != 0) x[i] = Vec3(g(rng), g(rng), g(rng));
    compute_body_forces(c.model, Environment{}, c.state, f);
    SpringSystem system;
    system.assemble(c.model, c.state, f, kDt, x, r);
    EXPECT_GT(dot(r, r), 1e6 * tolerance2);  // the start is far from the solution
    const CgStats stats = system.solve_from_residual(kind, r, tolerance2, 1000, x);
    EXPECT_GT(stats.iterations, 0);
    EXPECT_LE(stats.residual2, tolerance2);
    EXPECT_LE(residual2(c.system, c.b, x), 1.01 * tolerance2);
    double diff = 0;
    for (std::size_t i = 0; i < n; ++i) diff += (x[i] - expected[i]).squaredNorm();
    EXPECT_LT(std::sqrt(diff), 1e-6 * std::sqrt(dot(expected, expected)));
  }
}

// Stopped by max_iterations before the tolerance: the reported residual is
// x's, and falls with each iteration allowed.
TEST(SsorCg, AppliesTheLastStepWhenTheIterationsRunOut) {
  test::JitteredSystem c = random_system(7);
  const std::size_t n = c.b.size();
  const double tolerance2 = 1e-24 * dot(c.b, c.b);
  double last = dot(c.b, c.b);
  for (const int cap : {1, 2, 3, 5, 8}) {
    std::vector<Vec3> x(n, Vec3::Zero());
    const CgStats stats = c.system.solve(PreconditionerKind::kSymmetricGaussSeidel, c.b, tolerance2, cap, x);
    EXPECT_EQ(stats.iterations, cap);
    const double rr = residual2(c.system, c.b, x);
    EXPECT_NEAR(rr, stats.residual2, 1e-9 * rr) << cap;
    EXPECT_LT(rr, last) << cap;
    last = rr;
  }
}

}  // namespace
}  // namespace mtcut::sim
