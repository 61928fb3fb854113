#pragma once
// Scenario files (TOML): what `mtcut run` and `mtcut view` play. A scenario
// names the organ, the MT options, the material, the fixed region, the LOD,
// the cutter budget, the integrator, the time step, the scalpel path and the
// outputs; each section fills a definition struct (sim/world_def.h). Every
// unknown key or wrong type is an error with file:line.

#include <string>

#include "engine/mesh_loader.h"
#include "sim/scalpel.h"
#include "sim/world_def.h"

namespace mtcut::app {

struct ScenarioDef {
  std::string file;             // the scenario's path
  std::string mesh;             // builtin:NAME or a path (resolved against the scenario's folder)
  engine::MeshLoadDef mesh_load;
  sim::WorldDef world;
  sim::ScalpelPath scalpel;
  int frames = 120;
  std::string summary_path;     // summary.json ("" = none), relative to the working directory
  std::string frames_path;      // per-frame CSV ("" = none)
};

// Reads and checks a scenario. Throws InputError "file:line: what".
ScenarioDef load_scenario(const std::string& path);

}  // namespace mtcut::app
