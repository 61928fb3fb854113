// A stroke's part cut progressively with a record (cut/mt/part_record.h):
// each frame commits the tets its polygon crosses completely and splits
// only its front provisionally, so a frame's work follows the blade, not the
// part; the record stays consistent with the MT after every frame.
#include "cut/mt/part_record.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cut/mt/fragment_ledger.h"
#include "cut/mt/mt_pieces.h"
#include "cut/mt/stroke_cutter.h"
#include "tests/cut/mt/stroke_test_util.h"

namespace mtcut::test {
namespace {

// A blade from above the box down through it (or to `depth` of its height),
// leaning by `lean` (of the box's width, at the base) and drawn across the
// box along `direction` in xy, at s in [0, 1].
cut::BladePose blade_at(const engine::Aabb& box, double s, double depth, double lean, const Vec3& direction) {
  const Vec3 size = box.hi - box.lo;
  const Vec3 foot = box.center() + (s - 0.5) * 1.2 * size.norm() * direction.normalized();
  const Vec3 across = Vec3(-direction.y(), direction.x(), 0).normalized();
  return {Vec3(foot.x(), foot.y(), box.hi.z() + 0.05 * size.z()) + lean * size.x() * across,
          Vec3(foot.x(), foot.y(), box.hi.z() - depth * size.z()), true};
}

struct PartRun {
  Mt mt;
  std::size_t most_provisional = 0;  // replaced tets of the largest provisional (front) cut held
  std::size_t committed = 0;         // pieces the part's record owned at its largest
  std::size_t pieces = 0;
  bool valid = true;
};

// What a test looks at after each frame that changed the MT (k: the frame).
using FrameCheck = std::function<void(int k, const Mt& mt, const cut::TimeCriticalCutter& cutter)>;

// The stroke in `steps` frames of a pose each, then one that disengages;
// MT, BVH, frontier, cutter (and with it the part's record) validated after
// every frame; `check`, if given, after each.
PartRun cut_part(const Mt& original, const Path& path, int steps, const std::string& where,
                 const FrameCheck& check = {}) {
  PartRun out{original};
  Mt& mt = out.mt;
  engine::TetBvh bvh(mt);
  Frontier frontier = Frontier::coarsest(mt);
  cut::StrokeSweep stroke;
  cut::TimeCriticalCutter cutter(checked_cutter());
  for (int k = 0; k <= steps + 1 && out.valid; ++k) {
    cut::BladePose pose = path(std::min(1.0, static_cast<double>(k) / steps));
    pose.engaged = k <= steps;
    const cut::StrokeStep step = cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, std::span(&pose, 1));
    if (!step.recut) continue;
    for (const auto& report : {mt.validate(), bvh.validate(mt), engine::validate_frontier(mt, frontier),
                               cutter.validate(mt)}) {
      EXPECT_TRUE(report.ok()) << where << " step " << k << ": " << report.summary();
      out.valid = out.valid && report.ok();
    }
    if (const cut::MtChangeReport* front = cutter.provisional_changes(); front && cutter.part_record())
      out.most_provisional = std::max(out.most_provisional, front->replaced.size());
    if (cutter.part_record()) out.committed = std::max(out.committed, cutter.part_record()->num_owned());
    if (check) check(k, mt, cutter);
  }
  EXPECT_FALSE(cutter.provisional_held()) << where;
  EXPECT_EQ(cutter.part_record(), nullptr) << where << ": the part's record outlived the stroke";
  EXPECT_EQ(cutter.cuts_refused(), 0u) << where;
  out.pieces = cut::find_pieces(mt).count;
  return out;
}

// Straight strokes across the object, through it and with the tip inside,
// along an oblique direction with a leaning blade (a plane no axis lies in):
// the part's frames re-split only their front (the largest provisional cut
// is a small share of what the part commits), the MT is valid after every
// frame, and the stroke ends as the one cut of its polygon, tet for tet (the
// part's polygons share one plane: stroke_sweep.h), separating the object
// when it goes through.
TEST(PartRecord, AFrameResplitsOnlyTheFront) {
  for (const std::string name : {"ellipsoid", "liver", "box"}) {
    const Mt& original = cut_test_mt(name);
    for (const double depth : {0.6, 1.1}) {
      for (const int steps : {40, 160}) {
        const Vec3 direction(0.8, 0.55, 0);
        const double lean = 0.15;
        const std::string where =
            name + " depth " + std::to_string(depth) + ", " + std::to_string(steps) + " steps";
        const engine::Aabb box = mt_box(original);
        const Path path = [&](double s) { return blade_at(box, s, depth, lean, direction); };
        // A straight part through a fresh MT meets no older crack: its
        // fronts need no balance check (part_record.h).
        const PartRun r = cut_part(original, path, steps, where, [&](int k, const Mt&, const cut::TimeCriticalCutter& c) {
          if (c.part_record()) {
            EXPECT_FALSE(c.part_record()->met_old_crack()) << where << " step " << k;
          }
        });
        if (!r.valid) return;
        EXPECT_GT(r.committed, 0u) << where << ": nothing was committed";
        EXPECT_LE(4 * r.most_provisional, r.committed) << where << ": a frame re-split "
                                                       << r.most_provisional << " tets of " << r.committed;
        EXPECT_TRUE(canonical_mt(r.mt) == canonical_mt(cut_at_once(original, path, steps)))
            << where;
        if (depth > 1) {
          EXPECT_EQ(r.pieces, 2u) << where;
          double volume = 0;
          for (double v : cut::piece_volumes(r.mt, cut::find_pieces(r.mt))) volume += v;
          EXPECT_NEAR(volume, original.fine_volume(), 1e-9 * original.fine_volume()) << where;
        }
        std::printf("[ report   ] %s: front at most %zu tets, %zu committed pieces, %zu pieces\n", where.c_str(),
                    r.most_provisional, r.committed, r.pieces);
      }
    }
  }
}

// What a part's frames took back of the front they found held: over the
// stroke `path` in `steps` frames, the frames of a part with a front held
// (only those after the part met an older crack, with `met_only`), the
// pieces held and those taken back. The record holds the front's pieces
// between frames and nothing once the stroke has ended.
struct HeldFront {
  std::size_t frames = 0, held = 0, taken = 0;
  double share() const { return static_cast<double>(taken) / static_cast<double>(std::max<std::size_t>(held, 1)); }
};
HeldFront held_front_taken_back(const Mt& original, const Path& path, int steps, const std::string& where,
                                bool met_only) {
  HeldFront out;
  Mt mt = original;
  engine::TetBvh bvh(mt);
  Frontier frontier = Frontier::coarsest(mt);
  cut::StrokeSweep stroke;
  cut::TimeCriticalCutter cutter(checked_cutter());
  for (int k = 0; k <= steps + 1; ++k) {
    cut::BladePose pose = path(std::min(1.0, static_cast<double>(k) / steps));
    pose.engaged = k <= steps;
    const cut::PartRecord* before = cutter.part_record();
    const cut::MtChangeReport* front = before ? cutter.provisional_changes() : nullptr;
    const std::size_t held_before = front ? front->made_tets.size() : 0;
    const bool counted = held_before > 0 && (!met_only || before->met_old_crack());
    const cut::StrokeStep step = cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, std::span(&pose, 1));
    if (const cut::PartRecord* record = cutter.part_record()) {
      const cut::MtChangeReport* now = cutter.provisional_changes();
      EXPECT_EQ(record->num_held(), now ? now->made_tets.size() : 0u) << where << " step " << k;
      if (counted && record == before) {  // a frame of the part that found a front held
        ++out.frames;
        out.held += held_before;
        out.taken += step.retraction ? step.retraction->killed.size() : 0;
      }
    }
    if (step.recut) {
      const auto report = mt.validate();
      EXPECT_TRUE(report.ok()) << where << " step " << k << ": " << report.summary();
      if (!report.ok()) break;
    }
  }
  EXPECT_EQ(cutter.part_record(), nullptr) << where;
  EXPECT_FALSE(cutter.provisional_held()) << where;
  EXPECT_EQ(cutter.cuts_refused(), 0u) << where;
  std::printf("[ report   ] %s: %zu frames, %zu of %zu held front pieces taken back (%.1f%%)\n", where.c_str(),
              out.frames, out.taken, out.held, 100.0 * out.share());
  return out;
}

// From frame to frame the blade moves less than a tet, and most of the
// front is split as it was (TimeCriticalCutter::recut keeps those splits,
// held in the record): over a straight part in 240 frames, through the
// object and with the tip inside, a frame takes back under half of the
// pieces the front held (about 6 to 35% of the tets change configuration
// from frame to frame at 240 steps).
TEST(PartRecord, AFrameKeepsTheFrontSplitsItsGrownPolygonLeavesAsTheyWere) {
  for (const std::string name : {"ellipsoid", "liver", "box"}) {
    const Mt& original = cut_test_mt(name);
    for (const double depth : {0.6, 1.1}) {
      const std::string where = name + " depth " + std::to_string(depth);
      const engine::Aabb box = mt_box(original);
      const Path path = [&](double s) { return blade_at(box, s, depth, 0.15, Vec3(0.8, 0.55, 0)); };
      constexpr int kSteps = 240;
      const HeldFront h = held_front_taken_back(original, path, kSteps, where, false);
      EXPECT_GT(h.frames, kSteps / 2u) << where;
      EXPECT_LT(2 * h.taken, h.held) << where << ": " << h.taken << " of " << h.held << " held pieces taken back";
    }
  }
}

// An L: the blade drawn along x to the middle of the box, then along y
// (a sharp turn: the second part crosses the first one's crack), at s in
// [0, 1], down through the box or to `depth` of its height.
cut::BladePose l_blade_at(const engine::Aabb& box, double s, double depth) {
  const Vec3 size = box.hi - box.lo;
  const Vec3 start = box.center() - Vec3(0.75 * size.x(), 0.13 * size.y(), 0);
  const Vec3 corner = box.center() + Vec3(0.07 * size.x(), -0.13 * size.y(), 0);
  const Vec3 end = corner + Vec3(0, 0.8 * size.y(), 0);
  const Vec3 foot = s < 0.5 ? start + (corner - start) * (2 * s) : corner + (end - corner) * (2 * s - 1);
  return {Vec3(foot.x(), foot.y(), box.hi.z() + 0.05 * size.z()), Vec3(foot.x(), foot.y(), box.hi.z() - depth * size.z()),
          true};
}

// The part after a sharp turn meets the first part's crack, and still
// commits what it crosses completely, the pieces of that crack among them:
// what its commits owe the fragments there (the first crack's tets are
// split at every resolution around the junction) is in the record's ledger
// (fragment_ledger.h), and each frame's front pays it back exactly, where
// without the ledger the front alone leaves fragments out of balance. So
// the second part's frames re-split only its front, as a straight part's
// do, and the L ends in the same pieces as cut at once. MT, BVH, frontier
// and cutter (the record and its ledger) are validated after every frame.
TEST(PartRecord, APartAfterASharpTurnCommitsWhereItMeetsTheFirstCrack) {
  for (const std::string name : {"ellipsoid", "liver", "box"}) {
    const Mt& original = cut_test_mt(name);
    for (const double depth : {0.6, 1.1}) {
      for (const int steps : {60, 200}) {
        const std::string where = name + " L, depth " + std::to_string(depth) + ", " + std::to_string(steps) + " steps";
        const engine::Aabb box = mt_box(original);
        const Path path = [&](double s) { return l_blade_at(box, s, depth); };
        std::size_t committed = 0, most_front = 0, owing_fronts = 0, frames = 0, met = 0;
        const PartRun r = cut_part(original, path, steps, where, [&](int k, const Mt& mt,
                                                                     const cut::TimeCriticalCutter& cutter) {
          const cut::PartRecord* record = cutter.part_record();
          const cut::MtChangeReport* front = cutter.provisional_changes();
          if (2 * k <= steps + 2 || !record || !front) return;  // the second part's frames
          ++frames;
          committed = std::max(committed, record->num_owned());
          most_front = std::max(most_front, front->replaced.size());
          if (!record->met_old_crack()) return;
          ++met;
          const cut::FragmentLedger& owed = record->owed();
          const std::vector<engine::FragId> skip = cut::decomposed_fragments(*front);
          EXPECT_TRUE(owed.unbalanced_with(mt, *front, skip).empty()) << where << " step " << k;
          if (!owed.empty()) {
            ++owing_fronts;
            EXPECT_FALSE(cut::fragments_out_of_balance(mt, *front).empty())
                << where << " step " << k << ": the commits owed the fragments nothing the front paid";
          }
        });
        if (!r.valid) return;
        EXPECT_GT(frames, 0u) << where;
        // Where the turn lies in the tissue, the part after it crosses the
        // first crack (TimeCriticalCutter: the two cracks cross).
        const cut::BladePose turn = l_blade_at(box, 0.5, depth);
        const engine::TetBvh original_bvh(original);
        if (original_bvh.locate(original, 0.5 * (turn.base + turn.tip)).valid()) {
          EXPECT_GT(met, 0u) << where << ": the part after the turn never met the first crack";
          EXPECT_GT(owing_fronts, 0u) << where << ": no commit owed the fragments anything";
        }
        EXPECT_GT(committed, 0u) << where << ": the part after the turn committed nothing";
        EXPECT_LE(2 * most_front, committed) << where << ": a frame re-split " << most_front << " tets of "
                                             << committed;
        EXPECT_EQ(r.pieces, cut::find_pieces(cut_at_once(original, path, steps)).count) << where;
        std::printf("[ report   ] %s: after the turn, %zu of %zu frames met the first crack, front at most %zu tets, "
                    "%zu committed pieces, %zu pieces\n",
                    where.c_str(), met, frames, most_front, committed, r.pieces);
      }
    }
  }
}

// A part that has met an older crack keeps its front's splits too: its
// fronts are checked against what its commits owe, summed over the whole
// front (the splits kept and those made afresh, cut_guard.h), so a frame
// of the L's second part, after it crossed the first crack, takes back
// under half of the front it found held, as a straight part's frame does.
TEST(PartRecord, APartThatMetAnOlderCrackKeepsItsFrontToo) {
  for (const std::string name : {"ellipsoid", "box"}) {  // the liver's L turns outside it
    const Mt& original = cut_test_mt(name);
    for (const double depth : {0.6, 1.1}) {
      const std::string where = name + " L, depth " + std::to_string(depth);
      const engine::Aabb box = mt_box(original);
      const Path path = [&](double s) { return l_blade_at(box, s, depth); };
      constexpr int kSteps = 240;
      const HeldFront h = held_front_taken_back(original, path, kSteps, where, true);
      EXPECT_GT(h.frames, kSteps / 4u) << where << ": the part after the turn met the first crack late or never";
      EXPECT_LT(2 * h.taken, h.held) << where << ": " << h.taken << " of " << h.held << " held pieces taken back";
    }
  }
}

// A vertical polygon from above the top of `box` down to the middle of its
// height, half across, slightly oblique; `depth` (1 the middle) moves its
// bottom down: a commit of it leaves its outline's tets whole.
cut::CutPolygon half_across(const engine::Aabb& box, double depth = 1.0) {
  const Vec3 size = box.hi - box.lo, c = box.center();
  const double bottom = box.hi.z() - depth * (box.hi.z() - c.z());
  return cut::CutPolygon::from_points(
      {Vec3(c.x() - 0.6 * size.x(), c.y() + 0.013 * size.y(), box.hi.z() + 0.1 * size.z()),
       Vec3(c.x() + 0.1 * size.x(), c.y() + 0.017 * size.y(), box.hi.z() + 0.1 * size.z()),
       Vec3(c.x() + 0.1 * size.x(), c.y() + 0.017 * size.y(), bottom),
       Vec3(c.x() - 0.6 * size.x(), c.y() + 0.013 * size.y(), bottom)});
}

// A part that meets an older crack only after some commits owes the
// fragments, from then on, exactly what a part that had met one before its
// first commit owes: the fragments its commits changed, entered by what
// their tets sum to, hold what the commits added up commit by commit.
TEST(PartRecord, APartMeetingAnOlderCrackLateOwesWhatItsCommitsAddUpTo) {
  for (const std::string name : {"ellipsoid", "box", "liver"}) {
    Mt mt = cut_test_mt(name);
    engine::TetBvh bvh(mt);
    const engine::Aabb box = mt_box(mt);
    cut::PartRecord early(half_across(box)), late(half_across(box));
    early.meet_old_crack(mt, nullptr);  // before any commit: every commit is added to its ledger
    std::size_t commits = 0;
    for (const double depth : {0.6, 1.0, 1.4}) {
      cut::CutMtOptions options;
      options.def.record = &early;
      options.def.select = cut::CutSelect::kComplete;
      const cut::MtChangeReport commit = cut::cut_mt(mt, bvh, half_across(box, depth), {}, options);
      early.add(mt, commit);
      late.add(mt, commit);
      commits += !commit.made_tets.empty();  // (the MT conforms again once a front splits the outline's tets)
      EXPECT_TRUE(early.validate(mt).ok()) << name << ": " << early.validate(mt).summary();
      EXPECT_TRUE(late.validate(mt).ok()) << name << ": " << late.validate(mt).summary();
      EXPECT_TRUE(late.owed().empty()) << name << ": a ledger before the part met an older crack";
    }
    ASSERT_GE(commits, 2u) << name << ": the polygons committed nothing twice; the test tests nothing";
    ASSERT_FALSE(early.owed().empty()) << name << ": the commits owe the fragments nothing; the test tests nothing";
    late.meet_old_crack(mt, nullptr);
    EXPECT_TRUE(late.met_old_crack());
    EXPECT_EQ(late.owed().size(), early.owed().size()) << name;
    EXPECT_TRUE(late.owed() == early.owed()) << name;
    EXPECT_TRUE(late.validate(mt).ok()) << name << ": " << late.validate(mt).summary();
  }
}

// A commit taken back leaves the record as it was before it: no piece or
// point of it, and the ledger and the front it had.
TEST(PartRecord, ACommitTakenBackLeavesTheRecordAsBefore) {
  const Mt& original = cut_test_mt("ellipsoid");
  Mt mt = original;
  engine::TetBvh bvh(mt);
  const engine::Aabb box = mt_box(mt);
  // Its outline passes through the tissue (a front stays whole).
  const cut::CutPolygon polygon = half_across(box);
  cut::PartRecord record(polygon);
  const std::optional<engine::Aabb> front_before = engine::Aabb{box.lo, box.center()};
  record.set_front(front_before);
  const cut::PartRecord::Before before = record.before_commit();
  cut::CutMtOptions options;
  options.def.record = &record;
  options.def.select = cut::CutSelect::kComplete;
  const cut::MtChangeReport commit = cut::cut_mt(mt, bvh, polygon, {}, options);
  ASSERT_GT(commit.made_tets.size(), 0u);
  record.add(mt, commit);
  record.set_front(engine::Aabb{box.center(), box.hi});
  record.meet_old_crack(mt, nullptr);  // as the frame's front would, splitting a piece of an older crack
  ASSERT_GT(record.num_owned(), 0u);
  ASSERT_FALSE(record.committed_points().empty());
  ASSERT_FALSE(record.owed().empty()) << "the commit owes the fragments nothing: it tests nothing";
  EXPECT_TRUE(record.validate(mt).ok()) << record.validate(mt).summary();
  record.take_back(&commit, before);
  EXPECT_EQ(record.num_owned(), 0u);
  EXPECT_TRUE(record.committed_points().empty());
  EXPECT_TRUE(record.owed().empty());
  EXPECT_FALSE(record.met_old_crack());
  record.meet_old_crack(mt, nullptr);  // nothing committed: nothing owed
  EXPECT_TRUE(record.owed().empty());
  ASSERT_TRUE(record.front().has_value());
  EXPECT_EQ(record.front()->lo, front_before->lo);
  EXPECT_EQ(record.front()->hi, front_before->hi);
  for (TetId t : commit.made_tets) EXPECT_FALSE(record.owns(t));
  for (const cut::MadeVertex& m : commit.made_vertices) EXPECT_FALSE(record.made(m.id));
}

// A part's polygon only grows (TimeCriticalCutter::on_part_plane): a
// frame whose polygon lies on the part's plane but covers less than the
// last one (in the World, a sweep not carried to rest space after frames
// that were) keeps what the last one covered, so the part ends as the one
// cut of its largest polygon. Each frame's MT, index, frontier and cutter
// are valid (a part that shrank left whole the tets beside its committed
// pieces that only its first frame's outline crossed).
TEST(PartRecord, APolygonOfThePartsPlaneCoveringLessKeepsWhatTheLastOneCovered) {
  for (const std::string name : {"ellipsoid", "box"}) {
    const Mt& original = cut_test_mt(name);
    const engine::Aabb box = mt_box(original);
    const Vec3 size = box.hi - box.lo;
    const cut::CutPolygon wide = half_across(box);  // its leading edge inside the tissue
    std::vector<Vec3> corners = wide.corners();
    for (Vec3& x : corners) x.x() = std::min(x.x(), box.center().x() - 0.2 * size.x());
    const cut::CutPolygon narrow = cut::CutPolygon::on_plane_of(wide, corners);
    ASSERT_TRUE(narrow.same_plane(wide));
    // `frames` then the stroke's end: as a part that ended with the
    // polygon `ending` (a turn or the blade out), or none (the stroke ended).
    const auto stroke = [&](const std::vector<cut::CutPolygon>& frames,
                            const std::optional<cut::CutPolygon>& ending = std::nullopt) {
      Mt mt = original;
      engine::TetBvh bvh(mt);
      Frontier frontier = Frontier::coarsest(mt);
      cut::TimeCriticalCutter cutter(checked_cutter());
      for (std::size_t k = 0; k <= frames.size(); ++k) {
        const std::optional<cut::CutPolygon> current =
            k < frames.size() ? std::optional<cut::CutPolygon>(frames[k]) : std::nullopt;
        const std::uint8_t turned_back = 0;
        const bool ends = !current && ending;
        if (const auto taken = cutter.recut(mt, bvh, ends ? std::span(&*ending, 1) : std::span<const cut::CutPolygon>(),
                                            ends ? std::span(&turned_back, 1) : std::span<const std::uint8_t>(),
                                            current, current.has_value()))
          cut::follow_retraction(mt, frontier, *taken);
        const cut::TimeCriticalCutter::RunResult run = cutter.run(mt, bvh, frontier, cut::CutBudget::unlimited());
        cut::follow_cut(mt, frontier, run.changes);
        EXPECT_FALSE(run.refused.has_value()) << name << " frame " << k;
        for (const auto& report : {mt.validate(), bvh.validate(mt), engine::validate_frontier(mt, frontier),
                                   cutter.validate(mt)})
          EXPECT_TRUE(report.ok()) << name << " frame " << k << ": " << report.summary();
      }
      EXPECT_EQ(cutter.part_record(), nullptr) << name;
      return mt;
    };
    const Mt once = stroke({wide});
    const Mt shrunk = stroke({wide, narrow});
    // The hull of the two polygons is the wide one, its corners projected
    // again: the same cut, up to the rounding of the points its outline
    // makes.
    ASSERT_LT(stroke({narrow}).num_live_tets(), once.num_live_tets()) << name << ": the narrow polygon cuts as much";
    EXPECT_EQ(shrunk.num_live_tets(), once.num_live_tets()) << name << ": the part lost what its first frame covered";
    EXPECT_EQ(cut::find_pieces(shrunk).count, cut::find_pieces(once).count) << name;
    // The part's end given the narrow polygon keeps the wide one's too.
    const Mt ended_narrow = stroke({wide}, narrow);
    EXPECT_EQ(ended_narrow.num_live_tets(), once.num_live_tets()) << name << ": the part's end lost what it covered";
    EXPECT_EQ(cut::find_pieces(ended_narrow).count, cut::find_pieces(once).count) << name;
  }
}

}  // namespace
}  // namespace mtcut::test
