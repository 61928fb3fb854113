// A stroke's part cut progressively with a record (cut/mt/part_record.h):
// each frame commits the tets its polygon crosses completely and splits
// only its front provisionally, so a frame's work follows the blade, not the
// part; the record stays consistent with the MT after every frame.
#include "cut/mt/part_record.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cut/mt/mt_pieces.h"
#include "cut/mt/stroke_cutter.h"
#include "tests/cut/mt/mt_cut_test_util.h"

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

// The stroke in `steps` frames of a pose each, then one that disengages;
// MT, BVH, frontier, cutter (and with it the part's record) validated after
// every frame.
PartRun cut_part(const Mt& original, int steps, double depth, double lean, const Vec3& direction,
                 const std::string& where) {
  PartRun out{original};
  Mt& mt = out.mt;
  engine::TetBvh bvh(mt);
  Frontier frontier = Frontier::coarsest(mt);
  cut::StrokeSweep stroke;
  cut::TimeCriticalCutter cutter;
  const engine::Aabb box = mt_box(mt);
  for (int k = 0; k <= steps + 1 && out.valid; ++k) {
    cut::BladePose pose = blade_at(box, std::min(1.0, static_cast<double>(k) / steps), depth, lean, direction);
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
  }
  EXPECT_FALSE(cutter.provisional_held()) << where;
  EXPECT_EQ(cutter.part_record(), nullptr) << where << ": the part's record outlived the stroke";
  EXPECT_EQ(cutter.cuts_refused(), 0u) << where;
  out.pieces = cut::find_pieces(mt).count;
  return out;
}

// The same stroke with all its poses in one frame: one polygon per part.
Mt cut_at_once(const Mt& original, int steps, double depth, double lean, const Vec3& direction) {
  Mt mt = original;
  engine::TetBvh bvh(mt);
  Frontier frontier = Frontier::coarsest(mt);
  cut::StrokeSweep stroke;
  cut::TimeCriticalCutter cutter;
  const engine::Aabb box = mt_box(mt);
  std::vector<cut::BladePose> poses;
  for (int k = 0; k <= steps; ++k) poses.push_back(blade_at(box, static_cast<double>(k) / steps, depth, lean, direction));
  poses.push_back(poses.back());
  poses.back().engaged = false;
  cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, poses);
  return mt;
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
        const PartRun r = cut_part(original, steps, depth, lean, direction, where);
        if (!r.valid) return;
        EXPECT_GT(r.committed, 0u) << where << ": nothing was committed";
        EXPECT_LE(4 * r.most_provisional, r.committed) << where << ": a frame re-split "
                                                       << r.most_provisional << " tets of " << r.committed;
        EXPECT_TRUE(canonical_mt(r.mt) == canonical_mt(cut_at_once(original, steps, depth, lean, direction)))
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

}  // namespace
}  // namespace mtcut::test
