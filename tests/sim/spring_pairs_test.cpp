#include "sim/spring_pairs.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace mtcut::sim {
namespace {

// A random layout: n particles, m springs with random keys and other ends
// (odd and even counts per particle, some particles with none), random blocks.
struct RandomSide {
  std::size_t n = 37;
  std::vector<std::int32_t> key, other_end;
  std::vector<Vec3> w;
  std::vector<double> across;
  PairedSide side;

  explicit RandomSide(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::int32_t> particle(0, static_cast<std::int32_t>(n) - 1);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int s = 0; s < 150; ++s) {
      key.push_back(particle(rng));
      other_end.push_back(particle(rng));
      w.emplace_back(g(rng), g(rng), g(rng));
      across.push_back(std::abs(g(rng)));
    }
    side.build(n, key, other_end);
    for (std::size_t k = 0; k < side.lane_spring.size(); ++k) {
      const std::int32_t s = side.lane_spring[k];
      if (s < 0) continue;  // a pad
      BlockPair& b = side.blocks[k / 2];
      const auto& ws = w[static_cast<std::size_t>(s)];
      b.wx[k % 2] = ws.x();
      b.wy[k % 2] = ws.y();
      b.wz[k % 2] = ws.z();
      b.across[k % 2] = across[static_cast<std::size_t>(s)];
    }
  }

  Vec3 block_times(std::size_t s, const Vec3& u) const { return across[s] * u + w[s].dot(u) * w[s]; }
};

std::vector<Vec3> random_vectors(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vec3> u(n + 1, Vec3::Zero());  // u[n] = 0: the pads' dummy
  for (std::size_t i = 0; i < n; ++i) u[i] = Vec3(g(rng), g(rng), g(rng));
  return u;
}

// pull(i, u) is the sum of B_s u[o_s] over the springs keyed i.
TEST(PairedSide, PullSumsEachParticlesSprings) {
  const RandomSide r(3);
  const std::vector<Vec3> u = random_vectors(r.n, 5);
  std::vector<Vec3> expected(r.n, Vec3::Zero());
  for (std::size_t s = 0; s < r.key.size(); ++s)
    expected[static_cast<std::size_t>(r.key[s])] += r.block_times(s, u[static_cast<std::size_t>(r.other_end[s])]);
  for (std::size_t i = 0; i < r.n; ++i)
    EXPECT_LT((r.side.pull(i, u.data()) - expected[i]).norm(), 1e-12 * (1 + expected[i].norm())) << i;
}

// push(i, u_i, acc) adds B_s u_i at each other end o_s of i's springs: the
// transpose of pull; the pads add nothing but to the dummy.
TEST(PairedSide, PushAddsEachSpringsShareAtItsOtherEnd) {
  const RandomSide r(7);
  const std::vector<Vec3> u = random_vectors(r.n, 9);
  std::vector<Vec3> expected(r.n, Vec3::Zero()), acc(r.n + 1, Vec3::Zero());
  for (std::size_t s = 0; s < r.key.size(); ++s)
    expected[static_cast<std::size_t>(r.other_end[s])] += r.block_times(s, u[static_cast<std::size_t>(r.key[s])]);
  for (std::size_t i = 0; i < r.n; ++i) r.side.push(i, u[i], acc.data());
  for (std::size_t o = 0; o < r.n; ++o)
    EXPECT_LT((acc[o] - expected[o]).norm(), 1e-12 * (1 + expected[o].norm())) << o;
  EXPECT_EQ(acc[r.n], Vec3::Zero());
}

}  // namespace
}  // namespace mtcut::sim
