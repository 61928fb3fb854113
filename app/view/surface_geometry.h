#pragma once
// Per-frame geometry of the drawn surface: the deformed position and the
// normal of every corner of a SurfaceTopology, as floats ready to upload.

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "app/view/surface_topology.h"
#include "engine/predicates.h"

namespace mtcut::app::view {

enum class Shading { kSmooth, kFlat };

struct SurfaceGeometry {
  std::vector<glm::vec3> corner_position;  // (3 n_faces) deformed, m
  std::vector<glm::vec3> corner_normal;    // (3 n_faces) unit (zero for a degenerate face)
  std::vector<glm::vec3> group_normal;     // (n_groups) scratch for smooth shading
  std::vector<engine::Vec3> points;        // scratch: the finest surface's vertices, placed
};

// Fills `out` from the particle positions `x` (n_particles), through the
// finest surface's carriers when the topology is of it. Flat: each
// corner takes its face's normal; smooth: the area-weighted average over
// the faces of its normal group (SurfaceTopology::corner_group).
void update_surface_geometry(const SurfaceTopology& topology, std::span<const engine::Vec3> x, Shading shading,
                             SurfaceGeometry& out);

}  // namespace mtcut::app::view
