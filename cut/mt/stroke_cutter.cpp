#include "cut/mt/stroke_cutter.h"

namespace mtcut::cut {

StrokeStep cut_stroke_step(StrokeSweep& stroke, TimeCriticalCutter& cutter, Mt& mt, TetBvh& bvh,
                           Frontier& frontier, std::span<const BladePose> poses, const CutBudget& budget) {
  StrokeStep out;
  const StrokeAdvance advance = stroke.advance(poses);
  out.recut = advance.moved || !advance.ended.empty();
  if (out.recut) {
    out.retraction = cutter.recut(mt, bvh, advance.ended, stroke.current());
    if (out.retraction) frontier = retract_frontier(mt, frontier, *out.retraction);
  }
  if (out.recut || cutter.frozen()) {
    out.run = cutter.run(mt, bvh, frontier, budget);
    follow_cut(mt, frontier, out.run.changes);
    if (out.run.refused) frontier = retract_frontier(mt, frontier, *out.run.refused);
  }
  return out;
}

}  // namespace mtcut::cut
