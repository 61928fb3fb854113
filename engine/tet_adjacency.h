#pragma once
// Face adjacency of a TetMesh: for each tet, the tet across each of its four
// faces (face i opposite vertex i, kTetFaces), and the boundary faces oriented
// outwards. Derived data: rebuild it after editing the mesh.

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "engine/tet_geometry.h"
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

// The vertex ids of face f of tet t, outward oriented (inline: the guard's
// face chains and every validation call it per face).
inline std::array<VertId, 3> face_vertices(const Tet& tet, int f) {
  const auto& lf = kTetFaces[f];
  return {tet[lf[0]], tet[lf[1]], tet[lf[2]]};
}

// A face's ids ascending, as unsigned words (ids are not negative): the key
// under which the copies of a face meet (branch-free: the middle one is what
// the smallest and the largest leave of the sum).
inline std::array<std::uint32_t, 3> sorted_face_ids(const std::array<VertId, 3>& v) {
  const auto a = static_cast<std::uint32_t>(v[0].value), b = static_cast<std::uint32_t>(v[1].value),
             c = static_cast<std::uint32_t>(v[2].value);
  const std::uint32_t lo = std::min({a, b, c}), hi = std::max({a, b, c});
  return {lo, a + b + c - lo - hi, hi};
}

}  // namespace mtcut::engine
