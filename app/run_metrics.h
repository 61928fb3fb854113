#pragma once
// The per-frame figures of `mtcut run` and the CSV files that hold them:
// metrics.csv (one row per frame, the columns of issue 7) and, when a
// scenario asks for it ([output] frames), the World's stage figures.

#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "sim/world.h"

namespace mtcut::app {

// One frame: the World's metrics plus what the run derives from its state.
struct MetricsRow {
  sim::FrameMetrics frame;
  std::size_t cut_jobs_pending = 0;  // cut work queued after the frame
  double kinetic_energy = 0;         // J, 1/2 sum m |v|^2 over the particles
  int pieces = 1;                    // the World's pieces (World::pieces())
};

double kinetic_energy(const sim::SpringModel& model, const sim::SpringState& state);

// The row of the frame the World has just stepped.
MetricsRow record_frame(const sim::World& world);

// metrics.csv, atomically: a header line, then one row per frame.
void write_metrics_csv(const std::string& path, std::span<const MetricsRow> rows);

// The World's stage figures per frame (springs, LOD changes, CG
// iterations, refused steps), atomically.
void write_stage_csv(const std::string& path, std::span<const MetricsRow> rows);

}  // namespace mtcut::app
