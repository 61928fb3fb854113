#include "engine/mt/mt_stats.h"

#include <gtest/gtest.h>

#include <functional>

#include "tests/engine/mt/mt_test_util.h"

namespace mtcut::engine {
namespace {

using test::test_mt;

TEST(MtStats, CountsAndDepthMatchTheDag) {
  const Mt& mt = test_mt("box");
  const MtStats stats = compute_mt_stats(mt);
  EXPECT_EQ(stats.vertices, mt.num_vertices());
  EXPECT_EQ(stats.fragments, mt.num_fragments());
  EXPECT_EQ(stats.tets_total, mt.num_live_tets());
  EXPECT_EQ(stats.finest_tets, mt.created(mt.root()).size());
  EXPECT_EQ(stats.coarsest_tets, mt.replaced(mt.drain()).size());
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
