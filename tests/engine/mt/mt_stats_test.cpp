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

TEST(MtStats, PaperPresetHasThePapersSize) {
  const auto preset = find_mt_preset("paper");
  ASSERT_TRUE(preset.has_value());
  EXPECT_FALSE(find_mt_preset("nonsense").has_value());
  const Mt mt = build_mt(load_mesh(preset->mesh_spec, preset->mesh).mesh, preset->build);
  const MtStats stats = compute_mt_stats(mt);
  // The paper: 2,896 vertices, 37,062 tets, 1,542 fragments.
  EXPECT_NEAR(static_cast<double>(stats.vertices), 2896.0, 0.10 * 2896.0);
  EXPECT_NEAR(static_cast<double>(stats.tets_total), 37062.0, 0.10 * 37062.0);
  EXPECT_NEAR(static_cast<double>(stats.fragments), 1542.0, 0.10 * 1542.0);
  EXPECT_FALSE(mt.boundary_preserved());
  // (Its validity: MtBuilder.GroupsNeighbouringCollapsesIntoOneFragment
  // checks the same options on a smaller mesh.)
}

}  // namespace
}  // namespace mtcut::engine
