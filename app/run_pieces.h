#pragma once
// The pieces of a tet mesh: its connected components when two tets are
// connected through a shared face (an edge or a vertex does not hold two
// pieces together). A cut separates pieces by giving each side its own
// copies of the cut's vertices, so no face is shared across it.

#include <cstdint>
#include <vector>

#include "engine/tet_mesh.h"

namespace mtcut::app {

struct PieceLabels {
  // (n_tets) piece of each tet. Piece 0 has the most tets, then by
  // decreasing size, ties by the smallest tet index: stable across frames.
  std::vector<std::int32_t> tet_piece;
  std::vector<std::size_t> piece_tets;  // (n_pieces) tets in each piece
  int count() const { return static_cast<int>(piece_tets.size()); }
};

PieceLabels label_pieces(const engine::TetMesh& mesh);

}  // namespace mtcut::app
