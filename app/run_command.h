#pragma once
// `mtcut run SCENARIO [--frames N] [--summary FILE] [--json]`: plays a
// scenario headless and reports its figures (the project's main job).

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/scenario.h"

namespace mtcut::app {

void register_run_command(CLI::App& app);

struct RunOptions {
  int frames_override = 0;  // 0: the scenario's
  bool progress = true;     // a progress line on stderr about once a second
};

// Plays the scenario; returns the summary (also what summary.json holds).
nlohmann::ordered_json run_scenario(const ScenarioDef& scenario, const RunOptions& options);

}  // namespace mtcut::app
