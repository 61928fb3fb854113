#pragma once
// Meshes and MTs shared by the MT tests, built once per test binary run,
// and small helpers.

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "engine/mesh_loader.h"
#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "engine/mt/mt_builder.h"
#include "tests/test_paths.h"

namespace mtcut::test {

// "liver" (liver.msh, 596 tets), "armadillo" (Armadillo_Tetra_4406.vtu),
// "ellipsoid" and "box" (builtin, ~1.5k tets; the box has flat faces and
// straight creases that a preserved boundary may still simplify),
// "ellipsoid-3k".
inline const engine::TetMesh& test_mesh(const std::string& name) {
  static std::map<std::string, engine::TetMesh> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  engine::MeshLoadDef def;
  def.builtin_tets = 1500;
  std::string spec = name;
  if (name == "liver") spec = shared_mesh("liver.msh");
  if (name == "armadillo") spec = shared_mesh("Armadillo_Tetra_4406.vtu");
  if (name == "ellipsoid") spec = "builtin:ellipsoid";
  if (name == "box") spec = "builtin:box";
  if (name == "ellipsoid-3k") spec = "builtin:ellipsoid", def.builtin_tets = 3000;
  return cache.emplace(name, engine::load_mesh(spec, def).mesh).first->second;
}

// The MT of test_mesh(mesh), boundary preserved or not.
inline const engine::Mt& test_mt(const std::string& mesh, bool preserve_boundary = true) {
  static std::map<std::pair<std::string, bool>, engine::Mt> cache;
  const auto key = std::make_pair(mesh, preserve_boundary);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  engine::MtBuildOptions options;
  options.preserve_boundary = preserve_boundary;
  return cache.emplace(key, engine::build_mt(test_mesh(mesh), options)).first->second;
}

// A frontier's tets, sorted: two frontiers are the same mesh iff equal.
inline std::vector<engine::TetId> sorted_tets(const engine::Frontier& frontier) {
  std::vector<engine::TetId> tets(frontier.tets().begin(), frontier.tets().end());
  std::sort(tets.begin(), tets.end());
  return tets;
}

}  // namespace mtcut::test
