#pragma once
// Picking: the first triangle of the drawn surface that a ray meets.

#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "app/view/orbit_camera.h"

namespace mtcut::app::view {

struct SurfaceHit {
  double t = 0;           // distance along the ray (its direction is unit)
  int face = -1;          // index of the triangle
  glm::dvec3 point{0.0};  // origin + t * direction
};

// Intersects `ray` with triangles given as corner triples (3 n_faces corners,
// face i = corners 3i..3i+2), both sides; the nearest hit in front of the
// origin, or none (Moller-Trumbore, brute force: a few thousand faces).
std::optional<SurfaceHit> pick_surface(const Ray& ray, std::span<const glm::vec3> corners);

// The hit of the ray with the triangle (a, b, c), either side: t > 0 or none.
std::optional<double> intersect_triangle(const Ray& ray, const glm::dvec3& a, const glm::dvec3& b,
                                         const glm::dvec3& c);

}  // namespace mtcut::app::view
