#include "app/pieces.h"

#include <algorithm>
#include <numeric>

#include "engine/tet_components.h"

namespace mtcut::app {

PieceLabels label_pieces(const engine::TetMesh& mesh) {
  const engine::TetComponents components = engine::tet_components(mesh.tets, mesh.num_vertices());
  const std::vector<std::size_t>& sizes = components.tets;
  const std::vector<std::int32_t>& component = components.tet_component;
  const std::size_t n = mesh.num_tets();
  // Components are numbered in order of their first tet, so a stable
  // sort by size keeps that order among equal sizes.
  std::vector<std::int32_t> order(sizes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return sizes[static_cast<std::size_t>(a)] > sizes[static_cast<std::size_t>(b)];
  });
  std::vector<std::int32_t> rank(sizes.size());
  PieceLabels labels;
  for (std::size_t r = 0; r < order.size(); ++r) {
    rank[static_cast<std::size_t>(order[r])] = static_cast<std::int32_t>(r);
    labels.piece_tets.push_back(sizes[static_cast<std::size_t>(order[r])]);
  }
  labels.tet_piece.resize(n);
  for (std::size_t t = 0; t < n; ++t) labels.tet_piece[t] = rank[static_cast<std::size_t>(component[t])];
  return labels;
}

PieceLabels label_frontier_pieces(const engine::Mt& mt, const engine::Frontier& frontier) {
  PieceLabels mesh_labels = label_pieces(frontier.to_tet_mesh(mt));
  // to_tet_mesh writes the frontier's tets in ascending id order.
  std::vector<engine::TetId> ids(frontier.tets().begin(), frontier.tets().end());
  std::sort(ids.begin(), ids.end());
  PieceLabels labels;
  labels.tet_piece.assign(mt.num_tets(), -1);
  for (std::size_t i = 0; i < ids.size(); ++i) labels.tet_piece[ids[i].index()] = mesh_labels.tet_piece[i];
  labels.piece_tets = std::move(mesh_labels.piece_tets);
  return labels;
}

}  // namespace mtcut::app
