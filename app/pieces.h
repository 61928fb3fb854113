#pragma once
// The pieces of a tet mesh, labelled for people: its connected components
// (engine/tet_components.h: tets sharing a vertex are one piece, as the
// World counts them), numbered by size. `mtcut run` (snapshots, the piece
// report) and the viewer (piece colours) label them here; the count in
// metrics.csv and the summary is the World's (World::pieces()).

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
