#include "sim/spring_system.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "sim/forces.h"
#include "tests/sim/test_box.h"

namespace mtcut::sim {
namespace {

// A stretched box (every spring longer than at rest, so no transverse term
// is dropped and A is exactly M - h df/dv - h^2 df/dx), at rest, with its
// x = +0.05 face fixed, its springs in build_spring_model's order or shuffled.
struct Stretched {
  SpringModel model;
  SpringState state;
};

Stretched stretched_box(bool shuffle) {
  Stretched s;
  s.model = test::fixed_test_box();
  if (shuffle) test::shuffle_springs(s.model, 11);
  s.state = rest_state(s.model);
  for (auto& x : s.state.x) x *= 1.05;
  return s;
}

// A u, by central differences of compute_forces in x and in v.
std::vector<Vec3> finite_difference_product(const SpringModel& model, const SpringState& state, double h,
                                            const std::vector<Vec3>& u) {
  const std::size_t n = model.num_particles();
  const Environment env;
  const double eps = 1e-7;
  std::vector<Vec3> f_plus, f_minus, out(n, Vec3::Zero());
  for (int wrt_v = 0; wrt_v < 2; ++wrt_v) {
    SpringState plus = state, minus = state;
    auto& p = wrt_v ? plus.v : plus.x;
    auto& q = wrt_v ? minus.v : minus.x;
    for (std::size_t i = 0; i < n; ++i) {
      p[i] += eps * u[i];
      q[i] -= eps * u[i];
    }
    compute_forces(model, env, plus, f_plus);
    compute_forces(model, env, minus, f_minus);
    const double scale = wrt_v ? h : h * h;
    for (std::size_t i = 0; i < n; ++i) out[i] -= scale * (f_plus[i] - f_minus[i]) / (2 * eps);
  }
  for (std::size_t i = 0; i < n; ++i) {
    out[i] += model.mass[i] * u[i];
    if (model.inv_mass[i] == 0) out[i].setZero();  // fixed rows are decoupled
  }
  return out;
}

class SpringSystemProduct : public ::testing::TestWithParam<bool> {};

// The paired layout holds every spring once each way, at the right ends:
// the product matches the forces' derivatives.
TEST_P(SpringSystemProduct, MatchesTheForcesDerivatives) {
  const Stretched s = stretched_box(GetParam());
  const std::size_t n = s.model.num_particles();
  const double h = 1.0 / 60.0;
  std::vector<Vec3> f, b(n);
  compute_body_forces(s.model, Environment{}, s.state, f);
  SpringSystem system;
  system.assemble(s.model, s.state, f, h, b);
  EXPECT_EQ(system.rows_sorted(), !GetParam());
  std::mt19937 rng(4);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vec3> u(n), au(n);
  for (std::size_t i = 0; i < n; ++i)
    u[i] = s.model.inv_mass[i] == 0 ? Vec3::Zero() : Vec3(g(rng), g(rng), g(rng));
  system.multiply(u, au);
  const std::vector<Vec3> expected = finite_difference_product(s.model, s.state, h, u);
  double scale = 0;
  for (const auto& e : expected) scale = std::max(scale, e.norm());
  for (std::size_t i = 0; i < n; ++i) EXPECT_LT((au[i] - expected[i]).norm(), 1e-6 * scale) << i;
}

INSTANTIATE_TEST_SUITE_P(SortedAndShuffled, SpringSystemProduct, ::testing::Bool());

class SpringSystemRightHandSide : public ::testing::TestWithParam<bool> {};

// b = h (f + h K v): the forces at the state plus h times the derivative
// of the springs' elastic forces in x along v (central differences, the
// dashpots taken out: K leaves out their dependence on x), 0 at fixed
// particles.
TEST_P(SpringSystemRightHandSide, MatchesTheForcesAndTheirDerivative) {
  Stretched s = stretched_box(GetParam());
  const std::size_t n = s.model.num_particles();
  const double h = 1.0 / 60.0, eps = 1e-7;
  std::mt19937 rng(6);
  std::normal_distribution<double> g(0.0, 0.1);
  for (std::size_t i = 0; i < n; ++i)
    s.state.v[i] = s.model.inv_mass[i] == 0 ? Vec3::Zero() : Vec3(g(rng), g(rng), g(rng));
  const Environment env;
  std::vector<Vec3> body, b(n), f, f_plus, f_minus;
  compute_body_forces(s.model, env, s.state, body);
  SpringSystem system;
  system.assemble(s.model, s.state, body, h, b);
  compute_forces(s.model, env, s.state, f);
  SpringState plus = s.state, minus = s.state;
  for (std::size_t i = 0; i < n; ++i) {
    plus.x[i] += eps * s.state.v[i];
    minus.x[i] -= eps * s.state.v[i];
  }
  SpringModel elastic = s.model;
  std::fill(elastic.damping.begin(), elastic.damping.end(), 0.0);
  compute_forces(elastic, env, plus, f_plus);
  compute_forces(elastic, env, minus, f_minus);
  double scale = 0;
  std::vector<Vec3> expected(n);
  for (std::size_t i = 0; i < n; ++i) {
    expected[i] = s.model.inv_mass[i] == 0 ? Vec3::Zero() : Vec3(h * (f[i] + h * (f_plus[i] - f_minus[i]) / (2 * eps)));
    scale = std::max(scale, expected[i].norm());
  }
  for (std::size_t i = 0; i < n; ++i) EXPECT_LT((b[i] - expected[i]).norm(), 1e-6 * scale) << i;
}

INSTANTIATE_TEST_SUITE_P(SortedAndShuffled, SpringSystemRightHandSide, ::testing::Bool());

class SpringSystemResidual : public ::testing::TestWithParam<bool> {};

// The assembly from a start dv0 writes b - A dv0 (A and b as assembled
// without one, the product multiply's) and the same blocks, and its |b|^2
// is b's; fixed rows are 0 in both.
TEST_P(SpringSystemResidual, IsTheRightHandSideMinusTheProduct) {
  Stretched s = stretched_box(GetParam());
  const std::size_t n = s.model.num_particles();
  const double h = 1.0 / 60.0;
  std::mt19937 rng(9);
  std::normal_distribution<double> g(0.0, 0.1);
  std::vector<Vec3> dv0(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool fixed = s.model.inv_mass[i] == 0;
    s.state.v[i] = fixed ? Vec3::Zero() : Vec3(g(rng), g(rng), g(rng));
    dv0[i] = fixed ? Vec3::Zero() : Vec3(g(rng), g(rng), g(rng));
  }
  std::vector<Vec3> f, b(n), r(n), a_dv0(n);
  compute_body_forces(s.model, Environment{}, s.state, f);
  SpringSystem plain, from_start;
  plain.assemble(s.model, s.state, f, h, b);
  from_start.assemble(s.model, s.state, f, h, dv0, r);
  plain.multiply(dv0, a_dv0);
  double b_norm2 = 0, scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    b_norm2 += b[i].squaredNorm();
    scale = std::max({scale, b[i].norm(), a_dv0[i].norm()});
  }
  EXPECT_GT(scale, 0);
  EXPECT_DOUBLE_EQ(plain.rhs_norm2(), b_norm2);
  EXPECT_DOUBLE_EQ(from_start.rhs_norm2(), b_norm2);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_LT((r[i] - (b[i] - a_dv0[i])).norm(), 1e-12 * scale) << i;
    if (s.model.inv_mass[i] == 0) {
      EXPECT_EQ(r[i], Vec3::Zero()) << i;
    }
  }
  // The same system: equal products.
  std::vector<Vec3> a_dv0_too(n);
  from_start.multiply(dv0, a_dv0_too);
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(a_dv0_too[i], a_dv0[i]) << i;
}

INSTANTIATE_TEST_SUITE_P(SortedAndShuffled, SpringSystemResidual, ::testing::Bool());

// One SpringSystem reused on models of the same size but other springs
// (what a rebuild after a cut can give) lays them out anew each time.
TEST(SpringSystemLayout, FollowsTheModelsSprings) {
  SpringSystem system;
  for (const bool shuffle : {false, true, false}) {
    const Stretched s = stretched_box(shuffle);
    const std::size_t n = s.model.num_particles();
    const double h = 1.0 / 60.0;
    std::vector<Vec3> f, b(n);
    compute_body_forces(s.model, Environment{}, s.state, f);
    system.assemble(s.model, s.state, f, h, b);
    EXPECT_EQ(system.rows_sorted(), !shuffle);
    std::vector<Vec3> u(n), au(n);
    for (std::size_t i = 0; i < n; ++i)
      u[i] = s.model.inv_mass[i] == 0 ? Vec3::Zero() : Vec3(std::sin(1.0 * i), std::cos(2.0 * i), 0.5);
    system.multiply(u, au);
    const std::vector<Vec3> expected = finite_difference_product(s.model, s.state, h, u);
    double scale = 0;
    for (const auto& e : expected) scale = std::max(scale, e.norm());
    for (std::size_t i = 0; i < n; ++i) EXPECT_LT((au[i] - expected[i]).norm(), 1e-6 * scale) << i;
  }
}

}  // namespace
}  // namespace mtcut::sim
