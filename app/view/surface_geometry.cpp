#include "app/view/surface_geometry.h"

namespace mtcut::app::view {
namespace {

glm::vec3 unit_or_zero(const glm::vec3& v) {
  const float length = glm::length(v);
  return length > 0.0f ? v / length : glm::vec3(0.0f);
}

}  // namespace

void update_surface_geometry(const SurfaceTopology& topology, std::span<const engine::Vec3> x, Shading shading,
                             SurfaceGeometry& out) {
  std::span<const engine::Vec3> points = x;
  if (topology.finest) {
    sim::place_finest_surface(*topology.finest, x, out.points);
    points = out.points;
  }
  const std::size_t corners = topology.corner_point.size();
  out.corner_position.resize(corners);
  out.corner_normal.resize(corners);
  for (std::size_t c = 0; c < corners; ++c) {
    const engine::Vec3& p = points[static_cast<std::size_t>(topology.corner_point[c])];
    out.corner_position[c] = glm::vec3(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
  }
  if (shading == Shading::kSmooth) out.group_normal.assign(topology.groups, glm::vec3(0.0f));
  for (std::size_t f = 0; f < topology.num_faces(); ++f) {
    const glm::vec3& a = out.corner_position[3 * f];
    // Twice the area times the unit normal: summing it weights by area.
    const glm::vec3 n = glm::cross(out.corner_position[3 * f + 1] - a, out.corner_position[3 * f + 2] - a);
    if (shading == Shading::kFlat) {
      const glm::vec3 unit = unit_or_zero(n);
      for (int k = 0; k < 3; ++k) out.corner_normal[3 * f + k] = unit;
    } else {
      for (int k = 0; k < 3; ++k) out.group_normal[topology.corner_group[3 * f + k]] += n;
    }
  }
  if (shading == Shading::kSmooth)
    for (std::size_t c = 0; c < corners; ++c)
      out.corner_normal[c] = unit_or_zero(out.group_normal[topology.corner_group[c]]);
}

}  // namespace mtcut::app::view
