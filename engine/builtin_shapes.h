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
  // The mesh has about this many tets: usually within 10%, but TetGen's count
  // jumps as its volume bound varies, and on some shapes and sizes (the flat
  // default cylinder near 5k tets) the closest count it reaches is ~30% off.
  int target_tets = 20000;
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
// bound, re-aimed from the count obtained (at most eight TetGen runs, most
// often one or two).
TetMesh make_builtin_mesh(const BuiltinShapeDef& def, const TetrahedralizeOptions& quality);

}  // namespace mtcut::engine
