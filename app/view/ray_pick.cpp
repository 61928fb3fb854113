#include "app/view/ray_pick.h"

#include <cmath>

namespace mtcut::app::view {

std::optional<double> intersect_triangle(const Ray& ray, const glm::dvec3& a, const glm::dvec3& b,
                                         const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(ray.direction, e2);
  const double det = glm::dot(e1, p);
  // Relative to the triangle's size: a ray in the triangle's plane misses it.
  if (std::abs(det) <= 1e-12 * glm::length(e1) * glm::length(e2)) return std::nullopt;
  const double inv = 1.0 / det;
  const glm::dvec3 s = ray.origin - a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(ray.direction, q) * inv;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = glm::dot(e2, q) * inv;
  if (!(t > 0.0)) return std::nullopt;
  return t;
}

std::optional<SurfaceHit> pick_surface(const Ray& ray, std::span<const glm::vec3> corners) {
  std::optional<SurfaceHit> best;
  const std::size_t faces = corners.size() / 3;
  for (std::size_t f = 0; f < faces; ++f) {
    const auto t = intersect_triangle(ray, glm::dvec3(corners[3 * f]), glm::dvec3(corners[3 * f + 1]),
                                      glm::dvec3(corners[3 * f + 2]));
    if (t && (!best || *t < best->t)) best = SurfaceHit{*t, static_cast<int>(f), ray.origin + *t * ray.direction};
  }
  return best;
}

}  // namespace mtcut::app::view
