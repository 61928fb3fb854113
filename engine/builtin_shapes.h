#pragma once
// Built-in organs and test solids, so that nothing needs a file:
// builtin:box, builtin:ellipsoid (the default organ), builtin:cylinder.
// Each is a closed surface sized in metres and meshed to a target tet count.

#include <optional>
#include <string>

#include "engine/surface_mesh.h"
#include "engine/tetrahedralize.h"

namespace mtcut::engine {

enum class BuiltinShape { kBox, kEllipsoid, kCylinder };

struct BuiltinShapeDef {
  BuiltinShape shape = BuiltinShape::kEllipsoid;
  // Full extents along x, y, z (box sides, ellipsoid diameters; the cylinder's
  // axis is z with diameters x and y). The default is a liver-lobe-like organ.
  Vec3 size = Vec3(0.16, 0.10, 0.07);
  int target_tets = 20000;  // the mesh has about this many tets (within ~10% when the shape allows)
};

// "builtin:box" -> kBox, ...; nullopt when `spec` is not a builtin name.
// Throws InputError for "builtin:" followed by an unknown name.
std::optional<BuiltinShape> parse_builtin(const std::string& spec);

// The analytic volume of the shape.
double analytic_volume(const BuiltinShapeDef& def);

// A closed surface of the shape, fine enough for the target tet size, and
// scaled so that its enclosed volume equals the analytic one.
SurfaceMesh make_builtin_surface(const BuiltinShapeDef& def);

// The shape's tet mesh, with about target_tets tets: meshed at a volume
// bound, re-aimed from the count obtained (at most three TetGen runs).
TetMesh make_builtin_mesh(const BuiltinShapeDef& def, const TetrahedralizeOptions& quality);

}  // namespace mtcut::engine
