#pragma once
// The pieces a cut MT falls into, and each piece as an independent MT.
//
// Why pieces are labels on one MT first. After a separating cut every
// fragment but the root and the drain lies in one piece: the cut decomposed
// every fragment it separated (fragment_decomposition.h), so no arc (tet)
// joins two pieces except through the root (which creates the finest mesh of
// all of them) and the drain (which replaces the coarsest of all of them).
// A frontier S restricted to one piece's fragments is then a frontier of
// that piece alone: coarsening or refining a fragment of piece A needs only
// fragments of A (and the root) in S, and changes only tets of A. So the
// World keeps one MT and one frontier, refines and coarsens each piece on
// its own terms, and simulates each piece as the connected component of the
// frontier's mesh that it is: the labels are all it needs. extract_piece_mt()
// makes the paper's "two independent MTs" when a piece must leave the model
// (saved, handed to another process) and is what the tests validate: the
// piece's root creates its finest tets, its drain replaces its coarsest.
//
// Connectivity is through shared vertices, as in fragment_decomposition.h: a
// cut duplicates every vertex of its surface, so the sides of a separating
// cut share none.

#include <cstdint>
#include <vector>

#include "engine/mt/mt.h"
#include "engine/validation.h"

namespace mtcut::cut {

using engine::FragId;
using engine::Mt;
using engine::TetId;

struct MtPieces {
  std::size_t count = 0;
  std::vector<std::int32_t> fragment_piece;     // (n_fragments) piece of each fragment; -1 root, drain
  std::vector<std::int32_t> tet_piece;          // (n_tets) piece of each live tet; -1 dead
  std::vector<std::vector<FragId>> fragments;   // (count) each piece's fragments, ascending (root, drain excluded)
  std::vector<std::size_t> finest_tets;         // (count) tets of the finest mesh in each piece
};

// Numbered in the order of their first finest tet (ascending tet ids).
MtPieces find_pieces(const Mt& mt);
// find_pieces(mt).count, without the labels: a pass over the live tets and
// the vertices only (what the cutter reports after a cut).
std::size_t count_pieces(const Mt& mt);

// (pieces.count) the volume of each piece's finest mesh. Apart from
// find_pieces, which the World's outputs run after cuts: the volumes were 40%
// of it, and the outputs need only the labels.
std::vector<double> piece_volumes(const Mt& mt, const MtPieces& pieces);

// Every arc (live tet) within one piece, root and drain apart, and the
// pieces apart: no vertex in two of them; each piece's fragment list and
// finest-tet count are its own.
engine::ValidationReport validate_pieces(const Mt& mt, const MtPieces& pieces);

// Piece `piece` as its own MT: its vertices renumbered (vertex_ids, optional,
// receives the MT vertex each new vertex is), its fragments in ascending
// order, then its drain.
Mt extract_piece_mt(const Mt& mt, const MtPieces& pieces, std::size_t piece,
                    std::vector<engine::VertId>* vertex_ids = nullptr);

}  // namespace mtcut::cut
