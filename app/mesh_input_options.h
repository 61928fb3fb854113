#pragma once
// The mesh options every command that takes a mesh shares (`mtcut mesh`,
// `mtcut mt`, `mtcut cut`): --tets and --size of a builtin shape, and
// --max-volume when meshing a surface.

#include <CLI/CLI.hpp>
#include <vector>

#include "engine/mesh_loader.h"

namespace mtcut::app {

// Adds --tets, --size and --max-volume to `cmd`, filling `load` and `size`.
void add_mesh_input_options(CLI::App& cmd, engine::MeshLoadDef& load, std::vector<double>& size);

// Sets load.builtin_size from --size (left as is when --size was not given);
// throws InputError unless it holds three extents.
void apply_builtin_size(const std::vector<double>& size, engine::MeshLoadDef& load);

}  // namespace mtcut::app
