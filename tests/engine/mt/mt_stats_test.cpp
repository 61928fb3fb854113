#include "engine/mt/mt_stats.h"

#include <gtest/gtest.h>

#include <functional>

#include "engine/mt/frontier.h"
#include "tests/engine/mt/mt_test_util.h"

namespace mtcut::engine {
namespace {

using mtcut::test::test_mt;

// One fine tet, which the drain replaces: every figure known by hand.
TEST(MtStats, OneTetMtHasTheFiguresCountedByHand) {
  TetMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  mesh.tets = {Tet{VertId(0), VertId(1), VertId(2), VertId(3)}};
  Mt mt = Mt::from_fine_mesh(mesh);
  const FragId drain = mt.add_fragment();
  mt.set_drain(drain);
  mt.set_death(TetId(0), drain);
  const MtStats stats = compute_mt_stats(mt);
  EXPECT_EQ(stats.vertices, 4u);
  EXPECT_EQ(stats.fragments, 2u);
  EXPECT_EQ(stats.tets_total, 1u);
  EXPECT_EQ(stats.finest_tets, 1u);
  EXPECT_EQ(stats.coarsest_tets, 1u);
  EXPECT_EQ(stats.dag_depth, 1u);
}

// On a built MT: the finest and coarsest counts are the meshes of the
// finest and coarsest frontiers, the live tets a count over the slots,
// the depth the longest path by a recursion over children.
TEST(MtStats, CountsAndDepthMatchTheDag) {
  const Mt& mt = test_mt("box");
  const MtStats stats = compute_mt_stats(mt);
  std::size_t alive = 0;
  for (std::size_t t = 0; t < mt.num_tets(); ++t) alive += mt.alive(TetId(t));
  EXPECT_EQ(stats.tets_total, alive);
  EXPECT_EQ(stats.finest_tets, Frontier::finest(mt).tets().size());
  EXPECT_EQ(stats.coarsest_tets, Frontier::coarsest(mt).tets().size());
  EXPECT_LT(stats.coarsest_tets, stats.finest_tets);
  EXPECT_GE(stats.bytes, mt.num_tets() * (sizeof(Tet) + 2 * sizeof(FragId)));
  // Depth by memoised recursion over children.
  std::vector<int> memo(mt.num_fragments(), -1);
  std::function<int(FragId)> longest = [&](FragId f) {
    if (memo[f.index()] >= 0) return memo[f.index()];
    int best = 0;
    for (FragId c : mt.children(f)) best = std::max(best, 1 + longest(c));
    return memo[f.index()] = best;
  };
  EXPECT_EQ(stats.dag_depth, static_cast<std::size_t>(longest(mt.root())));
}

}  // namespace
}  // namespace mtcut::engine
