#include "engine/mt/selective_refinement.h"

#include <gtest/gtest.h>

#include <random>

#include "engine/mt/tet_bvh.h"
#include "tests/engine/mt/mt_test_util.h"

namespace mtcut::engine {
namespace {

using mtcut::test::sorted_tets;
using mtcut::test::test_mesh;
using mtcut::test::test_mt;

// The box around the MT's vertices.
Aabb mt_box(const Mt& mt) {
  Aabb box;
  for (const Vec3& p : mt.positions()) box.extend(p);
  return box;
}

// A field fine near the focus, growing outwards, scaled to the MT's errors.
ErrorField field_for(const Mt& mt, const Segment& focus) {
  float fine = 0.0f;
  for (TetId t : mt.created(mt.root())) fine = std::max(fine, mt.error(t));
  const Aabb box = mt_box(mt);
  ErrorField field;
  field.focus = focus;
  field.radius = 0.15 * (box.hi - box.lo).norm();
  field.near_error = fine;
  field.growth = 0.5;
  return field;
}

struct SelectiveCase {
  std::string mesh;
  bool preserve;
};

class SelectiveRefinementOnMeshes : public ::testing::TestWithParam<SelectiveCase> {
 protected:
  const Mt& mt() const { return test_mt(GetParam().mesh, GetParam().preserve); }

  // 30 incremental updates along a scalpel path (small steps, now and then a
  // jump) of a point focus, or of a blade whose two ends move apart (it
  // turns and reaches into the model and out). After every update the
  // frontier is the one extracted from scratch, and valid.
  void follow_scalpel_path(bool blade, unsigned seed) const {
    const Aabb box = mt_box(mt());
    const double size = (box.hi - box.lo).norm();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto random_point = [&]() -> Vec3 {
      return box.lo + (box.hi - box.lo).cwiseProduct(Vec3(unit(rng), unit(rng), unit(rng)));
    };
    const auto nudge = [&]() -> Vec3 { return 0.03 * size * Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5); };
    const auto jump = [&] { return blade ? Segment{random_point(), random_point()} : Segment::point(random_point()); };
    SelectiveRefiner refiner;
    Frontier frontier = Frontier::finest(mt());
    Segment focus = jump();
    std::size_t incremental = 0;
    for (int step = 0; step < 30; ++step) {
      if (step % 10 == 9) {
        focus = jump();
      } else {
        focus.a += nudge();
        focus.b = blade ? Vec3(focus.b + nudge()) : focus.a;
      }
      const ErrorField field = field_for(mt(), focus);
      const SelectiveRefiner::Stats stats = refiner.update(mt(), field, frontier);
      incremental += stats.incremental;
      ASSERT_EQ(sorted_tets(frontier), sorted_tets(extract_frontier(mt(), field))) << "step " << step;
      const ValidationReport report = validate_frontier(mt(), frontier);
      ASSERT_TRUE(report.ok()) << "step " << step << ": " << report.summary();
    }
    EXPECT_EQ(incremental, 29u);  // all but the first
  }
};

TEST_P(SelectiveRefinementOnMeshes, UniformErrorZeroIsFineAndInfinityCoarsest) {
  EXPECT_EQ(sorted_tets(extract_uniform(mt(), 0.0)), sorted_tets(Frontier::finest(mt())));
  EXPECT_EQ(sorted_tets(extract_uniform(mt(), std::numeric_limits<double>::infinity())),
            sorted_tets(Frontier::coarsest(mt())));
}

TEST_P(SelectiveRefinementOnMeshes, UniformLevelsCoarsenAsTheErrorGrows) {
  float top = 0.0f;
  for (std::size_t t = 0; t < mt().num_tets(); ++t) top = std::max(top, mt().error(TetId(t)));
  std::size_t previous = std::numeric_limits<std::size_t>::max();
  for (double e : {0.0, 0.1, 0.2, 0.4, 0.7, 1.0}) {
    const Frontier frontier = extract_uniform(mt(), e * top);
    const ValidationReport report = validate_frontier(mt(), frontier);
    ASSERT_TRUE(report.ok()) << report.summary();
    // Every tet not from the fine mesh meets the error.
    for (TetId t : frontier.tets())
      if (mt().birth(t) != mt().root()) {
        EXPECT_LE(mt().error(t), e * top);
      }
    EXPECT_LE(frontier.tets().size(), previous);
    previous = frontier.tets().size();
  }
}

TEST_P(SelectiveRefinementOnMeshes, IncrementalUpdatesMatchExtractionFromScratch) {
  follow_scalpel_path(/*blade=*/false, 5);
}

TEST_P(SelectiveRefinementOnMeshes, IncrementalUpdatesFollowABladeAsExtractionFromScratch) {
  follow_scalpel_path(/*blade=*/true, 8);
}

TEST_P(SelectiveRefinementOnMeshes, NearTheFocusTheFrontierIsAsFineAsAsked) {
  const Aabb box = mt_box(mt());
  ErrorField field = field_for(mt(), Segment::point(box.center()));
  const Frontier frontier = extract_frontier(mt(), field);
  for (TetId t : frontier.tets()) {
    if (mt().birth(t) == mt().root()) continue;
    const double d = min_distance(tet_box(mt(), t), field.focus);
    EXPECT_LE(mt().error(t), field.threshold(d));
  }
  // And it is coarser than the fine mesh elsewhere.
  EXPECT_LT(frontier.tets().size(), mt().created(mt().root()).size());
}

INSTANTIATE_TEST_SUITE_P(Meshes, SelectiveRefinementOnMeshes,
                         ::testing::Values(SelectiveCase{"liver", false}, SelectiveCase{"ellipsoid", true},
                                           SelectiveCase{"box", true}, SelectiveCase{"armadillo", false}),
                         [](const auto& case_info) {
                           return case_info.param.mesh + (case_info.param.preserve ? "_preserved" : "_free");
                         });

TEST(SelectiveRefinement, AroundTheScalpelTheMeshIsFine) {
  const Mt& mt = test_mt("box");
  const Aabb box = mt_box(mt);
  const ErrorField field = ErrorField::around(Segment::point(box.center()), 0.2 * (box.hi - box.lo).minCoeff());
  const Frontier frontier = extract_frontier(mt, field);
  ASSERT_TRUE(validate_frontier(mt, frontier).ok());
  std::size_t near = 0;
  for (TetId t : frontier.tets())
    if (min_distance(tet_box(mt, t), field.focus) <= field.radius) {
      ++near;
      EXPECT_EQ(mt.birth(t), mt.root());
    }
  EXPECT_GT(near, 0u);
  EXPECT_LT(frontier.tets().size(), mt.created(mt.root()).size());
}

// A blade through the model, its tip beyond it (a scalpel drawn down to the
// table): the mesh is fine along the whole blade inside the model, not only
// near the tip, which is in no tet's reach.
TEST(SelectiveRefinement, AlongTheWholeBladeTheMeshIsFine) {
  const Mt& mt = test_mt("box");
  const Aabb box = mt_box(mt);
  const Vec3 size = box.hi - box.lo;
  const double radius = 0.1 * size.minCoeff();
  const Vec3 top(box.center().x(), box.center().y(), box.hi.z() + 0.5 * size.z());
  const Segment blade{top, Vec3(top.x(), top.y(), box.lo.z() - 0.5 * size.z())};
  const ErrorField field = ErrorField::around(blade, radius);
  const Frontier frontier = extract_frontier(mt, field);
  ASSERT_TRUE(validate_frontier(mt, frontier).ok());
  std::size_t near_blade = 0;
  for (TetId t : frontier.tets()) {
    const Aabb tet = tet_box(mt, t);
    ASSERT_GT(tet.min_distance(blade.b), radius);  // the tip is out of reach
    if (min_distance(tet, blade) <= radius) {
      ++near_blade;
      EXPECT_EQ(mt.birth(t), mt.root());
    }
  }
  EXPECT_GT(near_blade, 0u);
  EXPECT_LT(frontier.tets().size(), mt.created(mt.root()).size());
}

TEST(SelectiveRefinement, SmallFocusMovesTouchOnlyNearbyFragments) {
  const Mt& mt = test_mt("ellipsoid-3k", false);
  const Aabb box = mt_box(mt);
  const double size = (box.hi - box.lo).norm();
  SelectiveRefiner refiner;
  Frontier frontier = Frontier::finest(mt);
  Vec3 focus = box.center() - 0.2 * (box.hi - box.lo);
  refiner.update(mt, field_for(mt, Segment::point(focus)), frontier);
  std::size_t tested = 0, steps = 0;
  for (; steps < 20; ++steps) {
    focus += Vec3(0.004 * size, 0.002 * size, 0.0);
    const SelectiveRefiner::Stats stats = refiner.update(mt, field_for(mt, Segment::point(focus)), frontier);
    EXPECT_TRUE(stats.incremental);
    tested += stats.fragments_tested;
  }
  // On average a step looks at a small share of the fragments.
  EXPECT_LT(static_cast<double>(tested) / static_cast<double>(steps), 0.1 * static_cast<double>(mt.num_fragments()))
      << tested / steps << " of " << mt.num_fragments();
  EXPECT_EQ(sorted_tets(frontier), sorted_tets(extract_frontier(mt, field_for(mt, Segment::point(focus)))));
}

TEST(SelectiveRefinement, AFrontierEditedElsewhereGetsAFullPass) {
  const Mt& mt = test_mt("box");
  const Aabb box = mt_box(mt);
  SelectiveRefiner refiner;
  Frontier frontier = Frontier::finest(mt);
  const ErrorField field = field_for(mt, Segment::point(box.lo));
  EXPECT_FALSE(refiner.update(mt, field, frontier).incremental);
  EXPECT_TRUE(refiner.update(mt, field, frontier).incremental);
  // Someone refines by hand: the refiner must notice.
  const auto refinable = frontier.refinable(mt);
  ASSERT_FALSE(refinable.empty());
  frontier.refine(mt, refinable.front());
  const SelectiveRefiner::Stats stats = refiner.update(mt, field, frontier);
  EXPECT_FALSE(stats.incremental);
  EXPECT_EQ(sorted_tets(frontier), sorted_tets(extract_frontier(mt, field)));
  // A different threshold shape too.
  ErrorField other = field;
  other.growth *= 2;
  EXPECT_FALSE(refiner.update(mt, other, frontier).incremental);
  EXPECT_EQ(sorted_tets(frontier), sorted_tets(extract_frontier(mt, other)));
}

}  // namespace
}  // namespace mtcut::engine
