// Selective refinement on an MT that cuts keep changing: after each cut the
// refiner re-indexes and re-tests only the fragments the cut changed, and
// must still reach exactly the frontier an extraction from scratch gives.
// A cut that decomposes no fragment (a stroke's provisional front) or is
// taken back leaves the DAG as it was: the refiner then refits its index
// and follows the changed fragments without a pass over the DAG.

#include <optional>
#include <random>
#include <utility>

#include "cut/mt/cut_retraction.h"
#include "cut/mt/follow_cut.h"
#include "cut/mt/time_critical_cutter.h"
#include "engine/mt/tet_bvh.h"
#include "tests/cut/mt/mt_cut_test_util.h"

namespace mtcut::test {
namespace {

class RefinerAfterCuts : public ::testing::TestWithParam<const char*> {};

TEST_P(RefinerAfterCuts, ReachesTheFrontierExtractedFromScratch) {
  Mt mt = cut_test_mt(GetParam());
  engine::TetBvh bvh(mt);
  const engine::Aabb box = mt_box(mt);
  const double diagonal = (box.hi - box.lo).norm();
  float max_error = 0;
  for (std::size_t f = 0; f < mt.num_fragments(); ++f) max_error = std::max(max_error, mt.fragment_error(FragId(f)));
  engine::ErrorField field;
  field.radius = 0.1 * diagonal;
  field.growth = 2.0 * max_error / diagonal;
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  engine::SelectiveRefiner refiner;
  Frontier frontier = Frontier::coarsest(mt);
  std::size_t cuts = 0, partial_passes = 0, followed = 0, undecomposed = 0;
  // The last cut, when it decomposed nothing: taken back at the next step.
  std::optional<std::pair<cut::MtChangeReport, std::size_t>> provisional;
  for (int step = 0; step < 60; ++step) {
    field.focus = engine::Segment::point(box.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.hi - box.lo));
    const engine::SelectiveRefiner::Stats stats = refiner.update(mt, field, frontier);
    partial_passes += !stats.incremental && !stats.followed_cut && stats.fragments_tested < mt.num_fragments();
    followed += stats.followed_cut;
    ASSERT_EQ(frontier_difference(frontier, engine::extract_frontier(mt, field)), "") << "step " << step;
    ASSERT_TRUE(engine::validate_frontier(mt, frontier).ok()) << "step " << step;
    if (provisional) {  // taken back: the MT as before it, DAG and all
      const cut::CutRetraction back = cut::retract_cut(mt, bvh, provisional->first, provisional->second);
      cut::follow_retraction(mt, frontier, back);
      provisional.reset();
      ASSERT_TRUE(mt.validate().ok()) << "step " << step;
      continue;
    }
    if (step % 3 == 2) continue;  // some steps only move the focus
    const CutPolygon polygon = random_polygon(box, rng, step % 4 == 0);
    cut::CutMtOptions options;
    options.def.decompose = step % 5 < 3;  // complete polygons (step % 4 == 0) of both kinds too
    const std::size_t fragments_before = mt.num_fragments();
    cut::MtChangeReport changes = cut::cut_mt(mt, bvh, polygon, {}, options);
    cut::follow_cut(mt, frontier, changes);
    ASSERT_TRUE(engine::validate_frontier(mt, frontier).ok()) << "step " << step;
    cuts += changes.counts.split_tets > 0;
    if (!options.def.decompose && changes.counts.split_tets > 0) {
      ++undecomposed;
      provisional.emplace(std::move(changes), fragments_before);
    } else {
      ASSERT_TRUE(mt.validate().ok()) << "step " << step;
    }
  }
  {
    const engine::SelectiveRefiner::Stats stats = refiner.update(mt, field, frontier);
    followed += stats.followed_cut;
    ASSERT_EQ(frontier_difference(frontier, engine::extract_frontier(mt, field)), "");
  }
  EXPECT_GT(cuts, 12u);
  // After a cut the pass tests only what changed (and what the focus move may change).
  EXPECT_GT(partial_passes, 8u);
  // After a cut that decomposed nothing, and after taking one back, no pass at all.
  EXPECT_GT(undecomposed, 4u);
  EXPECT_GE(followed, 2 * undecomposed - (provisional ? 1 : 0));  // the last one may not be taken back
  // A copy of the MT is another object: its first pass tests every fragment.
  const Mt copy = mt;
  Frontier copy_frontier = Frontier::coarsest(copy);
  const engine::SelectiveRefiner::Stats stats = refiner.update(copy, field, copy_frontier);
  EXPECT_EQ(stats.fragments_tested, copy.num_fragments());
  EXPECT_EQ(frontier_difference(copy_frontier, engine::extract_frontier(copy, field)), "");
}

INSTANTIATE_TEST_SUITE_P(Meshes, RefinerAfterCuts, ::testing::Values("ellipsoid", "liver"));

}  // namespace
}  // namespace mtcut::test
