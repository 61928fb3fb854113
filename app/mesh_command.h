#pragma once
// `mtcut mesh IN [-o OUT] [--max-volume V] [--quality Q] [--json]`: meshes a
// surface or a builtin shape, or reads a tet mesh; validates it; writes OUT;
// prints its statistics.

#include <CLI/CLI.hpp>

#include "engine/mesh_stats.h"

namespace mtcut::app {

void register_mesh_command(CLI::App& app);

// Writes a tet mesh by extension: .vtu (with per-tet quality), .node/.ele,
// or the boundary surface as .obj/.off/.stl/.ply. Throws InputError.
void write_mesh_output(const engine::TetMesh& mesh, const std::string& path);

}  // namespace mtcut::app
