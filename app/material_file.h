#pragma once
// Material presets (config/materials/NAME.toml) and material files.

#include <string>

#include "app/toml_table.h"
#include "sim/material.h"

namespace mtcut::app {

// The folder of config/: $MTCUT_CONFIG_DIR when set, else the source tree's.
std::string config_dir();

// `name_or_path` is a preset name (liver, kidney, stiff_test) or a .toml path.
// Throws InputError "file:line: ..." for unknown keys, wrong types, or
// non-physical values (density and Young's modulus must be positive).
sim::MaterialDef load_material(const std::string& name_or_path);

// Fills `material` from the keys of `table` (shared with scenario files).
void read_material(TomlTable& table, sim::MaterialDef& material);

}  // namespace mtcut::app
