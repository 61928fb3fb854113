#pragma once
// What one frame of a scalpel stroke costs the MT cutter (`mtcut bench
// table1` reports it beside Table 1): the per-frame target is for a
// cut of tens to a few hundred tets, the quad a blade sweeps in one frame.
//
// Why a dashed stroke. Two consecutive sweeps of one stroke share the blade
// segment between them, and cutting the second through the points the first
// made leaves the MT invalid at some resolution (the junction defect,
// stroke_sweep.h and tests/cut/mt/scalpel_steps_test.cpp): the World merges a
// stroke's sweeps into one polygon per straight part instead. So the bench
// cuts one frame's quad every `stride` frames along the stroke, in order, on
// one MT: each step a frame-sized cut on an MT that earlier steps have cut
// (and grown), sharing no segment with the last. Its figures are the
// latency of one frame-sized cut, including the first step's growth of the
// MT's arrays, not a stroke cut frame by frame.

#include <cstddef>

#include "engine/mt/mt.h"

namespace mtcut::cut {

struct FrameStepDef {
  int steps = 40;              // frames cut along the stroke
  int runs = 3;                // timed strokes, each on a fresh copy of the MT (median per step)
  double blade_depth = 0.35;   // of the model's height, from above its top
  double sweep_width = 0.008;  // one frame's advance, fraction of the model's length
  double stride = 0.0225;      // advance from one cut frame to the next, fraction of the model's length
};

struct FrameStepResult {
  std::size_t steps = 0;
  // Tets replaced or relabelled at every resolution, per step: nearest-rank
  // median (a step's count) and max over the steps; likewise new tets.
  std::size_t split_tets_median = 0, split_tets_max = 0;
  std::size_t new_tets_median = 0;
  // Find + split + DAG update of one step (its median over runs), over the steps.
  double ms_median = 0, ms_p90 = 0, ms_max = 0;
};

// `after`, when given, receives the MT the last stroke left (tests validate it).
FrameStepResult run_frame_steps(const engine::Mt& mt, const FrameStepDef& def = {}, engine::Mt* after = nullptr);

}  // namespace mtcut::cut
