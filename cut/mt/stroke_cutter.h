#pragma once
// A scalpel stroke cut progressively, with no simulation around it: a
// frame's blade poses go through the stroke's sweep (cut/stroke_sweep.h);
// when a straight part ended or the part in progress moved, the
// time-critical cutter takes the last provisional cut back and queues the
// ended parts for good and the part in progress provisionally
// (TimeCriticalCutter::recut), then runs within the budget, and the
// frontier follows (through a refused cut's retraction too). When the
// cutter has no cut pending, the slots retracted cuts left are reclaimed
// once they outnumber the live tets (TimeCriticalCutter::reclaim), and the
// frontier follows. The
// World does the same with the polygons carried to rest space and the
// simulated state carried over (sim/world.h); the tests and `mtcut bench
// stroke` cut with this.

#include <optional>
#include <span>

#include "cut/mt/time_critical_cutter.h"
#include "cut/stroke_sweep.h"

namespace mtcut::cut {

struct StrokeStep {
  bool recut = false;                     // the MT changed (or would have, with nothing to cut)
  std::optional<CutRetraction> retraction;  // the provisional cut taken back
  TimeCriticalCutter::RunResult run;      // what the cutter did
  // The MT compacted at the end of the step: ids held from before (the
  // run's report and the retraction among them) map through it.
  std::optional<engine::Mt::Compaction> reclaimed;
};

// One frame of a stroke over `mt` (rest space), `bvh` and `frontier` in step with it.
StrokeStep cut_stroke_step(StrokeSweep& stroke, TimeCriticalCutter& cutter, Mt& mt, TetBvh& bvh,
                           Frontier& frontier, std::span<const BladePose> poses,
                           const CutBudget& budget = CutBudget::unlimited());

}  // namespace mtcut::cut
