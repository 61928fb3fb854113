#include "engine/tet_adjacency.h"

#include <algorithm>

#include "engine/tet_geometry.h"

namespace mtcut::engine {
namespace {

struct FaceSlot {
  std::array<std::int32_t, 3> key;  // sorted vertex ids
  std::int64_t slot;                // tet * 4 + local face
};

}  // namespace

std::array<VertId, 3> face_vertices(const Tet& tet, int f) {
  const auto& lf = kTetFaces[f];
  return {tet[lf[0]], tet[lf[1]], tet[lf[2]]};
}

TetAdjacency build_adjacency(const TetMesh& mesh) {
  const std::size_t n = mesh.num_tets();
  std::vector<FaceSlot> faces;
  faces.reserve(4 * n);
  for (std::size_t t = 0; t < n; ++t) {
    for (int f = 0; f < 4; ++f) {
      const auto v = face_vertices(mesh.tets[t], f);
      std::array<std::int32_t, 3> key = {v[0].value, v[1].value, v[2].value};
      std::sort(key.begin(), key.end());
      faces.push_back({key, static_cast<std::int64_t>(4 * t + f)});
    }
  }
  std::sort(faces.begin(), faces.end(),
            [](const FaceSlot& a, const FaceSlot& b) { return a.key < b.key || (a.key == b.key && a.slot < b.slot); });

  TetAdjacency adj;
  adj.neighbors.assign(n, {TetId(), TetId(), TetId(), TetId()});
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j - i == 1) {
      const auto t = static_cast<std::size_t>(faces[i].slot / 4);
      const int f = static_cast<int>(faces[i].slot % 4);
      adj.boundary.push_back({TetId(t), f, face_vertices(mesh.tets[t], f)});
    } else if (j - i == 2) {
      const auto ta = static_cast<std::size_t>(faces[i].slot / 4), tb = static_cast<std::size_t>(faces[i + 1].slot / 4);
      adj.neighbors[ta][faces[i].slot % 4] = TetId(tb);
      adj.neighbors[tb][faces[i + 1].slot % 4] = TetId(ta);
    } else {
      ++adj.non_manifold_faces;
    }
    i = j;
  }
  return adj;
}

}  // namespace mtcut::engine
