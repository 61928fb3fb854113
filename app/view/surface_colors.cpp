#include "app/view/surface_colors.h"

#include <algorithm>
#include <array>

namespace mtcut::app::view {

glm::vec3 piece_color(int piece) {
  // Warm tints that stay clear of green (cuts) and of neutral grey (floor).
  static constexpr std::array<glm::vec3, 6> kTints = {
      kOrganColor,
      glm::vec3{0.85f, 0.60f, 0.22f},  // amber
      glm::vec3{0.70f, 0.30f, 0.62f},  // plum
      glm::vec3{0.30f, 0.45f, 0.85f},  // blue
      glm::vec3{0.90f, 0.62f, 0.70f},  // pink
      glm::vec3{0.60f, 0.45f, 0.30f},  // tan
  };
  return kTints[static_cast<std::size_t>(std::max(piece, 0)) % kTints.size()];
}

glm::vec3 level_color(int level, int max_level) {
  const float s = max_level > 0 ? std::clamp(static_cast<float>(level) / static_cast<float>(max_level), 0.0f, 1.0f)
                                : 0.0f;
  // blue -> cyan -> yellow -> red
  static constexpr std::array<glm::vec3, 4> kStops = {glm::vec3{0.20f, 0.30f, 0.90f}, glm::vec3{0.15f, 0.75f, 0.85f},
                                                      glm::vec3{0.95f, 0.85f, 0.20f}, glm::vec3{0.90f, 0.20f, 0.15f}};
  const float at = s * static_cast<float>(kStops.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(at), kStops.size() - 2);
  return glm::mix(kStops[i], kStops[i + 1], at - static_cast<float>(i));
}

std::vector<glm::vec3> corner_colors(const SurfaceTopology& topology, ColorMode mode) {
  std::vector<glm::vec3> colors(3 * topology.num_faces());
  for (std::size_t f = 0; f < topology.num_faces(); ++f) {
    glm::vec3 c;
    if (mode == ColorMode::kLodLevels) {
      c = level_color(topology.face_level[f], topology.max_level);
    } else {
      c = topology.face_cut[f] ? kCutColor : piece_color(topology.face_piece[f]);
    }
    for (int k = 0; k < 3; ++k) colors[3 * f + k] = c;
  }
  return colors;
}

}  // namespace mtcut::app::view
