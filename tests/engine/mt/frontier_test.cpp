#include "engine/mt/frontier.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "engine/tet_geometry.h"
#include "tests/engine/mt/mt_test_util.h"

namespace mtcut::engine {
namespace {

using mtcut::test::sorted_tets;
using mtcut::test::test_mesh;
using mtcut::test::test_mt;

struct FrontierCase {
  std::string mesh;
  bool preserve;
};

class FrontierOnMeshes : public ::testing::TestWithParam<FrontierCase> {
 protected:
  const Mt& mt() const { return test_mt(GetParam().mesh, GetParam().preserve); }
  const TetMesh& fine() const { return test_mesh(GetParam().mesh); }
};

TEST_P(FrontierOnMeshes, FinestIsTheFineMesh) {
  const Frontier frontier = Frontier::finest(mt());
  const ValidationReport report = validate_frontier(mt(), frontier);
  EXPECT_TRUE(report.ok()) << report.summary();
  // The root's tets are the fine mesh's, in order and with the same vertices.
  ASSERT_EQ(frontier.tets().size(), fine().num_tets());
  const auto tets = sorted_tets(frontier);
  for (std::size_t t = 0; t < tets.size(); ++t) EXPECT_EQ(mt().tet(tets[t]), fine().tets[t]);
  EXPECT_EQ(frontier.vertices().size(), fine().num_vertices());
  EXPECT_EQ(frontier.visible_fragments().size(), 1u);
  EXPECT_NEAR(frontier.volume(mt()), fine().total_volume(), 1e-12 * fine().total_volume());
}

TEST_P(FrontierOnMeshes, CoarsestIsWhatTheDrainReplaces) {
  const Frontier frontier = Frontier::coarsest(mt());
  const ValidationReport report = validate_frontier(mt(), frontier);
  EXPECT_TRUE(report.ok()) << report.summary();
  std::vector<TetId> drained(mt().replaced(mt().drain()).begin(), mt().replaced(mt().drain()).end());
  std::sort(drained.begin(), drained.end());
  EXPECT_EQ(sorted_tets(frontier), drained);
  EXPECT_TRUE(frontier.refinable(mt()).size() > 0);
  EXPECT_TRUE(frontier.coarsenable(mt()).empty());
}

TEST_P(FrontierOnMeshes, RandomRefineAndCoarsenStepsKeepAValidFrontier) {
  std::mt19937 rng(11);
  Frontier frontier = Frontier::finest(mt());
  for (int step = 0; step < 60; ++step) {
    const auto up = frontier.coarsenable(mt());
    const auto down = frontier.refinable(mt());
    ASSERT_FALSE(up.empty() && down.empty());
    // Mostly coarsen first, then mostly refine, so both ends are visited.
    const bool coarsen = !up.empty() && (down.empty() || (rng() % 10) < (step < 30 ? 8u : 2u));
    if (coarsen) {
      const FragId f = up[rng() % up.size()];
      frontier.coarsen(mt(), f);
      EXPECT_TRUE(frontier.contains(f));
    } else {
      const FragId f = down[rng() % down.size()];
      frontier.refine(mt(), f);
      EXPECT_FALSE(frontier.contains(f));
    }
    const ValidationReport report = validate_frontier(mt(), frontier);
    ASSERT_TRUE(report.ok()) << "step " << step << ": " << report.summary();
  }
}

TEST_P(FrontierOnMeshes, RefineUndoesCoarsen) {
  Frontier frontier = Frontier::finest(mt());
  const auto before = sorted_tets(frontier);
  for (FragId f : frontier.coarsenable(mt())) {
    frontier.coarsen(mt(), f);
    EXPECT_TRUE(frontier.can_refine(mt(), f));
    frontier.refine(mt(), f);
  }
  EXPECT_EQ(sorted_tets(frontier), before);
}

TEST_P(FrontierOnMeshes, SurfaceIsClosedAndOutward) {
  for (const Frontier& frontier : {Frontier::finest(mt()), Frontier::coarsest(mt())}) {
    // Divergence theorem: sum over faces of (centroid . area normal) / 3 = volume.
    double flux = 0.0;
    for (const auto& face : frontier.boundary_faces(mt())) {
      const Vec3 &a = mt().position(face[0]), &b = mt().position(face[1]), &c = mt().position(face[2]);
      flux += ((a + b + c) / 3.0).dot((b - a).cross(c - a) / 2.0) / 3.0;
    }
    EXPECT_NEAR(flux, frontier.volume(mt()), 1e-9 * frontier.volume(mt()));
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, FrontierOnMeshes,
                         ::testing::Values(FrontierCase{"liver", false}, FrontierCase{"ellipsoid", true},
                                           FrontierCase{"box", true}, FrontierCase{"armadillo", false}),
                         [](const auto& case_info) {
                           return case_info.param.mesh + (case_info.param.preserve ? "_preserved" : "_free");
                         });

TEST(Frontier, ValidateRejectsASetThatIsNotParentClosed) {
  const Mt& mt = test_mt("box");
  // A fragment whose parents are not all in S, without them.
  FragId deep;
  for (std::size_t f = 0; f < mt.num_fragments() && !deep.valid(); ++f) {
    const auto parents = mt.parents(FragId(f));
    if (std::any_of(parents.begin(), parents.end(), [&](FragId p) { return p != mt.root(); })) deep = FragId(f);
  }
  ASSERT_TRUE(deep.valid());
  const FragId set[] = {mt.root(), deep};
  const ValidationReport report = validate_frontier(mt, Frontier::from_fragments(mt, set));
  EXPECT_FALSE(report.ok());
  EXPECT_NE(report.summary().find("parent"), std::string::npos) << report.summary();
}

TEST(Frontier, ToTetMeshIsTheFrontierMesh) {
  const Mt& mt = test_mt("ellipsoid");
  const Frontier frontier = Frontier::coarsest(mt);
  std::vector<VertId> ids;
  const TetMesh mesh = frontier.to_tet_mesh(mt, &ids);
  EXPECT_TRUE(mesh.validate().ok());
  EXPECT_EQ(mesh.num_tets(), frontier.tets().size());
  EXPECT_EQ(mesh.num_vertices(), frontier.vertices().size());
  EXPECT_NEAR(mesh.total_volume(), frontier.volume(mt), 1e-12);
  for (std::size_t v = 0; v < ids.size(); ++v) EXPECT_EQ(mesh.positions[v], mt.position(ids[v]));
}

}  // namespace
}  // namespace mtcut::engine
