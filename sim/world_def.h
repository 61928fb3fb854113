#pragma once
// Everything that defines a World, with defaults; scenario files (app/) only
// fill these structs.

#include "engine/mt/mt_builder.h"
#include "sim/environment.h"
#include "sim/fixed_region.h"
#include "sim/material.h"
#include "sim/stepper.h"

namespace mtcut::sim {

// The level of detail around the scalpel: tets may have error up to
// near_error within near_radius of the blade (base to tip), growing linearly to
// far_error at far_radius and beyond (metres of error, as the MT's).
struct LodDef {
  bool enabled = true;
  double near_radius = 0.02;
  double near_error = 0.0;   // 0: the finest tets near the blade
  double far_radius = 0.08;
  double far_error = 1.0;    // large: the coarsest tets far away
  // Build the springs of a frontier move on another core during the
  // frames' physics, taking them build_frames later, and those of a cut
  // during the LOD stage (sim/model_build.h, World); false builds them
  // inline at the same points: the same bits, slower.
  bool background_build = true;
  // Update the springs by the tets a move or a cut changed
  // (sim/spring_model_update.h) instead of building them from every tet:
  // the same bits in a fraction of the time; false is for comparing.
  bool update_springs = true;
  // The frames a move's springs have to build: the move the blade asks for
  // at frame k is taken at frame k + build_frames (sooner when a cut comes)
  // and the next one is decided then. Why 2: a 26k-tet frontier's build
  // (~5-7 ms on a core that shares its cache with the physics) outlasted
  // one liver frame's physics (~3.5 ms), so with 1 the frame taking a move
  // waited out the rest (lod_ms p95 ~3.9 ms). Since springs are updated
  // (update_springs) 1 waits little, but moves twice as often: liver lod_ms
  // mean 0.65-0.78 ms against 0.48-0.55 with 2, frames alike. The price of
  // 2: the frontier follows the blade two frames late, at most every other
  // frame.
  int build_frames = 2;
};

// How much cutting a frame may do: in tets (reproducible) or milliseconds.
struct CutBudgetDef {
  enum class Unit { kTets, kMilliseconds };
  Unit unit = Unit::kTets;
  double amount = 1e9;  // per frame; large = unlimited
};

struct WorldDef {
  engine::MtBuildOptions mt;
  MaterialDef material;
  FixedRegion fixed;
  Environment environment;
  IntegratorDef integrator;
  LodDef lod;
  CutBudgetDef cut_budget;
  double dt = 1.0 / 60.0;        // s per frame
  double tool_radius = 0.002;    // m; the disengaged blade pushes within it (0: never)
};

}  // namespace mtcut::sim
