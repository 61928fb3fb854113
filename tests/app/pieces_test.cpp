// The pieces of a tet mesh and of an MT frontier: vertex-connected
// components (engine/tet_components.h), numbered by size.

#include "app/pieces.h"

#include <gtest/gtest.h>

#include "tests/app/view/tiny_mt.h"

namespace mtcut::app {
namespace {

using engine::Tet;
using engine::Vec3;
using engine::VertId;

Tet tet(int a, int b, int c, int d) { return {VertId(a), VertId(b), VertId(c), VertId(d)}; }

// Points of a small grid: enough positions for the ids the tests use.
engine::TetMesh mesh_of(std::vector<Tet> tets) {
  engine::TetMesh mesh;
  for (int i = 0; i < 16; ++i) mesh.positions.push_back(Vec3(i % 3, (i / 3) % 2, i / 6));
  mesh.tets = std::move(tets);
  return mesh;
}

TEST(Pieces, TetsSharingAFaceAreOnePiece) {
  const PieceLabels labels = label_pieces(mesh_of({tet(0, 1, 2, 3), tet(1, 2, 3, 4)}));
  EXPECT_EQ(labels.count(), 1);
  EXPECT_EQ(labels.tet_piece, (std::vector<std::int32_t>{0, 0}));
}

TEST(Pieces, AnEdgeOrAVertexHoldsTwoTetsTogetherAsTheSpringsDo) {
  // One particle per vertex: tets sharing only an edge or a vertex move as
  // one body, and the World counts them as one piece.
  EXPECT_EQ(label_pieces(mesh_of({tet(0, 1, 2, 3), tet(0, 1, 4, 5)})).count(), 1);  // an edge
  EXPECT_EQ(label_pieces(mesh_of({tet(0, 1, 2, 3), tet(0, 4, 5, 6)})).count(), 1);  // a vertex
  EXPECT_EQ(label_pieces(mesh_of({tet(0, 1, 2, 3), tet(4, 5, 6, 7)})).count(), 2);  // nothing
}

TEST(Pieces, TheLargestPieceIsPieceZeroThenBySizeThenByFirstTet) {
  // tet 0 alone; tets 1, 2, 3 a chain through faces; tet 4 alone.
  const PieceLabels labels = label_pieces(
      mesh_of({tet(0, 1, 2, 3), tet(4, 5, 6, 7), tet(5, 6, 7, 8), tet(6, 7, 8, 9), tet(10, 11, 12, 13)}));
  ASSERT_EQ(labels.count(), 3);
  EXPECT_EQ(labels.tet_piece, (std::vector<std::int32_t>{1, 0, 0, 0, 2}));
  EXPECT_EQ(labels.piece_tets, (std::vector<std::size_t>{3, 1, 1}));
}

TEST(Pieces, AnEmptyMeshHasNoPiece) { EXPECT_EQ(label_pieces(engine::TetMesh{}).count(), 0); }

TEST(Pieces, AFrontierIsLabelledByMtTetId) {
  const test::TinyWorld w = test::make_tiny_world(test::three_piece_mesh());
  const PieceLabels pieces = label_frontier_pieces(w.mt, w.frontier);
  ASSERT_EQ(pieces.count(), 3);
  EXPECT_EQ(pieces.piece_tets, (std::vector<std::size_t>{2, 1, 1}));
  ASSERT_EQ(pieces.tet_piece.size(), w.mt.num_tets());
  EXPECT_EQ(pieces.tet_piece[0], 0);  // A and B: the largest piece is 0
  EXPECT_EQ(pieces.tet_piece[1], 0);
  EXPECT_EQ(pieces.tet_piece[2], 1);  // C before E: equal sizes, smaller tet id first
  EXPECT_EQ(pieces.tet_piece[3], 2);
}

TEST(Pieces, OneFrontierTetIsOnePiece) {
  engine::TetMesh mesh = test::three_piece_mesh();
  mesh.tets.resize(1);
  const test::TinyWorld w = test::make_tiny_world(mesh);
  const PieceLabels pieces = label_frontier_pieces(w.mt, w.frontier);
  EXPECT_EQ(pieces.count(), 1);
  EXPECT_EQ(pieces.tet_piece[0], 0);
}

}  // namespace
}  // namespace mtcut::app
