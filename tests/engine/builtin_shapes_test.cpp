#include "engine/builtin_shapes.h"

#include <gtest/gtest.h>

#include "engine/input_error.h"
#include "engine/mesh_loader.h"

namespace mtcut::engine {
namespace {

class BuiltinShapes : public ::testing::TestWithParam<BuiltinShape> {};

TEST_P(BuiltinShapes, VolumeAndCountMatchTheTarget) {
  for (const int target : {1000, 5000, 20000}) {
    BuiltinShapeDef def;
    def.shape = GetParam();
    def.size = Vec3(0.16, 0.10, 0.07);
    def.target_tets = target;
    const SurfaceMesh surface = make_builtin_surface(def);
    EXPECT_EQ(surface.count_open_edges(), 0u);
    const TetMesh mesh = make_builtin_mesh(def, {});
    const auto report = mesh.validate();
    ASSERT_TRUE(report.ok()) << report.summary();
    const double exact = analytic_volume(def);
    EXPECT_NEAR(mesh.total_volume(), exact, 0.02 * exact) << "target " << target;
    // The count TetGen reaches is discontinuous in its volume bound: for the
    // flat default cylinder (7 cm high, 16 cm across) it jumps from ~6,700
    // to ~3,600 tets as the bound crosses 3.7 V/N, so near 5,000 tets the
    // closest count reachable is ~28% off. Elsewhere it is within 25%.
    const double tolerance = GetParam() == BuiltinShape::kCylinder ? 0.35 : 0.25;
    EXPECT_NEAR(static_cast<double>(mesh.num_tets()), target, tolerance * target) << "target " << target;
  }
}

std::string shape_name(const ::testing::TestParamInfo<BuiltinShape>& param) {
  switch (param.param) {
    case BuiltinShape::kBox: return "Box";
    case BuiltinShape::kEllipsoid: return "Ellipsoid";
    case BuiltinShape::kCylinder: return "Cylinder";
  }
  return "Unknown";
}

INSTANTIATE_TEST_SUITE_P(AllShapes, BuiltinShapes,
                         ::testing::Values(BuiltinShape::kBox, BuiltinShape::kEllipsoid, BuiltinShape::kCylinder),
                         shape_name);

TEST(BuiltinShapesParse, NamesAndErrors) {
  EXPECT_EQ(parse_builtin("builtin:box"), BuiltinShape::kBox);
  EXPECT_EQ(parse_builtin("builtin:ellipsoid"), BuiltinShape::kEllipsoid);
  EXPECT_EQ(parse_builtin("builtin:cylinder"), BuiltinShape::kCylinder);
  EXPECT_EQ(parse_builtin("liver.obj"), std::nullopt);
  EXPECT_THROW(parse_builtin("builtin:spleen"), InputError);
  EXPECT_THROW(make_builtin_surface(BuiltinShapeDef{BuiltinShape::kBox, Vec3(1, -1, 1), 10}), InputError);
  EXPECT_THROW(make_builtin_surface(BuiltinShapeDef{BuiltinShape::kBox, Vec3(1, 1, 1), 0}), InputError);
}

TEST(BuiltinShapesParse, LoaderUsesSizeAndCount) {
  MeshLoadDef def;
  def.builtin_size = Vec3(2, 1, 1);
  def.builtin_tets = 2000;
  const LoadedMesh loaded = load_mesh("builtin:box", def);
  EXPECT_EQ(loaded.kind, "builtin");
  EXPECT_NEAR(loaded.mesh.total_volume(), 2.0, 1e-12);
}

}  // namespace
}  // namespace mtcut::engine
