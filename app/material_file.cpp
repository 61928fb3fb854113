#include "app/material_file.h"

#include <cstdlib>
#include <filesystem>

#include "engine/input_error.h"

namespace mtcut::app {

std::string config_dir() {
  if (const char* dir = std::getenv("MTCUT_CONFIG_DIR"); dir && *dir) return dir;
  return MTCUT_CONFIG_DIR;
}

void read_material(TomlTable& table, sim::MaterialDef& material) {
  (void)table.string("name");  // informative only
  const toml::node* at = table.node("density");
  if (at) {
    if (!at->is_number() || !(at->value<double>().value() > 0)) table.fail(at, "'density' must be a positive number");
    material.density = at->value<double>().value();
  }
  at = table.node("youngs_modulus");
  if (at) {
    if (!at->is_number() || !(at->value<double>().value() > 0))
      table.fail(at, "'youngs_modulus' must be a positive number");
    material.youngs_modulus = at->value<double>().value();
  }
  for (const auto& [key, field] : {std::pair{"stiffness_damping", &material.stiffness_damping},
                                   std::pair{"mass_damping", &material.mass_damping},
                                   std::pair{"volume_stiffness", &material.volume_stiffness}}) {
    at = table.node(key);
    if (!at) continue;
    if (!at->is_number() || at->value<double>().value() < 0)
      table.fail(at, std::string("'") + key + "' must be a number >= 0");
    *field = at->value<double>().value();
  }
}

sim::MaterialDef load_material(const std::string& name_or_path) {
  std::string path = name_or_path;
  if (std::filesystem::path(name_or_path).extension() != ".toml") {
    path = config_dir() + "/materials/" + name_or_path + ".toml";
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
      throw engine::InputError("material '" + name_or_path + "': no such preset (see " + config_dir() + "/materials/)");
  }
  const toml::table root = parse_toml_file(path);
  TomlTable table(root, path);
  sim::MaterialDef material;
  read_material(table, material);
  table.finish();
  return material;
}

}  // namespace mtcut::app
