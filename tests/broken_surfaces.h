#pragma once
// Surfaces as people have them, made from the builtin shapes: parts that
// cross, a hole. For the repair's tests and the cuts on repaired meshes.

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "engine/builtin_shapes.h"
#include "engine/surface_mesh.h"

namespace mtcut::test {

using engine::Vec3;

// The builtin ellipsoid's surface for `target_tets` (1,280 faces for the
// default) moved by `at`.
inline engine::SurfaceMesh ellipsoid_surface(const Vec3& size, const Vec3& at = Vec3::Zero(),
                                             int target_tets = 100000) {
  engine::SurfaceMesh s =
      engine::make_builtin_surface(engine::BuiltinShapeDef{engine::BuiltinShape::kEllipsoid, size, target_tets});
  for (Vec3& p : s.positions) p += at;
  return s;
}

// The builtin box's surface (12 faces) moved by `at`.
inline engine::SurfaceMesh box_surface(const Vec3& size, const Vec3& at = Vec3::Zero()) {
  engine::SurfaceMesh s = engine::make_builtin_surface(engine::BuiltinShapeDef{engine::BuiltinShape::kBox, size, 1});
  for (Vec3& p : s.positions) p += at;
  return s;
}

// Both surfaces as one, their coinciding points merged when asked.
inline engine::SurfaceMesh joined(const engine::SurfaceMesh& a, const engine::SurfaceMesh& b, bool merge_points) {
  engine::SurfaceMesh s = a;
  std::map<std::array<double, 3>, std::int32_t> at;
  if (merge_points)
    for (std::size_t i = 0; i < a.positions.size(); ++i)
      at[{a.positions[i].x(), a.positions[i].y(), a.positions[i].z()}] = static_cast<std::int32_t>(i);
  std::vector<std::int32_t> id(b.positions.size());
  for (std::size_t i = 0; i < b.positions.size(); ++i) {
    const auto found = at.find({b.positions[i].x(), b.positions[i].y(), b.positions[i].z()});
    if (merge_points && found != at.end()) {
      id[i] = found->second;
    } else {
      id[i] = static_cast<std::int32_t>(s.positions.size());
      s.positions.push_back(b.positions[i]);
    }
  }
  for (const auto& t : b.triangles) s.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
  return s;
}

// The organs below: an ellipsoid of this size (metres).
inline Vec3 organ_size() { return Vec3(0.16, 0.1, 0.07); }

// Two organs that cross each other, the second moved by (5, 3, 1) cm, as
// one surface; ellipsoids of the builtin shape for `target_tets`.
inline engine::SurfaceMesh crossing_organs(int target_tets = 100000) {
  return joined(ellipsoid_surface(organ_size(), Vec3::Zero(), target_tets),
                ellipsoid_surface(organ_size(), Vec3(0.05, 0.03, 0.01), target_tets), false);
}

// An organ with two holes: three faces in a row from the 11th and the middle one.
inline engine::SurfaceMesh holed_organ(int target_tets = 100000) {
  engine::SurfaceMesh s = ellipsoid_surface(organ_size(), Vec3::Zero(), target_tets);
  s.triangles.erase(s.triangles.begin() + 10, s.triangles.begin() + 13);
  s.triangles.erase(s.triangles.begin() + static_cast<std::ptrdiff_t>(s.triangles.size() / 2));
  return s;
}

}  // namespace mtcut::test
