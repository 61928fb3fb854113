#include "app/view/frontier_pieces.h"

#include <gtest/gtest.h>

#include "tests/app/view/tiny_mt.h"

namespace mtcut::app::view {
namespace {

TEST(FrontierPieces, FacesJoinTetsButAVertexDoesNot) {
  const test::TinyWorld w = test::make_tiny_world(test::three_piece_mesh());
  const FrontierPieces pieces = find_frontier_pieces(w.mt, w.frontier);
  ASSERT_EQ(pieces.count(), 3);
  EXPECT_EQ(pieces.piece_tets, (std::vector<std::size_t>{2, 1, 1}));
  ASSERT_EQ(pieces.tet_piece.size(), w.mt.num_tets());
  EXPECT_EQ(pieces.tet_piece[0], 0);  // A and B: the largest piece is 0
  EXPECT_EQ(pieces.tet_piece[1], 0);
  EXPECT_EQ(pieces.tet_piece[2], 1);  // C before E: equal sizes, smaller tet id first
  EXPECT_EQ(pieces.tet_piece[3], 2);
}

TEST(FrontierPieces, OneTetIsOnePiece) {
  engine::TetMesh mesh = test::three_piece_mesh();
  mesh.tets.resize(1);
  const test::TinyWorld w = test::make_tiny_world(mesh);
  const FrontierPieces pieces = find_frontier_pieces(w.mt, w.frontier);
  EXPECT_EQ(pieces.count(), 1);
  EXPECT_EQ(pieces.tet_piece[0], 0);
}

}  // namespace
}  // namespace mtcut::app::view
