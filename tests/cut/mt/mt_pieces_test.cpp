// The pieces of an MT (cut/mt/mt_pieces.h) on MTs small enough to know their
// pieces by hand: finest tets joined through shared vertices, fragments
// joining what their arcs join, and vertices or fragments that hold no tet
// counting as nothing.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "cut/mt/mt_pieces.h"
#include "engine/mt/mt.h"

namespace mtcut::test {
namespace {

using engine::FragId;
using engine::Mt;
using engine::Tet;
using engine::TetId;
using engine::TetMesh;
using engine::Vec3;
using engine::VertId;

// A positively oriented unit corner tet at `origin`, its vertices appended.
Tet corner_tet(TetMesh& mesh, const Vec3& origin) {
  const auto first = static_cast<std::int32_t>(mesh.positions.size());
  for (const Vec3& d : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}) mesh.positions.push_back(origin + d);
  return {VertId(first), VertId(first + 1), VertId(first + 2), VertId(first + 3)};
}

// Closes the MT the way the builder does: a drain replacing every live tet
// no fragment replaces yet.
void add_drain(Mt& mt) {
  const FragId drain = mt.add_fragment();
  mt.set_drain(drain);
  for (std::size_t i = 0; i < mt.num_tets(); ++i)
    if (mt.alive(TetId(i)) && !mt.death(TetId(i)).valid()) mt.set_death(TetId(i), drain);
}

void expect_pieces(const Mt& mt, std::size_t count, const std::vector<std::size_t>& finest_tets) {
  const cut::MtPieces pieces = cut::find_pieces(mt);
  const auto report = cut::validate_pieces(mt, pieces);
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_EQ(pieces.count, count);
  EXPECT_EQ(pieces.finest_tets, finest_tets);
  EXPECT_EQ(cut::count_pieces(mt), count);
}

TEST(MtPieces, FinestTetsApartArePiecesAndASharedVertexJoinsThem) {
  TetMesh apart;
  apart.tets = {corner_tet(apart, Vec3(0, 0, 0)), corner_tet(apart, Vec3(3, 0, 0)), corner_tet(apart, Vec3(6, 0, 0))};
  Mt mt = Mt::from_fine_mesh(apart);
  add_drain(mt);
  expect_pieces(mt, 3, {1, 1, 1});

  // The third tet moved onto a corner of the first: two pieces, numbered by
  // their first finest tet.
  TetMesh touching = apart;
  touching.tets[2][0] = touching.tets[0][1];
  Mt joined = Mt::from_fine_mesh(touching);
  add_drain(joined);
  expect_pieces(joined, 2, {2, 1});
  const cut::MtPieces pieces = cut::find_pieces(joined);
  EXPECT_EQ(pieces.tet_piece, (std::vector<std::int32_t>{0, 1, 0}));
}

TEST(MtPieces, AVertexNoTetUsesIsNoPiece) {
  TetMesh mesh;
  mesh.tets = {corner_tet(mesh, Vec3(0, 0, 0))};
  mesh.positions.push_back(Vec3(5, 5, 5));  // used by no tet, as a retraction leaves the vertices it made
  Mt mt = Mt::from_fine_mesh(mesh);
  add_drain(mt);
  expect_pieces(mt, 1, {1});
}

TEST(MtPieces, AFragmentJoinsTheFinestTetsItReplaces) {
  // Two finest tets apart, both replaced by one fragment that creates them
  // again: no vertex joins them, the fragment's arcs do (a coarse
  // tessellation a cut has not separated).
  TetMesh mesh;
  mesh.tets = {corner_tet(mesh, Vec3(0, 0, 0)), corner_tet(mesh, Vec3(3, 0, 0))};
  Mt mt = Mt::from_fine_mesh(mesh);
  const FragId coarse = mt.add_fragment();
  for (TetId t : {TetId(0), TetId(1)}) mt.set_death(t, coarse);
  for (TetId t : {TetId(0), TetId(1)}) mt.add_copy(mt, t, mesh.tets[t.index()], coarse, FragId());
  add_drain(mt);
  expect_pieces(mt, 1, {2});
  const cut::MtPieces pieces = cut::find_pieces(mt);
  EXPECT_EQ(pieces.fragment_piece[coarse.index()], 0);
  EXPECT_EQ(pieces.tet_piece, (std::vector<std::int32_t>{0, 0, 0, 0}));

  // The fragment decomposed into one per finest tet (what a separating cut
  // does to it): two pieces, one fragment each.
  const FragId second = mt.add_fragment();
  mt.set_death(TetId(1), second);
  mt.set_birth(TetId(3), second);
  expect_pieces(mt, 2, {1, 1});
  const cut::MtPieces apart = cut::find_pieces(mt);
  EXPECT_EQ(apart.fragment_piece[coarse.index()], 0);
  EXPECT_EQ(apart.fragment_piece[second.index()], 1);
}

TEST(MtPieces, AFragmentJoinsThroughEveryLevel) {
  // Finest tets apart, each replaced by a fragment of its own, whose tets
  // one coarser fragment replaces: the chain of arcs joins them.
  TetMesh mesh;
  mesh.tets = {corner_tet(mesh, Vec3(0, 0, 0)), corner_tet(mesh, Vec3(3, 0, 0))};
  Mt mt = Mt::from_fine_mesh(mesh);
  const FragId a = mt.add_fragment(), b = mt.add_fragment(), top = mt.add_fragment();
  mt.set_death(TetId(0), a);
  mt.set_death(TetId(1), b);
  mt.add_copy(mt, TetId(0), mesh.tets[0], a, top);
  mt.add_copy(mt, TetId(1), mesh.tets[1], b, top);
  for (TetId t : {TetId(2), TetId(3)}) {
    const Tet tet = mt.tet(t);
    mt.add_copy(mt, t, tet, top, FragId());
  }
  add_drain(mt);
  expect_pieces(mt, 1, {2});
}

}  // namespace
}  // namespace mtcut::test
