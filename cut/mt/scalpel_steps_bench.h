#pragma once
// The per-frame cost of cutting (`mtcut bench table1`'s "scalpel_steps"): a
// blade drawn across the MT in many small steps, as a 1 kHz haptic loop or a
// frame-by-frame stroke would feed the cutter, each step one cut_mt of the
// quad the blade swept since the last step (progressive cutting: each quad
// continues the incision the previous ones left). Table 1 measures one big
// cut; this measures the small ones a real-time loop is made of.

#include <cstddef>
#include <vector>

#include "engine/mt/mt.h"

namespace mtcut::cut {

struct ScalpelStepsDef {
  int steps = 100;      // across the model's x extent (and a little beyond each end)
  double depth = 0.6;   // of the model's z extent, from its top
  int runs = 5;         // each on a fresh copy of the MT; times of every step of every run are pooled
};

struct ScalpelStepsResult {
  int steps = 0;
  double step_length = 0;               // model units
  std::size_t median_split_tets = 0;    // tets replaced per step that cut anything (every resolution)
  std::size_t max_split_tets = 0;
  std::size_t total_split_tets = 0;     // one run: tets split or moved onto a split vertex's copy
  std::size_t total_relabeled_tets = 0; // one run: of those, moved only
  std::size_t total_new_tets = 0;       // one run
  double median_ms = 0, p95_ms = 0, max_ms = 0;  // whole cut_mt call per step that cut anything
  std::size_t index_rebuilds = 0;       // steps whose cut_mt rebuilt the tet index first (one run)
};

ScalpelStepsResult run_scalpel_steps(const engine::Mt& mt, const ScalpelStepsDef& def = {});

}  // namespace mtcut::cut
