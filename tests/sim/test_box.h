#pragma once
// The small spring model the solver tests share: a 0.1 x 0.05 x 0.05 box of
// about 400 tets, stiff and damped, with its x = +0.05 face fixed; and a
// shuffle of its springs (an order not grouped by first particle).

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "engine/mesh_loader.h"
#include "sim/fixed_region.h"
#include "sim/spring_model.h"

namespace mtcut::sim::test {

inline SpringModel fixed_test_box(double volume_stiffness = 0) {
  engine::MeshLoadDef def;
  def.builtin_tets = 400;
  def.builtin_size = Vec3(0.1, 0.05, 0.05);
  const engine::TetMesh mesh = engine::load_mesh("builtin:box", def).mesh;
  MaterialDef material;
  material.youngs_modulus = 1e5;
  material.density = 1000;
  material.stiffness_damping = 0.002;
  material.mass_damping = 2.0;
  material.volume_stiffness = volume_stiffness;
  FixedRegion fixed;
  fixed.kind = FixedRegion::Kind::kHalfSpace;
  fixed.normal = Vec3(-1, 0, 0);
  fixed.offset = -(0.05 - 1e-9);
  return build_spring_model(mesh.tets, mesh.positions, material,
                            [&](engine::VertId v) { return fixed.contains(v, mesh.position(v)); });
}

// Reorders the springs by a random permutation drawn from `seed`.
inline void shuffle_springs(SpringModel& model, unsigned seed) {
  std::vector<std::size_t> order(model.num_springs());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  const SpringModel m = model;
  for (std::size_t k = 0; k < order.size(); ++k) {
    model.spring_a[k] = m.spring_a[order[k]];
    model.spring_b[k] = m.spring_b[order[k]];
    model.rest_length[k] = m.rest_length[order[k]];
    model.stiffness[k] = m.stiffness[order[k]];
    model.damping[k] = m.damping[order[k]];
  }
}

}  // namespace mtcut::sim::test
