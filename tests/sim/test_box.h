#pragma once
// The small spring model the solver tests share: a 0.1 x 0.05 x 0.05 box of
// about 400 tets, stiff and damped, with its x = +0.05 face fixed.

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

}  // namespace mtcut::sim::test
