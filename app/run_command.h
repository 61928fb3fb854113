#pragma once
// `mtcut run [SCENARIO] [--frames N] [--out DIR] [--json] [--record TRACE]`:
// plays a scenario headless (the project's main job) and writes its outputs
// into DIR: metrics.csv, summary.json, .vtu snapshots with a .pvd
// collection, and the final deformed surface (surface.obj).

#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "app/run_hid.h"
#include "app/scenario.h"
#include "engine/mt/mt.h"
#include "sim/world.h"

namespace mtcut::app {

void register_run_command(CLI::App& app);

struct RunOptions {
  int frames_override = 0;  // 0: the scenario's
  bool progress = true;     // a progress bar on stderr when it is a terminal
  std::string out_dir;      // "" : out/<scenario file name without extension>
  std::string record_path;  // write every scalpel sample the World got here, at its time ("" = no)
  RunHidDef hid;            // the HID drives the scalpel instead of the scenario's path
};

struct RunResult {
  nlohmann::ordered_json summary;  // what summary.json holds
  bool interrupted = false;        // SIGINT stopped the run early
};

// Plays the scenario and writes its outputs. Throws InputError.
RunResult run_scenario(const ScenarioDef& scenario, const RunOptions& options);

// The organ's MT, built from the scenario's mesh (`mtcut run` and `mtcut
// view`). Throws InputError for a bad or invalid mesh.
engine::Mt build_organ_mt(const ScenarioDef& scenario);

// The World on the scenario's organ `mt` (`mtcut run` and `mtcut view`). An
// InputError the World raises about the organ (a body beyond what the spring
// model holds) is said of the scenario's mesh, as the loader's errors are.
std::unique_ptr<sim::World> start_organ_world(const ScenarioDef& scenario, engine::Mt mt, const sim::WorldDef& def,
                                              const std::optional<sim::ScalpelPose>& blade);

// The scenario `mtcut run` plays without one: <config dir>/scenarios/default.toml.
std::string default_scenario_path();

// The output folder by default: out/<scenario file name without extension>.
std::string default_out_dir(const std::string& scenario_path);

}  // namespace mtcut::app
