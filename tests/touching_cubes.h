#pragma once
// Tet meshes whose parts touch only along an edge or at a vertex: two cubes
// of 6 Kuhn tets each, the second moved by a whole cube along x and y (an
// edge shared) or x, y and z (a vertex shared), their shared points merged.

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "engine/predicates.h"
#include "engine/io/mesh_file.h"

namespace mtcut::test {

// Two cubes of side `side` (metres), the second at (side, side, z_step * side).
inline engine::RawMesh touching_cubes(double side, int z_step) {
  engine::RawMesh raw;
  std::map<std::array<int, 3>, std::int64_t> id_of;
  const std::array<std::array<int, 4>, 6> kuhn = {
      {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}}};
  for (const std::array<int, 3> origin : {std::array<int, 3>{0, 0, 0}, std::array<int, 3>{1, 1, z_step}}) {
    for (const auto& tet : kuhn) {
      std::array<std::int64_t, 4> ids{};
      for (int k = 0; k < 4; ++k) {
        const int corner = tet[k];
        const std::array<int, 3> at = {origin[0] + (corner & 1), origin[1] + ((corner >> 1) & 1),
                                       origin[2] + ((corner >> 2) & 1)};
        auto [it, inserted] = id_of.emplace(at, static_cast<std::int64_t>(raw.positions.size()));
        if (inserted) raw.positions.emplace_back(side * at[0], side * at[1], side * at[2]);
        ids[k] = it->second;
      }
      raw.tets.push_back(ids);
    }
  }
  return raw;
}

// The mesh as TetGen .node/.ele text, for files a command reads.
inline std::array<std::string, 2> tetgen_text(const engine::RawMesh& raw) {
  std::string node = std::to_string(raw.positions.size()) + " 3 0 0\n", ele = std::to_string(raw.tets.size()) + " 4 0\n";
  for (std::size_t i = 0; i < raw.positions.size(); ++i)
    node += std::to_string(i) + " " + std::to_string(raw.positions[i].x()) + " " + std::to_string(raw.positions[i].y()) +
            " " + std::to_string(raw.positions[i].z()) + "\n";
  for (std::size_t t = 0; t < raw.tets.size(); ++t)
    ele += std::to_string(t) + " " + std::to_string(raw.tets[t][0]) + " " + std::to_string(raw.tets[t][1]) + " " +
           std::to_string(raw.tets[t][2]) + " " + std::to_string(raw.tets[t][3]) + "\n";
  return {node, ele};
}

}  // namespace mtcut::test
