#pragma once
// The pieces of a frontier's mesh: its connected components when two tets
// are connected through a shared face (sharing an edge or a vertex does not
// hold two pieces together). A cut separates pieces by giving each side its
// own copies of the cut's vertices, so the faces across it are not shared.

#include <cstdint>
#include <vector>

#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"

namespace mtcut::app::view {

struct FrontierPieces {
  // (n_mt_tets) piece of each tet of the frontier, -1 for tets outside it.
  // Piece 0 is the largest (most tets), then by decreasing size, ties by
  // smallest tet id, so numbering is stable across frames.
  std::vector<std::int32_t> tet_piece;
  std::vector<std::size_t> piece_tets;  // (n_pieces) tets in each piece
  int count() const { return static_cast<int>(piece_tets.size()); }
};

FrontierPieces find_frontier_pieces(const engine::Mt& mt, const engine::Frontier& frontier);

}  // namespace mtcut::app::view
