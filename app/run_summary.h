#pragma once
// The summary of a `mtcut run`: summary.json (the figures of issue 7 at the
// top level, then the detail: per-stage time distributions, frontier sizes,
// validity) and the one-paragraph account printed for people.

#include <nlohmann/json.hpp>
#include <ostream>
#include <span>

#include "app/run_metrics.h"
#include "app/scenario.h"
#include "engine/mt/mt_stats.h"
#include "sim/world.h"

namespace mtcut::app {

// What the run loop knows beyond the World's state.
struct RunRecord {
  engine::MtStats mt_stats;             // of the MT as built, before any cut
  double setup_seconds = 0;             // meshing and building the MT
  double run_seconds = 0;               // the frame loop
  int frames_requested = 0;
  bool interrupted = false;             // stopped early by SIGINT
  std::span<const MetricsRow> rows;     // (frames done)
};

// Builds the summary; validates the World (MT, frontier, springs).
nlohmann::ordered_json summarize_run(const ScenarioDef& scenario, const RunRecord& record, const sim::World& world);

// The summary as one paragraph (reads the keys summarize_run writes, and
// "outputs" when present).
void print_run_paragraph(std::ostream& out, const nlohmann::ordered_json& summary);

}  // namespace mtcut::app
