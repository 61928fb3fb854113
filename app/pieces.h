#pragma once
// The pieces of a tet mesh: its connected components when two tets are
// connected through a shared face (an edge or a vertex does not hold two
// pieces together). A cut separates pieces by giving each side its own
// copies of the cut's vertices, so no face is shared across it. `mtcut run`
// (metrics, snapshots) and the viewer (piece colours) both count them here.

#include <cstdint>
#include <vector>

#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "engine/tet_mesh.h"

namespace mtcut::app {

struct PieceLabels {
  // Piece of each tet (label_pieces: (n_tets); label_frontier_pieces:
  // (n_mt_tets), -1 for tets outside the frontier). Piece 0 has the most
  // tets, then by decreasing size, ties by the smallest tet index: stable
  // across frames.
  std::vector<std::int32_t> tet_piece;
  std::vector<std::size_t> piece_tets;  // (n_pieces) tets in each piece
  int count() const { return static_cast<int>(piece_tets.size()); }
};

PieceLabels label_pieces(const engine::TetMesh& mesh);

// The pieces of the frontier's mesh, labelled by MT tet id.
PieceLabels label_frontier_pieces(const engine::Mt& mt, const engine::Frontier& frontier);

}  // namespace mtcut::app
