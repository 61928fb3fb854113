#pragma once
// The small spring model the solver tests share: a 0.1 x 0.05 x 0.05 box of
// about 400 tets, stiff and damped, with its x = +0.05 face fixed; a
// shuffle of its springs (an order not grouped by first particle); and a
// jittered, moving state with its implicit system; the frame step and the
// built-in box the solver tests build their own models on.

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "engine/mesh_loader.h"
#include "sim/environment.h"
#include "sim/fixed_region.h"
#include "sim/forces.h"
#include "sim/spring_model.h"
#include "sim/spring_system.h"

namespace mtcut::sim::test {

// One frame at 60 Hz, the step the solver tests take.
inline constexpr double kDt = 1.0 / 60.0;

// The built-in box of about `tets` tets and the given size.
inline engine::TetMesh box_mesh(int tets, const Vec3& size) {
  engine::MeshLoadDef def;
  def.builtin_tets = tets;
  def.builtin_size = size;
  return engine::load_mesh("builtin:box", def).mesh;
}

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

// The rest state of `model` with every free particle moved by up to 3 mm
// and given up to 0.2 m/s per axis, drawn from `rng`.
inline SpringState jittered_moving_state(const SpringModel& model, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.003, 0.003), speed(-0.2, 0.2);
  SpringState state = rest_state(model);
  for (std::size_t i = 0; i < model.num_particles(); ++i) {
    if (model.inv_mass[i] == 0) continue;
    state.x[i] += Vec3(jitter(rng), jitter(rng), jitter(rng));
    state.v[i] = Vec3(speed(rng), speed(rng), speed(rng));
  }
  return state;
}

// A model at a jittered, moving state (jittered_moving_state) and its
// implicit system A dv = b over one step of `dt`, with no force but the
// body forces (gravity off).
struct JitteredSystem {
  SpringModel model;
  SpringState state;
  SpringSystem system;
  std::vector<Vec3> b;
};

inline JitteredSystem jittered_system(SpringModel model, std::mt19937& rng, double dt) {
  JitteredSystem c;
  c.model = std::move(model);
  c.state = jittered_moving_state(c.model, rng);
  std::vector<Vec3> f;
  compute_body_forces(c.model, Environment{}, c.state, f);
  c.b.resize(c.model.num_particles());
  c.system.assemble(c.model, c.state, f, dt, c.b);
  return c;
}

}  // namespace mtcut::sim::test
