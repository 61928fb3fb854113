#pragma once
// Summary figures of a tet mesh, as `mtcut mesh` prints them.

#include <cstddef>

#include "engine/tet_mesh.h"

namespace mtcut::engine {

struct MeshStats {
  std::size_t vertices = 0;
  std::size_t tets = 0;
  std::size_t boundary_faces = 0;
  double volume = 0;            // sum of tet volumes
  double min_dihedral_deg = 0;  // over all tets
  double mean_radius_ratio = 0; // 1 = all regular
  double min_radius_ratio = 0;
};

MeshStats compute_stats(const TetMesh& mesh);

// Per-tet quality, for cell data in output files: (n_tets) each.
std::vector<double> tet_min_dihedral_deg(const TetMesh& mesh);
std::vector<double> tet_radius_ratio(const TetMesh& mesh);

}  // namespace mtcut::engine
