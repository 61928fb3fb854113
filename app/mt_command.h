#pragma once
// `mtcut mt IN | --preset NAME [--json]`: builds the Multi-Tessellation of a
// mesh, validates it, and prints its figures.

#include <CLI/CLI.hpp>
#include <string>

#include "engine/mesh_loader.h"
#include "engine/mt/mt.h"
#include "engine/mt/mt_builder.h"
#include "engine/mt/mt_presets.h"

namespace mtcut::app {

void register_mt_command(CLI::App& app);

// The preset named `name` (`--preset`); throws InputError for an unknown one.
engine::MtPreset require_mt_preset(const std::string& name);

// An MT and what it took to make it.
struct BuiltMt {
  engine::Mt mt;
  engine::MtBuildReport report;
  double mesh_seconds = 0;   // loading or meshing the fine mesh
  double build_seconds = 0;  // the collapses
};

// Loads `spec` (as `mtcut mesh` does), checks it is a valid tet mesh and
// builds its MT. Throws InputError naming `spec`.
BuiltMt build_mt_from(const std::string& spec, const engine::MeshLoadDef& load, const engine::MtBuildOptions& build);

// The MT of a preset, as `mtcut mt --preset NAME` builds it.
BuiltMt build_preset_mt(const std::string& name);

}  // namespace mtcut::app
