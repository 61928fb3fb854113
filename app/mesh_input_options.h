#pragma once
// The mesh options every command that takes a mesh shares (`mtcut mesh`,
// `mtcut mt`, `mtcut cut`): --tets and --size of a builtin shape,
// --max-volume when meshing a surface, --units or --scale of a mesh file,
// --strict (no repair); the load every command that takes a mesh does; and
// the advice, in these options' terms, that an input's hint asks for.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "engine/mesh_loader.h"

namespace mtcut::app {

// The options a command's parse fills, applied by apply_mesh_input_options.
struct MeshInputOptions {
  std::vector<double> size;  // --size
  std::string units;         // --units
  double scale = 0;          // --scale (0 = not given)
};

// Adds --tets, --size, --max-volume, --units, --scale and --strict to `cmd`, filling `load` and `options`.
void add_mesh_input_options(CLI::App& cmd, engine::MeshLoadDef& load, MeshInputOptions& options);

// Sets load.builtin_size from --size and the file's unit from --units or
// --scale (each left as is when not given); throws InputError unless --size
// holds three extents and the unit is one of m, dm, cm, mm.
void apply_mesh_input_options(const MeshInputOptions& options, engine::MeshLoadDef& load);

// Reads a unit name into `load` (m, dm, cm, mm); throws InputError naming `where` otherwise.
void set_mesh_units(const std::string& units, const std::string& where, engine::MeshLoadDef& load);

// `line` (an InputError's message or a load's note) with the advice its
// hint asks for, in the terms of these options and of a scenario's [mesh]
// keys: "...; raise --max-volume, or [mesh] max_volume in a scenario".
// `line` as it is for no hint.
std::string add_advice(const std::string& line, const engine::InputHint& hint);

// engine::load_mesh for a command: while TetGen meshes for over a second,
// a progress line on stderr when it is a terminal ("mtcut: meshing NAME
// with TetGen: 3 s", rewritten in place and erased at the end); then the
// load's notes on stderr, one line each, with their advice.
engine::LoadedMesh load_input_mesh(const std::string& spec, engine::MeshLoadDef load);

}  // namespace mtcut::app
