#include "cut/mt/stroke_cutter.h"

namespace mtcut::cut {

StrokeStep cut_stroke_step(StrokeSweep& stroke, TimeCriticalCutter& cutter, Mt& mt, TetBvh& bvh,
                           Frontier& frontier, std::span<const BladePose> poses, const CutBudget& budget) {
  StrokeStep out;
  const StrokeAdvance advance = stroke.advance(poses);
  out.recut = advance.moved || !advance.ended.empty();
  if (out.recut) {
    out.retraction = cutter.recut(mt, bvh, advance.ended, advance.turned_back, stroke.current(), stroke.plane_fixed());
    if (out.retraction) follow_retraction(mt, frontier, *out.retraction);
  }
  if (out.recut || cutter.frozen()) {
    out.run = cutter.run(mt, bvh, frontier, budget);
    follow_cut(mt, frontier, out.run.changes);
    if (out.run.refused) follow_retraction(mt, frontier, *out.run.refused);
    // A refusal ends the cutter's call: the cuts queued behind it run now.
    while (out.run.refused && cutter.frozen()) {
      TimeCriticalCutter::RunResult more = cutter.run(mt, bvh, frontier, budget);
      follow_cut(mt, frontier, more.changes);
      if (more.refused) follow_retraction(mt, frontier, *more.refused);
      out.run.changes.append(more.changes);
      out.run.cuts_finished += more.cuts_finished;
      if (more.pieces) out.run.pieces = std::move(more.pieces);
      out.run.refused = std::move(more.refused);
    }
  }
  if ((out.reclaimed = cutter.reclaim(mt, bvh))) frontier = Frontier::from_fragments(mt, frontier.fragments());
  return out;
}

}  // namespace mtcut::cut
