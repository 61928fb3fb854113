#include "engine/tet_components.h"

#include <gtest/gtest.h>

#include <random>

#include "engine/union_find.h"

namespace mtcut::engine {
namespace {

Tet tet(int a, int b, int c, int d) { return {VertId(a), VertId(b), VertId(c), VertId(d)}; }

TEST(TetComponents, TetsSharingAFaceAnEdgeOrAVertexAreOneComponent) {
  EXPECT_EQ(tet_components(std::vector<Tet>{tet(0, 1, 2, 3), tet(1, 2, 3, 4)}, 5).count(), 1u);  // a face
  EXPECT_EQ(tet_components(std::vector<Tet>{tet(0, 1, 2, 3), tet(0, 1, 4, 5)}, 6).count(), 1u);  // an edge
  EXPECT_EQ(tet_components(std::vector<Tet>{tet(0, 1, 2, 3), tet(0, 4, 5, 6)}, 7).count(), 1u);  // a vertex
  EXPECT_EQ(tet_components(std::vector<Tet>{tet(0, 1, 2, 3), tet(4, 5, 6, 7)}, 8).count(), 2u);  // nothing
  EXPECT_EQ(tet_components(std::vector<Tet>{}, 0).count(), 0u);
}

TEST(TetComponents, NumberedByTheirFirstTetWithTheirSizes) {
  // 0 and 3 meet through 3's vertex 0 after 1 and 2 started components of
  // their own; 4 joins 2 through vertex 9.
  const std::vector<Tet> tets = {tet(0, 1, 2, 3), tet(4, 5, 6, 7), tet(8, 9, 10, 11), tet(12, 13, 14, 0),
                                 tet(9, 15, 16, 17)};
  const TetComponents c = tet_components(tets, 18);
  EXPECT_EQ(c.tet_component, (std::vector<std::int32_t>{0, 1, 2, 0, 2}));
  EXPECT_EQ(c.tets, (std::vector<std::size_t>{2, 1, 2}));
}

// Against a search over the tets sharing a vertex, on random sparse meshes.
TEST(TetComponents, AgreeWithASearchOnRandomMeshes) {
  std::mt19937 rng(5);
  for (int round = 0; round < 50; ++round) {
    const int vertices = 40 + static_cast<int>(rng() % 60);
    std::vector<Tet> tets;
    for (int i = 0; i < 20; ++i) {
      Tet t;
      for (VertId& v : t) v = VertId(static_cast<std::int32_t>(rng() % static_cast<unsigned>(vertices)));
      tets.push_back(t);
    }
    const TetComponents c = tet_components(tets, static_cast<std::size_t>(vertices));
    std::vector<int> label(tets.size(), -1);
    int count = 0;
    for (std::size_t seed = 0; seed < tets.size(); ++seed) {
      if (label[seed] >= 0) continue;
      std::vector<std::size_t> stack{seed};
      label[seed] = count;
      while (!stack.empty()) {
        const std::size_t t = stack.back();
        stack.pop_back();
        for (std::size_t u = 0; u < tets.size(); ++u) {
          if (label[u] >= 0) continue;
          bool shared = false;
          for (VertId a : tets[t])
            for (VertId b : tets[u]) shared = shared || a == b;
          if (shared) label[u] = count, stack.push_back(u);
        }
      }
      ++count;
    }
    ASSERT_EQ(c.count(), static_cast<std::size_t>(count)) << "round " << round;
    for (std::size_t t = 0; t < tets.size(); ++t) EXPECT_EQ(c.tet_component[t], label[t]) << "round " << round;
  }
}

TEST(UnionFind, ASetIsRepresentedByItsSmallestMember) {
  UnionFind sets(6);
  EXPECT_TRUE(sets.unite(4, 2));
  EXPECT_TRUE(sets.unite(5, 4));
  EXPECT_FALSE(sets.unite(2, 5));
  EXPECT_EQ(sets.find(5), 2);
  EXPECT_TRUE(sets.is_root(2));
  EXPECT_FALSE(sets.is_root(4));
  EXPECT_TRUE(sets.unite(1, 5));
  EXPECT_EQ(sets.find(4), 1);
  EXPECT_EQ(sets.find(0), 0);
  EXPECT_EQ(sets.size(), 6u);
}

}  // namespace
}  // namespace mtcut::engine
