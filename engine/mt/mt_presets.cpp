#include "engine/mt/mt_presets.h"

#include <limits>

namespace mtcut::engine {

std::optional<MtPreset> find_mt_preset(const std::string& name) {
  if (name == "paper") {
    MtPreset preset;
    preset.name = name;
    preset.mesh_spec = "builtin:ellipsoid";
    preset.mesh.builtin_tets = 12500;
    preset.build.preserve_boundary = false;
    // The paper's MT: the surface moves by the collapses' errors alone.
    preset.build.max_surface_deviation = std::numeric_limits<double>::infinity();
    preset.build.collapses_per_fragment = 2;
    return preset;
  }
  return std::nullopt;
}

}  // namespace mtcut::engine
