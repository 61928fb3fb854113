#pragma once
// Face adjacency of a TetMesh: for each tet, the tet across each of its four
// faces (face i opposite vertex i, kTetFaces), and the boundary faces oriented
// outwards. Derived data: rebuild it after editing the mesh.

#include <array>
#include <vector>

#include "engine/tet_mesh.h"

namespace mtcut::engine {

struct BoundaryFace {
  TetId tet;                     // the tet the face belongs to
  int local_face;                // 0..3, opposite that local vertex
  std::array<VertId, 3> verts;   // outward oriented
};

struct TetAdjacency {
  std::vector<std::array<TetId, 4>> neighbors;  // (n_tets x 4) tet across face i, none on boundary
  std::vector<BoundaryFace> boundary;           // (n_boundary_faces)
  std::size_t non_manifold_faces = 0;           // faces on more than two tets
};

// Throws std::invalid_argument for a negative vertex id (other ids need not
// have positions: only the ids are read).
TetAdjacency build_adjacency(const TetMesh& mesh);

// The vertex ids of face f of tet t, outward oriented.
std::array<VertId, 3> face_vertices(const Tet& tet, int f);

}  // namespace mtcut::engine
