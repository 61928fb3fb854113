#include "sim/spring_law.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/predicates.h"
#include "sim/lanes2.h"
#include "sim/lanes4.h"

namespace mtcut::sim {
namespace {

using engine::Vec3;

// One spring's inputs: d = x_b - x_a, u = v_b - v_a, k, L, c.
struct SpringCase {
  Vec3 d, u;
  double k, rest, c;
};

const SpringCase kCases[] = {
    {{2, 0, 0}, {1, 0, 0}, 3, 1, 0.5},                             // stretched, separating
    {{0.3, -0.2, 0.1}, {-0.4, 0.05, 0.2}, 1200, 0.5, 2.5},         // compressed, closing
    {{1e-3, 2e-3, -1e-3}, {0.01, 0, -0.03}, 5e4, 2e-3, 0.7},      // a short stiff one
    {{0.1, 0.1, 0.1}, {0.2, -0.1, 0.05}, 10, std::sqrt(0.03), 0},  // at rest, undamped
};

double tension(const SpringCase& s) {
  const double l = s.d.norm();
  return spring_tension(s.k, s.rest, s.c, l, (s.d / l).dot(s.u));
}

double coefficient(const SpringCase& s) {
  const double l2 = s.d.squaredNorm();
  double coef = 0;
  spring_coefficient(s.k, s.k * s.rest, s.c, s.d.dot(s.u), std::sqrt(l2), 1.0 / l2, coef);
  return coef;
}

TEST(SpringLaw, AnExactCaseGivesHookePlusDashpot) {
  // l = 2, n = x, n . u = 1: 3 (2 - 1) + 0.5 * 1; as a multiple of d, half that.
  EXPECT_EQ(tension(kCases[0]), 3.5);
  EXPECT_EQ(coefficient(kCases[0]), 1.75);
}

TEST(SpringLaw, ItsTwoArrangementsGiveTheSameForce) {
  for (const SpringCase& s : kCases) {
    const Vec3 along_n = tension(s) * s.d.normalized(), along_d = coefficient(s) * s.d;
    const double scale = s.k * s.d.norm() + s.c * s.u.norm();  // the terms' size (the last case's sum is ~0)
    EXPECT_LE((along_n - along_d).norm(), 1e-14 * scale) << s.d.transpose();
  }
}

TEST(SpringLaw, EachLaneIsTheScalarResultBitForBit) {
  // Four springs as the pass's quads (q_), the first two as its pairs (p_).
  Lanes4 q_k{}, q_kl{}, q_c{}, q_du{}, q_l{}, q_il2{}, q_coef{};
  Lanes2 p_k{}, p_rest{}, p_c{}, p_l{}, p_nu{}, p_kl{}, p_du{}, p_il2{}, p_coef{};
  for (int i = 0; i < 4; ++i) {
    const SpringCase& s = kCases[i];
    const double length2 = s.d.squaredNorm(), length = std::sqrt(length2);
    q_k[i] = s.k, q_kl[i] = s.k * s.rest, q_c[i] = s.c, q_du[i] = s.d.dot(s.u), q_l[i] = length;
    q_il2[i] = 1.0 / length2;
    if (i >= 2) continue;
    p_k[i] = s.k, p_rest[i] = s.rest, p_c[i] = s.c, p_l[i] = length, p_nu[i] = (s.d / length).dot(s.u);
    p_kl[i] = q_kl[i], p_du[i] = q_du[i], p_il2[i] = q_il2[i];
  }
  spring_coefficient(q_k, q_kl, q_c, q_du, q_l, q_il2, q_coef);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(q_coef[i], coefficient(kCases[i])) << i;
  const Lanes2 p_tension = spring_tension(p_k, p_rest, p_c, p_l, p_nu);
  spring_coefficient(p_k, p_kl, p_c, p_du, p_l, p_il2, p_coef);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(p_tension[i], tension(kCases[i])) << i;
    EXPECT_EQ(p_coef[i], coefficient(kCases[i])) << i;
  }
}

}  // namespace
}  // namespace mtcut::sim
