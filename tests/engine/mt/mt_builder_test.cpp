#include "engine/mt/mt_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "engine/tet_adjacency.h"

#include "engine/mt/frontier.h"
#include "engine/mt/mt_stats.h"
#include "tests/engine/mt/mt_test_util.h"

namespace mtcut::engine {
namespace {

using mtcut::test::test_mesh;

// Connected components of a set of tets, adjacency through shared faces.
int face_components(const Mt& mt, std::span<const TetId> tets) {
  std::map<std::array<VertId, 3>, std::vector<std::size_t>> by_face;
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (int f = 0; f < 4; ++f) {
      auto face = face_vertices(mt.tet(tets[i]), f);
      std::sort(face.begin(), face.end());
      by_face[face].push_back(i);
    }
  std::vector<std::size_t> parent(tets.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [face, holders] : by_face)
    for (std::size_t k = 1; k < holders.size(); ++k) parent[find(holders[k])] = find(holders[0]);
  int components = 0;
  for (std::size_t i = 0; i < tets.size(); ++i) components += find(i) == i;
  return components;
}

struct BuildCase {
  std::string mesh;
  bool preserve;
};

class MtBuilderOnMeshes : public ::testing::TestWithParam<BuildCase> {};

TEST_P(MtBuilderOnMeshes, BuildsAValidShallowMtThatSimplifies) {
  const TetMesh& fine = test_mesh(GetParam().mesh);
  MtBuildOptions options;
  options.preserve_boundary = GetParam().preserve;
  // Free: the surface moves by the collapses' errors alone (a bound of 1% of
  // the size stops a coarse mesh early: surface_deviation_test.cpp).
  options.max_surface_deviation = std::numeric_limits<double>::infinity();
  MtBuildReport report;
  const Mt mt = build_mt(fine, options, &report);
  const ValidationReport valid = mt.validate();
  EXPECT_TRUE(valid.ok()) << valid.summary();
  const MtStats stats = compute_mt_stats(mt);
  EXPECT_EQ(stats.vertices, fine.num_vertices());
  EXPECT_EQ(stats.finest_tets, fine.num_tets());
  EXPECT_EQ(stats.fragments, report.collapses + 2);
  EXPECT_EQ(mt.boundary_preserved(), GetParam().preserve);
  EXPECT_LT(stats.coarsest_tets, fine.num_tets());
  EXPECT_GT(report.collapses, GetParam().preserve ? fine.num_vertices() / 20 : fine.num_vertices() / 2);
  EXPECT_LE(stats.dag_depth, report.rounds + 1);
  // Shallow: many collapses per level (meaningless for a handful of collapses).
  if (report.collapses >= 100) {
    EXPECT_LT(stats.dag_depth, report.collapses / 3);
  }
  if (GetParam().preserve) {
    // The coarsest mesh covers exactly the fine domain.
    EXPECT_NEAR(Frontier::coarsest(mt).volume(mt), fine.total_volume(), 1e-9 * fine.total_volume());
  }
  RecordProperty("depth", static_cast<int>(stats.dag_depth));
  RecordProperty("fragments", static_cast<int>(stats.fragments));
}

INSTANTIATE_TEST_SUITE_P(Meshes, MtBuilderOnMeshes,
                         ::testing::Values(BuildCase{"liver", false}, BuildCase{"liver", true},
                                           BuildCase{"armadillo", false}, BuildCase{"ellipsoid", true},
                                           BuildCase{"ellipsoid", false}, BuildCase{"box", true}),
                         [](const auto& case_info) {
                           return case_info.param.mesh + (case_info.param.preserve ? "_preserved" : "_free");
                         });

TEST(MtBuilder, StopsAtTheTargetCoarsestSize) {
  MtBuildOptions options;
  options.target_coarsest_tets = 600;
  const Mt mt = build_mt(test_mesh("box"), options);
  const MtStats stats = compute_mt_stats(mt);
  EXPECT_LE(stats.coarsest_tets, 600u);
  EXPECT_GT(stats.coarsest_tets, 500u);  // stopped right after reaching it
  EXPECT_TRUE(mt.validate().ok());
}

TEST(MtBuilder, StopsAfterMaxCollapses) {
  MtBuildOptions options;
  options.max_collapses = 37;
  MtBuildReport report;
  const Mt mt = build_mt(test_mesh("box"), options, &report);
  EXPECT_EQ(report.collapses, 37u);
  EXPECT_EQ(mt.num_fragments(), 39u);
}

TEST(MtBuilder, GroupsNeighbouringCollapsesIntoOneFragment) {
  MtBuildOptions options;
  options.collapses_per_fragment = 3;
  options.preserve_boundary = false;
  MtBuildReport report;
  const Mt mt = build_mt(test_mesh("ellipsoid"), options, &report);
  const ValidationReport valid = mt.validate();
  EXPECT_TRUE(valid.ok()) << valid.summary();
  EXPECT_LT(mt.num_fragments(), report.collapses / 2);
  EXPECT_GT(mt.num_fragments(), report.collapses / 4);
  // A fragment is one connected region: its created tets are connected
  // through shared faces.
  for (std::size_t i = 0; i < mt.num_fragments(); ++i) {
    const FragId f(i);
    if (f == mt.root() || f == mt.drain()) continue;
    EXPECT_EQ(face_components(mt, mt.created(f)), 1) << "fragment " << i;
  }
}

TEST(MtBuilder, IsDeterministic) {
  const Mt a = build_mt(test_mesh("liver"), {});
  const Mt b = build_mt(test_mesh("liver"), {});
  ASSERT_EQ(a.num_tets(), b.num_tets());
  ASSERT_EQ(a.num_fragments(), b.num_fragments());
  for (std::size_t t = 0; t < a.num_tets(); ++t) {
    EXPECT_EQ(a.tet(TetId(t)), b.tet(TetId(t)));
    EXPECT_EQ(a.birth(TetId(t)), b.birth(TetId(t)));
    EXPECT_EQ(a.death(TetId(t)), b.death(TetId(t)));
  }
}

TEST(MtBuilder, DepthGrowsLikeLogN) {
  // Eight times the tets: a linear depth would grow 8x, a logarithmic one
  // by a constant (measured ~1.3x).
  MeshLoadDef small, large;
  small.builtin_tets = 600;
  large.builtin_tets = 4800;
  const Mt a = build_mt(load_mesh("builtin:box", small).mesh, {});
  const Mt b = build_mt(load_mesh("builtin:box", large).mesh, {});
  const MtStats sa = compute_mt_stats(a), sb = compute_mt_stats(b);
  EXPECT_GT(sb.fragments, 5 * sa.fragments);
  EXPECT_LT(static_cast<double>(sb.dag_depth), 2.0 * static_cast<double>(sa.dag_depth))
      << sa.dag_depth << " -> " << sb.dag_depth;
}

}  // namespace
}  // namespace mtcut::engine
