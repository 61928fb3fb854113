#include "engine/mesh_stats.h"

#include <algorithm>
#include <numeric>

#include "engine/tet_adjacency.h"
#include "engine/tet_geometry.h"

namespace mtcut::engine {

std::vector<double> tet_min_dihedral_deg(const TetMesh& mesh) {
  std::vector<double> out(mesh.num_tets());
  for (std::size_t t = 0; t < out.size(); ++t) {
    const auto c = mesh.corners(TetId(t));
    out[t] = min_dihedral_deg(c[0], c[1], c[2], c[3]);
  }
  return out;
}

std::vector<double> tet_radius_ratio(const TetMesh& mesh) {
  std::vector<double> out(mesh.num_tets());
  for (std::size_t t = 0; t < out.size(); ++t) {
    const auto c = mesh.corners(TetId(t));
    out[t] = radius_ratio(c[0], c[1], c[2], c[3]);
  }
  return out;
}

MeshStats compute_stats(const TetMesh& mesh) {
  MeshStats s;
  s.vertices = mesh.num_vertices();
  s.tets = mesh.num_tets();
  s.boundary_faces = build_adjacency(mesh).boundary.size();
  s.volume = mesh.total_volume();
  if (s.tets == 0) return s;
  const auto dihedral = tet_min_dihedral_deg(mesh);
  const auto ratio = tet_radius_ratio(mesh);
  s.min_dihedral_deg = *std::min_element(dihedral.begin(), dihedral.end());
  s.min_radius_ratio = *std::min_element(ratio.begin(), ratio.end());
  s.mean_radius_ratio = std::accumulate(ratio.begin(), ratio.end(), 0.0) / static_cast<double>(s.tets);
  return s;
}

}  // namespace mtcut::engine
