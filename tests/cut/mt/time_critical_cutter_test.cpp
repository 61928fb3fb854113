#include "cut/mt/time_critical_cutter.h"

#include <gtest/gtest.h>

#include "tests/cut/mt/mt_cut_test_util.h"

namespace mtcut::test {
namespace {

using cut::CutBudget;
using cut::TimeCriticalCutter;

// Runs `polygons` through a cutter with `budget` per call, checking after
// every call: frozen while jobs are pending, the MT valid, the frontier
// followed in place (follow_cut) equal to the rebuilt one (map_frontier),
// valid and showing every cut whose visible jobs are done, and no hidden job
// before a visible one of the same cut.
Mt run_cutter(const std::vector<CutPolygon>& polygons, const CutBudget& budget, bool visible_at_once,
              std::size_t* calls_out) {
  Mt mt = cut_test_mt("ellipsoid");
  engine::TetBvh bvh(mt);
  std::mt19937_64 rng(3);
  Frontier frontier = random_frontier(mt, rng);
  cut::TimeCriticalCutterDef def;
  def.visible_at_once = visible_at_once;
  TimeCriticalCutter cutter(def);
  for (const auto& p : polygons) cutter.submit(mt, p);
  EXPECT_TRUE(cutter.frozen());
  std::size_t calls = 0, finished = 0;
  bool hidden_seen = false;
  std::vector<char> visible_at_start;
  while (cutter.frozen()) {
    const auto before = cutter.progress();
    if (before.jobs_done == 0) {
      // A cut starts in this call (or the previous one did not reach it):
      // its visible set is the frontier's now.
      hidden_seen = false;
      visible_at_start.assign(mt.num_fragments(), 0);
      for (FragId f : frontier.visible_fragments()) visible_at_start[f.index()] = 1;
    }
    const auto result = cutter.run(mt, bvh, frontier, budget);
    ++calls;
    for (FragId f : result.changes.processed) {
      const bool visible = f.index() < visible_at_start.size() && visible_at_start[f.index()];
      if (result.cuts_finished == 0) {
        EXPECT_FALSE(visible && hidden_seen) << "a visible job after a hidden one";
      }
      hidden_seen = hidden_seen || !visible;
    }
    // The World's in-place update agrees with the rebuild of the mapped set.
    const Frontier rebuilt = cut::map_frontier(mt, frontier, result.changes.fragment_splits);
    cut::follow_cut(mt, frontier, result.changes);
    EXPECT_EQ(frontier_difference(frontier, rebuilt), "") << "after call " << calls;
    const auto cr = cutter.validate(mt);
    EXPECT_TRUE(cr.ok()) << cr.summary();
    EXPECT_TRUE(bvh.validate(mt).ok()) << "after call " << calls << ": " << bvh.validate(mt).summary();
    finished += result.cuts_finished;
    const auto p = cutter.progress();
    // Spread visible jobs leave the visible mesh half cut: the World waits for them.
    if (visible_at_once || p.visible_pending == 0) {
      const auto fr = engine::validate_frontier(mt, frontier);
      EXPECT_TRUE(fr.ok()) << "after call " << calls << ": " << fr.summary();
    }
    EXPECT_EQ(cutter.frozen(), p.cuts_queued > 0);
    // Every finished cut, and the active one once its visible jobs are done, is in the mesh.
    const std::size_t shown = finished + (p.cuts_queued > 0 && p.jobs_done > 0 && p.visible_pending == 0 ? 1 : 0);
    // (Earlier cuts are checked near their outline in mt_cut_test; here the
    // last cut that changed the MT, once shown, is checked exactly.)
    const std::size_t started = finished + (p.cuts_queued > 0 && p.jobs_done > 0 ? 1 : 0);
    if (shown == started && shown > 0) {
      EXPECT_EQ(properly_crossed_tets(mt, frontier, polygons[shown - 1]), 0u) << "call " << calls;
    }
    if (visible_at_once && p.cuts_queued > 0 && p.jobs_done > 0) {
      EXPECT_EQ(p.visible_pending, 0u);
    }
    if (calls > 100000) break;
  }
  EXPECT_EQ(finished, polygons.size());
  const auto report = mt.validate();
  EXPECT_TRUE(report.ok()) << report.summary();
  *calls_out = calls;
  return mt;
}

std::vector<CutPolygon> three_cuts() {
  Mt const& mt = cut_test_mt("ellipsoid");
  std::mt19937_64 rng(77);
  return {random_polygon(mt_box(mt), rng, false), random_polygon(mt_box(mt), rng, true),
          random_polygon(mt_box(mt), rng, false)};
}

TEST(TimeCriticalCutter, TinyBudgetGivesTheSameMtAsUnlimited) {
  const auto polygons = three_cuts();
  std::size_t calls_unlimited = 0, calls_tiny = 0, calls_spread = 0;
  const Mt unlimited = run_cutter(polygons, CutBudget::unlimited(), true, &calls_unlimited);
  const Mt tiny = run_cutter(polygons, CutBudget::units(1), true, &calls_tiny);
  const Mt spread = run_cutter(polygons, CutBudget::units(1), false, &calls_spread);
  EXPECT_EQ(calls_unlimited, 1u);
  EXPECT_GT(calls_tiny, 3u);
  EXPECT_GT(calls_spread, calls_tiny);
  EXPECT_TRUE(canonical_mt(tiny) == canonical_mt(unlimited));
  EXPECT_TRUE(canonical_mt(spread) == canonical_mt(unlimited));
}

// A budget of milliseconds already spent (none) does one job a call (every
// call does at least one), as a budget of one work unit does: the same
// calls and the same MT, on any machine at any speed.
TEST(TimeCriticalCutter, ASpentMillisecondBudgetDoesOneJobACall) {
  const auto polygons = three_cuts();
  std::size_t calls_ms = 0, calls_units = 0;
  const Mt by_ms = run_cutter(polygons, CutBudget::ms(0.0), true, &calls_ms);
  const Mt by_units = run_cutter(polygons, CutBudget::units(1), true, &calls_units);
  EXPECT_GT(calls_ms, 3u);
  EXPECT_EQ(calls_ms, calls_units);
  EXPECT_TRUE(canonical_mt(by_ms) == canonical_mt(by_units));
}

TEST(TimeCriticalCutter, AProvisionalCutCountsPiecesOnlyWithoutAFront) {
  // A provisional cut whose outline passes through the tissue (a stroke's
  // blade in it) separates nothing but a lobe, and the next frame takes it
  // back: its pieces are not counted (a pass over the MT). The same cut
  // through the whole object counts them. A cut that changes nothing (the
  // blade not in the tissue yet) counts none: the caller counted the MT's
  // pieces before the cutter's first cut.
  Mt mt = cut_test_mt("ellipsoid");
  engine::TetBvh bvh(mt);
  Frontier frontier = Frontier::coarsest(mt);
  const engine::Aabb box = mt_box(mt);
  const Vec3 size = box.hi - box.lo, centre = box.center();
  const auto square = [&](double y_hi) {
    const double x = centre.x() + 0.013 * size.x();
    const double y_lo = box.lo.y() - 0.1 * size.y(), z_lo = box.lo.z() - 0.1 * size.z(),
                 z_hi = box.hi.z() + 0.1 * size.z();
    return CutPolygon::from_points(
        {Vec3(x, y_lo, z_lo), Vec3(x, y_hi, z_lo), Vec3(x, y_hi, z_hi), Vec3(x, y_lo, z_hi)});
  };
  TimeCriticalCutter cutter;
  const double outside = box.lo.y() - 0.05 * size.y();
  cutter.submit_provisional(CutPolygon::from_points({Vec3(centre.x(), outside, box.lo.z()),
                                                      Vec3(centre.x(), outside - 0.01 * size.y(), box.lo.z()),
                                                      Vec3(centre.x(), outside, box.hi.z())}));
  const TimeCriticalCutter::RunResult nothing = cutter.run(mt, bvh, frontier, CutBudget::unlimited());
  EXPECT_EQ(nothing.cuts_finished, 1u);
  EXPECT_TRUE(nothing.changes.replaced.empty());
  EXPECT_FALSE(nothing.pieces.has_value()) << "a cut that changed nothing counted pieces";
  if (const std::optional<cut::CutRetraction> none = cutter.retract(mt, bvh)) cut::follow_retraction(mt, frontier, *none);
  cutter.submit_provisional(square(centre.y()));  // into the middle
  TimeCriticalCutter::RunResult partial = cutter.run(mt, bvh, frontier, CutBudget::unlimited());
  cut::follow_cut(mt, frontier, partial.changes);
  EXPECT_GT(partial.changes.replaced.size(), 0u);
  EXPECT_FALSE(partial.pieces.has_value()) << "a provisional cut with a front counted pieces";
  const std::optional<cut::CutRetraction> back = cutter.retract(mt, bvh);
  ASSERT_TRUE(back.has_value());
  cut::follow_retraction(mt, frontier, *back);
  cutter.submit_provisional(square(box.hi.y() + 0.1 * size.y()));  // right through
  TimeCriticalCutter::RunResult through = cutter.run(mt, bvh, frontier, CutBudget::unlimited());
  cut::follow_cut(mt, frontier, through.changes);
  EXPECT_TRUE(through.pieces.has_value()) << "a provisional cut right through counted no pieces";
  for (const auto& report : {mt.validate(), bvh.validate(mt), engine::validate_frontier(mt, frontier),
                             cutter.validate(mt)})
    EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(TimeCriticalCutter, RoomReservedChangesNoCut) {
  // The room a World reserves when it is made (TimeCriticalCutter::reserve)
  // changes neither the MT nor what a cut makes of it: the same cuts give
  // the same MT, and the cutter's storage is handed back clean.
  const auto polygons = three_cuts();
  const auto cut_all = [&](bool reserve) {
    Mt mt = cut_test_mt("ellipsoid");
    engine::TetBvh bvh(mt);
    Frontier frontier = Frontier::coarsest(mt);
    TimeCriticalCutter cutter;
    if (reserve) {
      cutter.reserve(mt);
      EXPECT_TRUE(canonical_mt(mt) == canonical_mt(cut_test_mt("ellipsoid")));
      EXPECT_TRUE(cutter.validate(mt).ok()) << cutter.validate(mt).summary();
    }
    for (const CutPolygon& p : polygons) {
      cutter.submit(mt, p);
      cut::follow_cut(mt, frontier, cutter.run(mt, bvh, frontier, CutBudget::unlimited()).changes);
      EXPECT_TRUE(cutter.validate(mt).ok()) << cutter.validate(mt).summary();
    }
    EXPECT_TRUE(mt.validate().ok()) << mt.validate().summary();
    return mt;
  };
  EXPECT_TRUE(canonical_mt(cut_all(true)) == canonical_mt(cut_all(false)));
}

TEST(TimeCriticalCutter, MapFragmentSetAddsEveryPart) {
  const std::vector<FragId> s = {FragId(0), FragId(2), FragId(5)};
  const std::vector<cut::FragmentSplit> splits = {{FragId(2), {FragId(2), FragId(9)}},
                                                  {FragId(9), {FragId(9), FragId(11), FragId(12)}},
                                                  {FragId(3), {FragId(3), FragId(10)}}};
  const auto mapped = cut::map_fragment_set(s, splits);
  const std::vector<FragId> expected = {FragId(0), FragId(2), FragId(5), FragId(9), FragId(11), FragId(12)};
  EXPECT_EQ(mapped, expected);
}

}  // namespace
}  // namespace mtcut::test
