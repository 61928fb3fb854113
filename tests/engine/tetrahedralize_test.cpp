#include "engine/tetrahedralize.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/builtin_shapes.h"
#include "engine/child_process.h"
#include "engine/input_error.h"
#include "engine/mesh_loader.h"
#include "engine/mesh_stats.h"
#include "tests/temp_dir.h"
#include "tests/test_paths.h"

namespace mtcut::engine {
namespace {

using mtcut::test::input_error_of;

SurfaceMesh unit_box() { return make_builtin_surface(BuiltinShapeDef{BuiltinShape::kBox, Vec3(1, 1, 1), 10}); }

TEST(Tetrahedralize, RealSurfacesGiveValidMeshesOfTheSameVolume) {
  for (const std::string name : {"liver.obj", "liver2.obj", "torus.obj"}) {
    const SurfaceMesh surface = read_surface_file(mtcut::test::shared_mesh(name));
    const TetMesh mesh = tetrahedralize(surface, {}, name);
    const auto report = mesh.validate();
    EXPECT_TRUE(report.ok()) << name << ": " << report.summary();
    // TetGen treats facets coplanar within its tolerance (-T, 1e-8) as one
    // and may re-triangulate them, which moves the volume by ~1e-7 relative.
    EXPECT_NEAR(mesh.total_volume(), std::abs(surface.enclosed_volume()), 1e-6 * mesh.total_volume()) << name;
    EXPECT_GT(compute_stats(mesh).min_dihedral_deg, 0.5) << name;
  }
}

TEST(Tetrahedralize, MaxVolumeBoundsEveryTet) {
  TetrahedralizeOptions options;
  options.max_volume = 0.001;
  const TetMesh mesh = tetrahedralize(unit_box(), options, "box");
  EXPECT_GE(mesh.num_tets(), 1000u);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) EXPECT_LE(mesh.volume(TetId(t)), 0.001 * (1 + 1e-9));
  EXPECT_NEAR(mesh.total_volume(), 1.0, 1e-12);
}

TEST(Tetrahedralize, QualityRaisesTheSmallestAngle) {
  TetrahedralizeOptions rough;
  rough.radius_edge_ratio = 0;
  rough.max_volume = 0;
  const SurfaceMesh liver = read_surface_file(mtcut::test::shared_mesh("liver2.obj"));
  TetrahedralizeOptions good;
  good.min_dihedral_deg = 12;
  EXPECT_GT(compute_stats(tetrahedralize(liver, good, "liver2")).min_dihedral_deg,
            compute_stats(tetrahedralize(liver, rough, "liver2")).min_dihedral_deg);
}

TEST(Tetrahedralize, SurfaceWithAHoleIsRejected) {
  SurfaceMesh box = unit_box();
  box.triangles.pop_back();
  const std::string m = input_error_of([&] { tetrahedralize(box, {}, "holey.obj"); });
  EXPECT_NE(m.find("holey.obj: the surface is not closed"), std::string::npos) << m;
}

TEST(Tetrahedralize, SelfIntersectingSurfaceNamesTheFaces) {
  // Two closed boxes that overlap, given as one surface.
  SurfaceMesh a = unit_box();
  const SurfaceMesh b = unit_box();
  const auto offset = static_cast<std::int32_t>(a.positions.size());
  for (const auto& p : b.positions) a.positions.push_back(p + Vec3(0.5, 0.3, 0.2));
  for (const auto& t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const std::string m = input_error_of([&] { tetrahedralize(a, {}, "twoboxes.obj"); });
  EXPECT_NE(m.find("twoboxes.obj: the surface intersects itself"), std::string::npos) << m;
  EXPECT_NE(m.find("triangles"), std::string::npos) << m;
}

TEST(Tetrahedralize, TetGenChatterStaysOffStdout) {
  testing::internal::CaptureStdout();
  (void)tetrahedralize(unit_box(), {}, "box");
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
}

TEST(Tetrahedralize, NegativeOptionsAreRejected) {
  TetrahedralizeOptions options;
  options.max_volume = -1;
  EXPECT_THROW(tetrahedralize(unit_box(), options, "box"), InputError);
}

// A tube 1 m long and 1 cm wide whose faces are slivers 12.5 cm long:
// TetGen's quality refinement adds 1.6 million points to it unbounded.
SurfaceMesh sliver_tube() {
  constexpr int kAround = 200, kAlong = 4;
  SurfaceMesh tube;
  for (int i = 0; i <= kAlong; ++i)
    for (int j = 0; j < kAround; ++j) {
      const double a = 2 * M_PI * j / kAround;
      tube.positions.emplace_back(0.005 * std::cos(a), 0.005 * std::sin(a), static_cast<double>(i) / kAlong);
    }
  const auto id = [](int i, int j) { return static_cast<std::int32_t>(i * kAround + (j % kAround)); };
  for (int i = 0; i < kAlong; ++i)
    for (int j = 0; j < kAround; ++j) {
      tube.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      tube.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  const auto bottom = static_cast<std::int32_t>(tube.positions.size());
  tube.positions.emplace_back(0, 0, 0);
  tube.positions.emplace_back(0, 0, 1);
  for (int j = 0; j < kAround; ++j) {
    tube.triangles.push_back({bottom, id(0, j + 1), id(0, j)});
    tube.triangles.push_back({bottom + 1, id(kAlong, j), id(kAlong, j + 1)});
  }
  return tube;
}

TEST(Tetrahedralize, RefinementStopsAtItsBoundOfAddedPointsAndSaysSo) {
  const SurfaceMesh tube = sliver_tube();
  EXPECT_GT(steiner_point_bound(tube, {}), 100000);
  EXPECT_LT(steiner_point_bound(tube, {}), 200000);
  TetrahedralizeOptions options;
  options.max_added_points = 3000;
  std::vector<InputNote> notes;
  const TetMesh mesh = tetrahedralize(tube, options, "tube.obj", &notes);
  EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().summary();
  EXPECT_LE(mesh.num_vertices(), tube.positions.size() + 3000);
  EXPECT_NEAR(mesh.total_volume(), tube.enclosed_volume(), 1e-9 * tube.enclosed_volume());
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].text.find("tube.obj: TetGen reached its bound of 3000 added points"), std::string::npos)
      << notes[0].text;
  EXPECT_NE(notes[0].text.find("looser quality bound 2.25"), std::string::npos) << notes[0].text;
  EXPECT_EQ(notes[0].hint.kind, InputHint::Kind::kNone);
  // Within the bound, no note.
  notes.clear();
  (void)tetrahedralize(read_surface_file(mtcut::test::shared_mesh("liver2.obj")), {}, "liver2.obj", &notes);
  EXPECT_TRUE(notes.empty());
}

TEST(Tetrahedralize, AMeshingOverItsTimeLimitIsStoppedAndRefused) {
  TetrahedralizeOptions options;
  options.time_limit_seconds = 1e-6;
  const std::string m =
      input_error_of([&] { tetrahedralize(read_surface_file(mtcut::test::shared_mesh("liver2.obj")), options, "liver2.obj"); });
  EXPECT_NE(m.find("liver2.obj: TetGen did not finish"), std::string::npos) << m;
}

// The time limit stops the quality refinement too, not only the surface's
// check: with no bound on added points, the tube's refinement (1.6 million
// points, 84 s on the machine of docs/meshes.md) runs past its share of the
// limit (60%, 6 s) on any machine, is stopped, and a looser try (to 85%)
// or none (the last 1.5 s; a Delaunay mesh of the tube's 1,000 points)
// meshes the tube, with a note that says why. The limit is an input here,
// not a bound on the test's time. The tries run in children, which the
// deadline needs: this test process runs no other thread.
TEST(Tetrahedralize, ARefinementOverItsShareOfTheTimeLimitIsRetriedLooserAndSaysSo) {
  ASSERT_FALSE(process_runs_other_threads());
  const SurfaceMesh tube = sliver_tube();
  TetrahedralizeOptions options;
  options.max_added_points = 100000000;
  options.time_limit_seconds = 10;
  std::vector<InputNote> notes;
  const TetMesh mesh = tetrahedralize(tube, options, "tube.obj", &notes);
  EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().summary();
  EXPECT_NEAR(mesh.total_volume(), tube.enclosed_volume(), 1e-9 * tube.enclosed_volume());
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].text.rfind("tube.obj: TetGen did not finish within ", 0), 0u) << notes[0].text;
  EXPECT_NE(notes[0].text.find(" instead"), std::string::npos) << notes[0].text;
}

TEST(MeshLoader, LoadsEveryGoodSharedMeshAndRejectsTheBrokenOnes) {
  MeshLoadDef def;
  for (const auto& entry : std::filesystem::directory_iterator(mtcut::test::shared_mesh(""))) {
    const std::string path = entry.path().string();
    const std::string name = entry.path().filename().string();
    if (name == "README.md") continue;
    if (name.find("_broken") != std::string::npos) {
      const std::string m = input_error_of([&] { load_mesh(path, def); });
      EXPECT_NE(m, "no error") << name;
      EXPECT_NE(m.find(name), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    } else {
      const LoadedMesh loaded = load_mesh(path, def);
      EXPECT_GT(loaded.mesh.num_tets(), 0u) << name;
      const auto report = loaded.mesh.validate();
      EXPECT_TRUE(report.ok()) << name << ": " << report.summary();
    }
  }
}

TEST(MeshLoader, UnknownFormatsAndShapesAreRejected) {
  EXPECT_NE(input_error_of([] { load_mesh("organ.xyz", {}); }).find("organ.xyz: unknown mesh format"), std::string::npos);
  EXPECT_NE(input_error_of([] { load_mesh("builtin:heart", {}); }).find("unknown built-in shape"), std::string::npos);
}

}  // namespace
}  // namespace mtcut::engine
