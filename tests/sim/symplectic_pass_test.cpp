#include "sim/symplectic_pass.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/forces.h"
#include "sim/stepper.h"
#include "tests/sim/test_box.h"

namespace mtcut::sim {
namespace {

// A box with its x = +0.05 face fixed, volume terms on, and a state moved
// off rest (positions and velocities) so every force is at work.
struct MovedBox {
  SpringModel model;
  SpringState state;
};

MovedBox moved_box(double volume_stiffness) {
  MovedBox out;
  out.model = test::fixed_test_box(volume_stiffness);
  out.state = rest_state(out.model);
  for (std::size_t i = 0; i < out.model.num_particles(); ++i) {
    const double u = static_cast<double>(i);
    out.state.x[i] += 1e-3 * Vec3(std::sin(u), std::cos(1.3 * u), std::sin(0.7 * u));
    if (out.model.inv_mass[i] != 0) out.state.v[i] = 0.05 * Vec3(std::cos(u), std::sin(2.1 * u), std::cos(0.3 * u));
  }
  return out;
}

// The plain three-pass form: forces, then v += h f / m, x += h v, then contacts.
void plain_substep(const SpringModel& model, const Environment& env, double h, SpringState& state) {
  std::vector<Vec3> f;
  compute_forces(model, env, state, f);
  for (std::size_t i = 0; i < model.num_particles(); ++i) {
    state.v[i] += (h * model.inv_mass[i]) * f[i];
    state.x[i] += h * state.v[i];
  }
  apply_contacts(model, env, state);
}

class SymplecticPass : public ::testing::TestWithParam<double> {};

TEST_P(SymplecticPass, MatchesThePlainSubStepToRoundOff) {
  MovedBox s = moved_box(GetParam());
  ASSERT_TRUE(springs_in_run_order(s.model));
  Environment env;
  env.floor = Plane{Vec3(0, 0, 1), -0.02};  // cuts through the box: some particles start below it
  env.tool = Capsule{Vec3(0, 0, -1), Vec3(0, 0, 1), 0.01};
  const double h = 1e-5;
  SpringState plain = s.state, pass = s.state;
  RunLanes lanes;
  lanes.fill(s.model);
  PassState scratch;
  double x_scale = 0, v_scale = 0;
  for (int k = 0; k < 20; ++k) plain_substep(s.model, env, h, plain);
  symplectic_substeps(s.model, lanes, env, true, h, 20, pass, scratch);
  for (std::size_t i = 0; i < plain.x.size(); ++i) {
    x_scale = std::max(x_scale, plain.x[i].norm());
    v_scale = std::max(v_scale, plain.v[i].norm());
  }
  for (std::size_t i = 0; i < plain.x.size(); ++i) {
    EXPECT_LT((pass.x[i] - plain.x[i]).norm(), 1e-13 * x_scale) << i;
    EXPECT_LT((pass.v[i] - plain.v[i]).norm(), 1e-10 * v_scale) << i;
    for (int c = 0; c < 4; ++c) EXPECT_EQ(scratch.acc[i].p[c], 0.0) << i;  // left zero for the next step
    if (s.model.inv_mass[i] == 0) {
      EXPECT_EQ(pass.x[i], s.state.x[i]) << i;  // fixed stay put
    }
  }
}

INSTANTIATE_TEST_SUITE_P(WithAndWithoutVolumeTerms, SymplecticPass, ::testing::Values(0.0, 0.5));

TEST(SymplecticPass, RunOrderIsCheckedNotAssumed) {
  MovedBox s = moved_box(0.0);
  EXPECT_TRUE(springs_in_run_order(s.model));
  SpringModel swapped = s.model;
  std::swap(swapped.spring_a[3], swapped.spring_b[3]);  // a > b
  EXPECT_FALSE(springs_in_run_order(swapped));
  SpringModel unsorted = s.model;
  std::swap(unsorted.spring_a.front(), unsorted.spring_a.back());
  std::swap(unsorted.spring_b.front(), unsorted.spring_b.back());
  EXPECT_FALSE(springs_in_run_order(unsorted));
}

}  // namespace
}  // namespace mtcut::sim
