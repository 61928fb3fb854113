#pragma once
// A random axis-aligned box for the distance tests: its low corner in
// [-1, 1]^3, each side in [0, size].

#include <random>

#include "engine/mt/bvh.h"

namespace mtcut::test {

inline engine::Aabb random_box(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), s(0.0, size);
  const engine::Vec3 lo(u(rng), u(rng), u(rng));
  engine::Aabb box;
  box.extend(lo);
  box.extend(engine::Vec3(lo + engine::Vec3(s(rng), s(rng), s(rng))));
  return box;
}

}  // namespace mtcut::test
