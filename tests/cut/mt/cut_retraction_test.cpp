// Retracting a provisional cut (cut/mt/cut_retraction.h): the MT as before
// the cut up to numbering, and a stroke part cut provisionally step after
// step ends as the one cut of its polygon.
#include "cut/mt/cut_retraction.h"

#include <gtest/gtest.h>

#include <random>

#include "cut/mt/time_critical_cutter.h"
#include "tests/cut/mt/mt_cut_test_util.h"

namespace mtcut::test {
namespace {

// A rectangle in the plane x = x0 (tilted by `tilt` in z), from y0 to y1,
// z from above the box's top down to `bottom`.
CutPolygon blade_rect(const engine::Aabb& box, double y0, double y1, double bottom, double tilt = 0.0) {
  const Vec3 c = box.center(), size = box.hi - box.lo;
  const double x0 = c.x() + 0.0137 * size.x(), top = box.hi.z() + 0.05 * size.z();
  const auto at = [&](double y, double z) { return Vec3(x0 + tilt * (y - c.y()), y, z); };
  return CutPolygon::from_points({at(y0, top), at(y1, top), at(y1, bottom), at(y0, bottom)});
}

void expect_valid(const Mt& mt, const engine::TetBvh& bvh, const std::string& where) {
  const auto report = mt.validate();
  EXPECT_TRUE(report.ok()) << where << ": " << report.summary();
  const auto index = bvh.validate(mt);
  EXPECT_TRUE(index.ok()) << where << ": " << index.summary();
}

TEST(CutRetraction, RetractingACutRestoresTheMtUpToNumbering) {
  std::mt19937_64 rng(7);
  for (const std::string name : {"ellipsoid", "liver"}) {
    const Mt& original = cut_test_mt(name);
    const auto canonical = canonical_mt(original);
    const engine::Aabb box = mt_box(original);
    for (int i = 0; i < 6; ++i) {
      const std::string where = name + " cut " + std::to_string(i);
      Mt mt = original;
      engine::TetBvh bvh(mt);
      const std::size_t fragments = mt.num_fragments(), live = mt.num_live_tets();
      const cut::MtChangeReport report = cut::cut_mt(mt, bvh, random_polygon(box, rng, i % 2 == 0));
      ASSERT_GT(report.counts.split_tets, 0u) << where;
      EXPECT_TRUE(cut::validate_retractable(mt, report, fragments).ok()) << where;
      const cut::CutRetraction r = cut::retract_cut(mt, bvh, report, fragments);
      expect_valid(mt, bvh, where);
      EXPECT_EQ(mt.num_fragments(), fragments) << where;
      EXPECT_EQ(mt.num_live_tets(), live) << where;
      EXPECT_EQ(r.revived.size(), report.replaced.size()) << where;
      EXPECT_EQ(r.killed.size(), report.made_tets.size()) << where;
      EXPECT_EQ(r.fragments_removed, report.counts.new_fragments) << where;
      EXPECT_TRUE(canonical_mt(mt) == canonical) << where;
    }
  }
}

// A provisional cut (no fragment decomposed) taken back split by split,
// some now and the rest later: the splits left stay, the report keeps
// every vertex the cut made, and once every split is taken back the MT is
// as before, up to numbering. A cut that decomposed fragments is refused.
TEST(CutRetraction, SplitsTakenBackOneByOneRestoreTheMt) {
  std::mt19937_64 rng(11);
  for (const std::string name : {"ellipsoid", "liver"}) {
    const Mt& original = cut_test_mt(name);
    const auto canonical = canonical_mt(original);
    const engine::Aabb box = mt_box(original);
    for (int i = 0; i < 4; ++i) {
      const std::string where = name + " cut " + std::to_string(i);
      Mt mt = original;
      engine::TetBvh bvh(mt);
      cut::CutMtOptions options;
      options.def.decompose = false;
      cut::MtChangeReport report = cut::cut_mt(mt, bvh, random_polygon(box, rng, i % 2 == 0), {}, options);
      ASSERT_GT(report.replaced.size(), 1u) << where;
      const std::size_t made = report.made_vertices.size(), splits = report.replaced.size();
      std::vector<std::uint8_t> take(report.replaced.size());
      for (auto& t : take) t = rng() % 2;
      const std::size_t taken = static_cast<std::size_t>(std::count(take.begin(), take.end(), 1));
      const cut::CutRetraction first = cut::retract_replacements(mt, bvh, report, take);
      EXPECT_EQ(first.revived.size(), taken) << where;
      EXPECT_EQ(report.replaced.size(), splits - taken) << where;
      EXPECT_TRUE(cut::validate_replacements(mt, report).ok()) << where << ": "
                                                               << cut::validate_replacements(mt, report).summary();
      EXPECT_TRUE(bvh.validate(mt).ok()) << where << ": " << bvh.validate(mt).summary();
      EXPECT_EQ(report.made_vertices.size(), made) << where;
      const std::vector<std::uint8_t> rest(report.replaced.size(), 1);
      const cut::CutRetraction second = cut::retract_replacements(mt, bvh, report, rest);
      EXPECT_EQ(second.revived.size(), splits - taken) << where;
      EXPECT_TRUE(report.replaced.empty() && report.made_tets.empty()) << where;
      expect_valid(mt, bvh, where);
      EXPECT_TRUE(canonical_mt(mt) == canonical) << where;
    }
  }
  Mt mt = cut_test_mt("ellipsoid");
  engine::TetBvh bvh(mt);
  cut::MtChangeReport decomposing = cut::cut_mt(mt, bvh, random_polygon(mt_box(mt), rng, true));
  ASSERT_FALSE(decomposing.fragment_splits.empty());
  const std::vector<std::uint8_t> all(decomposing.replaced.size(), 1);
  EXPECT_THROW(cut::retract_replacements(mt, bvh, decomposing, all), std::logic_error);
}

TEST(CutRetraction, AReportThatDoesNotMatchTheMtIsRefused) {
  Mt mt = cut_test_mt("ellipsoid");
  engine::TetBvh bvh(mt);
  const std::size_t fragments = mt.num_fragments();
  cut::MtChangeReport report = cut::cut_mt(mt, bvh, blade_rect(mt_box(mt), -1, 1, -1));
  ASSERT_FALSE(report.made_tets.empty());
  cut::MtChangeReport stale = report;
  mt.kill_tet(stale.made_tets.front());  // something else edited the MT
  EXPECT_FALSE(cut::validate_retractable(mt, stale, fragments).ok());
  EXPECT_THROW(cut::retract_cut(mt, bvh, stale, fragments), std::logic_error);
}

// A straight part of a stroke, its polygon growing pose after pose, cut
// provisionally at every pose (the last cut retracted first), ends with the
// MT the one cut of its final polygon makes: each tet split once from its
// original, whatever the number of steps.
TEST(CutRetraction, AGrowingPartCutAtEveryStepEndsAsItsOneCut) {
  for (const std::string name : {"ellipsoid", "liver", "box"}) {
    const Mt& original = cut_test_mt(name);
    const engine::Aabb box = mt_box(original);
    const Vec3 size = box.hi - box.lo;
    for (const double depth : {0.6, 1.1}) {
      const double bottom = box.hi.z() - depth * size.z();
      const double y0 = box.lo.y() - 0.02 * size.y();
      const auto polygon_at = [&](int k, int steps) { return blade_rect(box, y0, y0 + 1.04 * size.y() * k / steps, bottom, 0.1); };
      const int steps = 24;
      Mt one = original;
      engine::TetBvh one_bvh(one);
      cut::cut_mt(one, one_bvh, polygon_at(steps, steps));
      Mt mt = original;
      engine::TetBvh bvh(mt);
      std::optional<std::pair<cut::MtChangeReport, std::size_t>> held;
      for (int k = 1; k <= steps; ++k) {
        const std::string where = name + " depth " + std::to_string(depth) + " step " + std::to_string(k);
        if (held) cut::retract_cut(mt, bvh, held->first, held->second);
        const std::size_t fragments = mt.num_fragments();
        held.emplace(cut::cut_mt(mt, bvh, polygon_at(k, steps)), fragments);
        expect_valid(mt, bvh, where);
        if (::testing::Test::HasFailure()) return;
      }
      EXPECT_EQ(mt.num_live_tets(), one.num_live_tets()) << name;
      EXPECT_TRUE(canonical_mt(mt) == canonical_mt(one)) << name << " depth " << depth;
    }
  }
}

// What retracted cuts leave (dead pieces, unused vertices) is dropped by
// Mt::compact: the MT the same up to numbering, every slot live, every
// vertex from the first droppable one on used, the ones before it (the
// mesh's own) keeping their ids, and the maps sending each kept tet and
// vertex to its new self; the BVH follows (TetBvh::renumber).
TEST(CutRetraction, CompactingDropsWhatRetractedCutsLeft) {
  std::mt19937_64 rng(5);
  for (const std::string name : {"ellipsoid", "liver"}) {
    Mt mt = cut_test_mt(name);
    const std::size_t original_vertices = mt.num_vertices();
    const engine::Aabb box = mt_box(mt);
    engine::TetBvh bvh(mt);
    // A kept cut, then cuts taken back, then another kept one.
    cut::cut_mt(mt, bvh, random_polygon(box, rng, true));
    for (int i = 0; i < 4; ++i) {
      const std::size_t fragments = mt.num_fragments();
      const cut::MtChangeReport report = cut::cut_mt(mt, bvh, random_polygon(box, rng, i % 2 == 0));
      cut::retract_cut(mt, bvh, report, fragments);
    }
    cut::cut_mt(mt, bvh, random_polygon(box, rng, false));
    ASSERT_GT(mt.num_dead_tets(), 0u) << name;
    ASSERT_GT(mt.num_unused_vertices(), 0u) << name;
    const Mt before = mt;
    const auto canonical = canonical_mt(mt);
    const engine::Mt::Compaction c = mt.compact(original_vertices);
    bvh.renumber(c);  // the same tree over the new ids
    expect_valid(mt, bvh, name);
    EXPECT_EQ(c.tets_dropped, before.num_dead_tets()) << name;
    EXPECT_EQ(mt.num_tets(), mt.num_live_tets()) << name;
    EXPECT_EQ(mt.num_dead_tets(), 0u) << name;
    EXPECT_EQ(mt.num_unused_vertices(), 0u) << name;  // the mesh's own vertices are all used here
    EXPECT_EQ(c.vertices_dropped + mt.num_vertices(), before.num_vertices()) << name;
    EXPECT_TRUE(canonical_mt(mt) == canonical) << name;
    EXPECT_NE(mt.instance(), before.instance()) << name;
    for (std::size_t v = 0; v < original_vertices; ++v) ASSERT_EQ(c.vertex_map[v], static_cast<std::int32_t>(v)) << name;
    for (std::size_t v = 0; v < before.num_vertices(); ++v) {
      if (c.vertex_map[v] >= 0) {
        ASSERT_EQ(mt.position(c.vertex(VertId(v))), before.position(VertId(v))) << name;
      }
    }
    for (std::size_t t = 0; t < before.num_tets(); ++t) {
      const TetId old(t);
      ASSERT_EQ(c.tet_map[t] >= 0, before.alive(old)) << name << " tet " << t;
      if (!before.alive(old)) continue;
      const TetId now = c.tet(old);
      for (int k = 0; k < 4; ++k) ASSERT_EQ(mt.tet(now)[k], c.vertex(before.tet(old)[k])) << name;
      EXPECT_EQ(mt.birth(now), before.birth(old)) << name;
      EXPECT_EQ(mt.death(now), before.death(old)) << name;
    }
  }
}

// Through the time-critical cutter: a provisional cut with hidden jobs left
// (a budget of one job) is retracted as cleanly, the frontier mapped back.
TEST(CutRetraction, TheCutterRetractsAProvisionalCutHalfDone) {
  std::mt19937_64 rng(11);
  for (const std::string name : {"ellipsoid", "liver"}) {
    const Mt& original = cut_test_mt(name);
    const auto canonical = canonical_mt(original);
    for (int i = 0; i < 4; ++i) {
      const std::string where = name + " run " + std::to_string(i);
      Mt mt = original;
      engine::TetBvh bvh(mt);
      Frontier frontier = random_frontier(mt, rng);
      const Frontier before = frontier;
      cut::TimeCriticalCutter cutter;
      cutter.submit_provisional(random_polygon(mt_box(mt), rng, true));
      EXPECT_TRUE(cutter.provisional_held());
      EXPECT_THROW(cutter.submit(mt, random_polygon(mt_box(mt), rng, true)), std::logic_error);
      const auto result = cutter.run(mt, bvh, frontier, cut::CutBudget::units(1));
      cut::follow_cut(mt, frontier, result.changes);
      EXPECT_TRUE(cutter.validate(mt).ok()) << where << ": " << cutter.validate(mt).summary();
      EXPECT_TRUE(engine::validate_frontier(mt, frontier).ok()) << where;
      const auto r = cutter.retract(mt, bvh);
      ASSERT_TRUE(r.has_value()) << where;
      EXPECT_FALSE(cutter.provisional_held());
      EXPECT_FALSE(cutter.frozen());
      const Frontier rebuilt = Frontier::from_fragments(mt, cut::retract_fragment_set(mt, frontier.fragments(), *r));
      cut::follow_retraction(mt, frontier, *r);
      expect_valid(mt, bvh, where);
      EXPECT_EQ(frontier_difference(frontier, rebuilt), "") << where;
      EXPECT_TRUE(engine::validate_frontier(mt, frontier).ok()) << where;
      EXPECT_EQ(frontier_difference(frontier, before), "") << where;
      EXPECT_TRUE(canonical_mt(mt) == canonical) << where;
      // A queued provisional cut not started is dropped: nothing to undo.
      cutter.submit_provisional(random_polygon(mt_box(mt), rng, true));
      EXPECT_FALSE(cutter.retract(mt, bvh).has_value()) << where;
      EXPECT_FALSE(cutter.frozen()) << where;
    }
  }
}

// The level of detail may leave out a part of a fragment the provisional cut
// split; mapped back, the set is closed under parents again.
TEST(CutRetraction, TheFrontierOfARetractionIsClosedUnderParents) {
  std::mt19937_64 rng(5);
  for (const std::string name : {"ellipsoid", "liver"}) {
    for (int i = 0; i < 6; ++i) {
      const std::string where = name + " run " + std::to_string(i);
      Mt mt = cut_test_mt(name);
      engine::TetBvh bvh(mt);
      Frontier frontier = random_frontier(mt, rng);
      const std::size_t fragments = mt.num_fragments();
      const cut::MtChangeReport report = cut::cut_mt(mt, bvh, random_polygon(mt_box(mt), rng, true));
      cut::follow_cut(mt, frontier, report);
      // Another level of detail over the cut MT, then the retraction.
      engine::SelectiveRefiner refiner;
      engine::ErrorField field;
      const engine::Aabb box = mt_box(mt);
      field.focus = engine::Segment{box.lo, box.lo + 0.3 * (box.hi - box.lo)};
      field.radius = 0.1 * (box.hi - box.lo).norm();
      field.growth = 4.0 / (box.hi - box.lo).norm();
      refiner.update(mt, field, frontier);
      ASSERT_TRUE(engine::validate_frontier(mt, frontier).ok()) << where;
      const cut::CutRetraction r = cut::retract_cut(mt, bvh, report, fragments);
      Frontier back = frontier;
      cut::follow_retraction(mt, back, r);
      const auto v = engine::validate_frontier(mt, back);
      EXPECT_TRUE(v.ok()) << where << ": " << v.summary();
    }
  }
}

}  // namespace
}  // namespace mtcut::test
