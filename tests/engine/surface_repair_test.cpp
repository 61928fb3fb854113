// repair_surface on the surfaces people have, made here: crossing parts, a
// hole, a non-manifold seam, STL-style duplicate points, faces turned the
// wrong way; each comes out fit for TetGen, of the shape it had, and says
// what was done. A clean surface is left as it is; a sheet is refused.

#include "engine/surface_repair.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/builtin_shapes.h"
#include "engine/mesh_loader.h"
#include "engine/tetrahedralize.h"
#include "tests/broken_surfaces.h"
#include "tests/temp_dir.h"

namespace mtcut::engine {
namespace {

using mtcut::test::input_error_of;

using mtcut::test::box_surface;
using mtcut::test::ellipsoid_surface;
using mtcut::test::joined;


// The surface meshes, and its tets fill the volume it encloses.
void expect_meshes(const SurfaceMesh& s, const std::string& what) {
  ASSERT_EQ(s.count_open_edges(), 0u) << what;
  const TetMesh mesh = tetrahedralize(s, {}, what);
  EXPECT_TRUE(mesh.validate().ok()) << what << ": " << mesh.validate().summary();
  EXPECT_NEAR(mesh.total_volume(), s.enclosed_volume(), 1e-6 * mesh.total_volume()) << what;
}

TEST(SurfaceRepair, ACleanSurfaceIsLeftAsItIs) {
  SurfaceMesh s = ellipsoid_surface(mtcut::test::organ_size());
  const SurfaceMesh before = s;
  const SurfaceRepair r = repair_surface(s, "organ.obj");
  EXPECT_FALSE(r.changed());
  EXPECT_EQ(s.positions, before.positions);
  EXPECT_EQ(s.triangles, before.triangles);
}

TEST(SurfaceRepair, DuplicatePointsAndTurnedFacesAreMendedExactly) {
  const SurfaceMesh clean = ellipsoid_surface(mtcut::test::organ_size());
  SurfaceMesh soup;  // every triangle with its own points, every third one turned
  for (std::size_t t = 0; t < clean.triangles.size(); ++t) {
    const auto first = static_cast<std::int32_t>(soup.positions.size());
    for (int k = 0; k < 3; ++k) soup.positions.push_back(clean.positions[clean.triangles[t][k]]);
    soup.triangles.push_back(t % 3 == 0 ? std::array<std::int32_t, 3>{first, first + 2, first + 1}
                                        : std::array<std::int32_t, 3>{first, first + 1, first + 2});
  }
  const SurfaceRepair r = repair_surface(soup, "soup.stl");
  EXPECT_EQ(r.step, SurfaceRepair::Step::kSoup);
  EXPECT_EQ(r.points_merged, 3 * clean.triangles.size() - clean.positions.size());
  EXPECT_GT(r.faces_flipped, 0u);
  EXPECT_EQ(r.faces_out, clean.triangles.size());
  EXPECT_LT(r.max_distance, 1e-12);
  EXPECT_NEAR(soup.enclosed_volume(), clean.enclosed_volume(), 1e-12);
  expect_meshes(soup, "soup.stl");
  const std::string line = r.describe("soup.stl");
  EXPECT_NE(line.find("soup.stl: repaired (duplicates and orientation)"), std::string::npos) << line;
  EXPECT_NE(line.find("duplicate points merged"), std::string::npos) << line;
  EXPECT_NE(line.find("faces turned"), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
}

TEST(SurfaceRepair, HolesAreClosed) {
  const double volume = ellipsoid_surface(mtcut::test::organ_size()).enclosed_volume();
  SurfaceMesh s = mtcut::test::holed_organ();
  const SurfaceRepair r = repair_surface(s, "holey.obj");
  EXPECT_EQ(r.step, SurfaceRepair::Step::kHoles);
  EXPECT_GE(r.holes_closed, 2u);
  EXPECT_FALSE(r.input_closed);
  EXPECT_NEAR(s.enclosed_volume(), volume, 0.01 * volume);
  expect_meshes(s, "holey.obj");
  EXPECT_NE(r.describe("holey.obj").find("holes closed"), std::string::npos);
}

TEST(SurfaceRepair, OverlappingPartsBecomeTheirUnion) {
  const double part = ellipsoid_surface(mtcut::test::organ_size()).enclosed_volume();
  SurfaceMesh s = mtcut::test::crossing_organs();
  const SurfaceRepair r = repair_surface(s, "two.obj");
  EXPECT_EQ(r.step, SurfaceRepair::Step::kSelfIntersections);
  const double union_volume = s.enclosed_volume();
  EXPECT_GT(union_volume, part);
  EXPECT_LT(union_volume, 2 * part);
  EXPECT_LT(r.max_distance, 1e-9);  // the union's surface is the input's, cut where the parts cross
  EXPECT_LT(r.volume_change, 0);
  expect_meshes(s, "two.obj");
}

TEST(SurfaceRepair, ANonManifoldSeamIsMended) {
  // Two boxes sharing one edge, their points on it merged.
  const Vec3 side(0.05, 0.05, 0.05);
  SurfaceMesh s = joined(box_surface(side), box_surface(side, Vec3(0.05, 0.05, 0)), true);
  ASSERT_GT(s.count_open_edges(), 0u);  // the seam's edges are on four faces
  const double volume = 2 * 0.05 * 0.05 * 0.05;
  const SurfaceRepair r = repair_surface(s, "seam.obj");
  EXPECT_TRUE(r.changed());
  // Within what the repair says of itself, and what it promises.
  EXPECT_NEAR(s.enclosed_volume(), volume * (1 + r.volume_change), 1e-9);
  EXPECT_LT(std::abs(r.volume_change), 0.02);
  EXPECT_LT(r.max_distance, 0.01 * std::sqrt(0.1 * 0.1 + 0.1 * 0.1 + 0.05 * 0.05));
  expect_meshes(s, "seam.obj");
}

TEST(SurfaceRepair, AnOpenSheetCannotBeMadeASolid) {
  SurfaceMesh sheet;
  sheet.positions = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0.1, 0.1, 0), Vec3(0, 0.1, 0)};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
  const std::string m = input_error_of([&] { repair_surface(sheet, "sheet.obj"); });
  EXPECT_NE(m.find("sheet.obj: the surface could not be repaired"), std::string::npos) << m;
}

TEST(SurfaceRepair, AWrapIsWatertightNearTheInputAndSaysHowNear) {
  SurfaceMesh s = ellipsoid_surface(mtcut::test::organ_size());
  const double volume = s.enclosed_volume();
  const SurfaceRepair r = repair_surface(s, "organ.obj", true);
  EXPECT_EQ(r.step, SurfaceRepair::Step::kWrap);
  EXPECT_GT(r.volume_change, 0);  // the wrap encloses the input
  EXPECT_LT(r.volume_change, 0.05);
  EXPECT_LT(r.max_distance, 0.2 * 0.01);  // 1% of the diagonal
  EXPECT_NEAR(s.enclosed_volume(), volume * (1 + r.volume_change), 1e-9);
  expect_meshes(s, "organ.obj");
  EXPECT_NE(r.describe("organ.obj").find("wrapped whole"), std::string::npos);
}

// load_mesh repairs unless strict, and says what it did in a note.
TEST(SurfaceRepair, LoadMeshRepairsUnlessStrict) {
  mtcut::test::TempDir dir;
  const std::string path = dir.file("two.obj");
  write_surface_file(mtcut::test::crossing_organs(), path);
  const LoadedMesh loaded = load_mesh(path, {});
  EXPECT_TRUE(loaded.mesh.validate().ok());
  ASSERT_EQ(loaded.notes.size(), 1u);
  EXPECT_NE(loaded.notes[0].text.find(path + ": repaired (self-intersections resolved)"), std::string::npos)
      << loaded.notes[0].text;
  EXPECT_EQ(loaded.notes[0].hint.kind, InputHint::Kind::kNone);
  MeshLoadDef strict;
  strict.strict = true;
  const std::string m = input_error_of([&] { load_mesh(path, strict); });
  EXPECT_NE(m.find("intersects itself"), std::string::npos) << m;
}

}  // namespace
}  // namespace mtcut::engine
