#include "app/mesh_input_options.h"

#include "engine/input_error.h"

namespace mtcut::app {

void add_mesh_input_options(CLI::App& cmd, engine::MeshLoadDef& load, std::vector<double>& size) {
  cmd.add_option("--tets", load.builtin_tets, "target tet count of a builtin shape")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd.add_option("--size", size, "extents x,y,z of a builtin shape in metres")->delimiter(',');
  cmd.add_option("--max-volume", load.meshing.max_volume, "largest tet volume when meshing a surface (0 = none)")
      ->check(CLI::NonNegativeNumber);
}

void apply_builtin_size(const std::vector<double>& size, engine::MeshLoadDef& load) {
  if (size.empty()) return;
  if (size.size() != 3) throw engine::InputError("--size: give three extents x,y,z");
  load.builtin_size = engine::Vec3(size[0], size[1], size[2]);
}

}  // namespace mtcut::app
