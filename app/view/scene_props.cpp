#include "app/view/scene_props.h"

#include <cmath>

#include "app/view/surface_colors.h"

namespace mtcut::app::view {
namespace {

glm::dvec3 to_glm(const engine::Vec3& v) { return {v.x(), v.y(), v.z()}; }

void push_quad(std::vector<PropVertex>& out, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
               const glm::dvec3& d, const glm::vec3& normal, const glm::vec3& color) {
  for (const glm::dvec3& p : {a, b, c, a, c, d}) out.push_back({glm::vec3(p), normal, color});
}

}  // namespace

std::vector<PropVertex> floor_triangles(const sim::Plane& floor, const glm::dvec3& lo, const glm::dvec3& hi,
                                        int tiles, double extent) {
  const glm::dvec3 n = glm::normalize(to_glm(floor.normal));
  // Two axes in the plane: the one closest to x first, then n x u.
  const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(helper - glm::dot(helper, n) * n);
  const glm::dvec3 v = glm::cross(n, u);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const glm::dvec3 origin = centre + (floor.offset - glm::dot(centre, n)) * n;  // centre dropped on the plane
  const double half = 0.5 * extent * glm::length(hi - lo);
  const double tile = 2.0 * half / tiles;
  std::vector<PropVertex> out;
  out.reserve(static_cast<std::size_t>(tiles) * tiles * 6);
  for (int i = 0; i < tiles; ++i) {
    for (int j = 0; j < tiles; ++j) {
      const glm::dvec3 a = origin + (-half + i * tile) * u + (-half + j * tile) * v;
      const glm::vec3 color = (i + j) % 2 == 0 ? kFloorLight : kFloorDark;
      push_quad(out, a, a + tile * u, a + tile * (u + v), a + tile * v, glm::vec3(n), color);
    }
  }
  return out;
}

std::vector<PropVertex> blade_triangles(const sim::ScalpelPose& pose, const glm::dvec3& eye, double width) {
  const glm::dvec3 base = to_glm(pose.base), tip = to_glm(pose.tip);
  const glm::dvec3 along = tip - base;
  const glm::dvec3 to_eye = eye - 0.5 * (base + tip);
  glm::dvec3 side = glm::cross(along, to_eye);
  if (glm::length(side) < 1e-12) side = glm::cross(along, glm::dvec3(0, 0, 1));
  if (glm::length(side) < 1e-12) side = glm::dvec3(1, 0, 0);
  side = 0.5 * width * glm::normalize(side);
  const glm::vec3 normal(glm::normalize(to_eye));
  std::vector<PropVertex> out;
  push_quad(out, base - side, tip - side, tip + side, base + side, normal,
            pose.engaged ? kEngagedBladeColor : kBladeColor);
  return out;
}

}  // namespace mtcut::app::view
