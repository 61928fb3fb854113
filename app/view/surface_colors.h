#pragma once
// Colours of the drawn surface. Pieces: piece 0 (the largest) has the
// organ's colour and the others distinct tints of it; faces made by a cut
// are green, as in the paper's figures. LOD: a ramp from the finest level
// (blue) to the coarsest (red), so the detail following the scalpel shows.
// The tests read these colours back from screenshots, so every hue here is
// kept apart from the floor (neutral grey) and the background (dark blue).

#include <vector>

#include <glm/glm.hpp>

#include "app/view/surface_topology.h"

namespace mtcut::app::view {

enum class ColorMode { kPieces, kLodLevels };

inline constexpr glm::vec3 kOrganColor{0.72f, 0.26f, 0.20f};  // red-brown, liver-like
inline constexpr glm::vec3 kCutColor{0.25f, 0.80f, 0.30f};    // green
inline constexpr glm::vec3 kBackgroundColor{0.11f, 0.13f, 0.18f};
inline constexpr glm::vec3 kFloorLight{0.62f, 0.62f, 0.62f};
inline constexpr glm::vec3 kFloorDark{0.48f, 0.48f, 0.48f};

// The tint of piece p (p = 0: kOrganColor); cycles after a few pieces.
glm::vec3 piece_color(int piece);

// The LOD ramp at level in [0, max_level].
glm::vec3 level_color(int level, int max_level);

// (3 n_faces) the colour of every corner.
std::vector<glm::vec3> corner_colors(const SurfaceTopology& topology, ColorMode mode);

}  // namespace mtcut::app::view
