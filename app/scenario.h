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

// The tissue's surface as surface.obj and the viewer show it: the organ's
// finest surface and the finest faces of its cuts, carried by the simulated
// frontier (sim/finest_surface.h), or the simulated frontier's own surface
// (coarse away from the blade).
enum class SurfaceKind { kFinest, kFrontier };

struct ScenarioDef {
  std::string file;             // the scenario's path
  std::string mesh;             // builtin:NAME or a path (resolved against the scenario's folder)
  engine::MeshLoadDef mesh_load;
  sim::WorldDef world;
  sim::ScalpelPath scalpel;     // keyframes, or the samples of the trace
  std::string scalpel_trace;    // the replayed trace file ("" = keyframes), resolved against the scenario's folder
  int frames = 120;
  std::string summary_path;     // an extra copy of summary.json ("" = none), relative to the output folder
  std::string frames_path;      // per-frame CSV of every stage's figures ("" = none), relative to the output folder
  int snapshot_every = 0;       // a .vtu snapshot every this many frames (0 = none)
  SurfaceKind surface = SurfaceKind::kFinest;  // [output] surface = "finest" | "frontier"
};

// Reads and checks a scenario. Throws InputError "file:line: what".
ScenarioDef load_scenario(const std::string& path);

}  // namespace mtcut::app
