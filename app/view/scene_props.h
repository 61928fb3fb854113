#pragma once
// The props drawn around the tissue, as plain triangles: the floor (a
// checkerboard on the environment's floor plane, under the organ) and the
// blade (a ribbon along the scalpel's segment, turned to face the eye).

#include <vector>

#include <glm/glm.hpp>

#include "sim/environment.h"
#include "sim/scalpel.h"

namespace mtcut::app::view {

struct PropVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec3 color;
};

inline constexpr glm::vec3 kBladeColor{0.40f, 0.75f, 1.00f};         // light blue: touching only
inline constexpr glm::vec3 kEngagedBladeColor{1.00f, 0.85f, 0.20f};  // yellow: cutting

// Triangles of a `tiles` x `tiles` checkerboard on `floor`, centred under the
// box [lo, hi] and `extent` times its diagonal wide.
std::vector<PropVertex> floor_triangles(const sim::Plane& floor, const glm::dvec3& lo, const glm::dvec3& hi,
                                        int tiles = 12, double extent = 2.5);

// Two triangles: the blade from base to tip, `width` m wide, facing `eye`.
std::vector<PropVertex> blade_triangles(const sim::ScalpelPose& pose, const glm::dvec3& eye, double width);

}  // namespace mtcut::app::view
