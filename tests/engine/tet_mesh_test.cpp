#include "engine/tet_mesh.h"

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>

#include "engine/input_error.h"
#include "engine/mesh_loader.h"
#include "engine/tet_adjacency.h"
#include "tests/touching_cubes.h"

namespace mtcut::engine {
namespace {

// A unit cube split into 6 tets around the diagonal 0-7 (Kuhn triangulation).
TetMesh kuhn_cube() {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const std::vector<std::array<std::int64_t, 4>> tets = {
      {0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};
  return make_tet_mesh(p, tets, "cube");
}

bool mentions(const ValidationReport& r, const std::string& text) {
  for (const auto& p : r.problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

TEST(TetMesh, KuhnCubeIsValidWithUnitVolume) {
  const TetMesh mesh = kuhn_cube();
  const auto report = mesh.validate();
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_NEAR(mesh.total_volume(), 1.0, 1e-15);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) EXPECT_GT(mesh.volume(TetId(t)), 0);
}

TEST(TetMesh, AdjacencyOfKuhnCube) {
  const TetMesh mesh = kuhn_cube();
  const TetAdjacency adj = build_adjacency(mesh);
  EXPECT_EQ(adj.boundary.size(), 12u);
  EXPECT_EQ(adj.non_manifold_faces, 0u);
  std::size_t interior = 0;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      const TetId u = adj.neighbors[t][f];
      if (!u.valid()) continue;
      ++interior;
      // Symmetric: u sees t across one of its faces.
      const auto& back = adj.neighbors[u.index()];
      EXPECT_NE(std::find(back.begin(), back.end(), TetId(t)), back.end());
    }
  EXPECT_EQ(interior, 12u);  // 6 interior faces, seen from both sides
}

// What build_adjacency must find, by the plainest means: every face slot
// filed under its sorted vertex ids in an ordered map. Boundary faces come in
// the map's order (sorted ids), as build_adjacency promises.
void expect_adjacency_matches_face_map(const TetMesh& mesh) {
  std::map<std::array<std::int32_t, 3>, std::vector<std::pair<std::size_t, int>>> slots;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      const auto v = face_vertices(mesh.tets[t], f);
      std::array<std::int32_t, 3> key = {v[0].value, v[1].value, v[2].value};
      std::sort(key.begin(), key.end());
      slots[key].emplace_back(t, f);
    }
  std::vector<std::array<TetId, 4>> neighbors(mesh.num_tets(), {TetId(), TetId(), TetId(), TetId()});
  std::vector<std::pair<std::size_t, int>> boundary;
  std::size_t non_manifold = 0;
  for (const auto& [key, on] : slots) {
    if (on.size() == 1) boundary.push_back(on[0]);
    if (on.size() == 2) {
      neighbors[on[0].first][static_cast<std::size_t>(on[0].second)] = TetId(on[1].first);
      neighbors[on[1].first][static_cast<std::size_t>(on[1].second)] = TetId(on[0].first);
    }
    if (on.size() > 2) ++non_manifold;
  }
  const TetAdjacency adj = build_adjacency(mesh);
  EXPECT_EQ(adj.neighbors, neighbors);
  EXPECT_EQ(adj.non_manifold_faces, non_manifold);
  ASSERT_EQ(adj.boundary.size(), boundary.size());
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    EXPECT_EQ(adj.boundary[i].tet, TetId(boundary[i].first)) << "boundary face " << i;
    EXPECT_EQ(adj.boundary[i].local_face, boundary[i].second) << "boundary face " << i;
    EXPECT_EQ(adj.boundary[i].verts, face_vertices(mesh.tets[boundary[i].first], boundary[i].second));
  }
}

TEST(TetMesh, AdjacencyMatchesMatchingFacesBySortedIds) {
  for (const char* spec : {"builtin:box", "builtin:ellipsoid"}) {
    SCOPED_TRACE(spec);
    MeshLoadDef load;
    load.builtin_tets = 3000;
    expect_adjacency_matches_face_map(load_mesh(spec, load).mesh);
  }
  // Three tets on one face (non-manifold), a vertex no tet uses, and ids
  // out of spatial order.
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1}, {0.3, 0.3, -1}, {0.2, 0.2, 2}, {5, 5, 5}};
  TetMesh fan = make_tet_mesh(p, {{5, 0, 1, 2}, {0, 1, 2, 3}, {0, 2, 1, 4}}, "fan");
  expect_adjacency_matches_face_map(fan);
  EXPECT_EQ(build_adjacency(fan).non_manifold_faces, 1u);  // face 0-1-2, on three tets
  fan.tets.push_back(fan.tets[1]);  // a duplicate: its other faces pair it with tet 1
  expect_adjacency_matches_face_map(fan);
  const TetAdjacency adj = build_adjacency(fan);
  EXPECT_EQ(adj.non_manifold_faces, 1u);
  EXPECT_EQ(adj.neighbors[3][0], TetId(1));  // face 1-2-3 (opposite vertex 0)
  fan.tets[2][1] = VertId();  // id -1
  EXPECT_THROW(build_adjacency(fan), std::invalid_argument);
}

TEST(TetMesh, MakeTetMeshFixesOrientation) {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const TetMesh mesh = make_tet_mesh(p, {{0, 2, 1, 3}}, "flipped");
  EXPECT_GT(mesh.volume(TetId(0)), 0);
  EXPECT_TRUE(mesh.validate().ok());
}

TEST(TetMesh, MakeTetMeshRejectsBadInput) {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  EXPECT_THROW(make_tet_mesh(p, {{0, 1, 2, 9}}, "x"), InputError);
  EXPECT_THROW(make_tet_mesh(p, {{0, 1, 2, 4}}, "x"), InputError);  // coplanar
  p[4] = Vec3(std::nan(""), 0, 0);
  try {
    make_tet_mesh(p, {{0, 1, 2, 3}}, "bad.node");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.node: vertex 4"), std::string::npos) << e.what();
  }
}

TEST(TetMesh, ValidateNamesInvertedTets) {
  TetMesh mesh = kuhn_cube();
  std::swap(mesh.tets[2][0], mesh.tets[2][1]);
  const auto report = mesh.validate();
  EXPECT_FALSE(report.ok());
  EXPECT_TRUE(mentions(report, "tet 2 is negatively oriented")) << report.summary();
}

TEST(TetMesh, ValidateNamesDuplicatesAndBadIds) {
  TetMesh mesh = kuhn_cube();
  mesh.tets.push_back(mesh.tets[0]);
  auto report = mesh.validate();
  EXPECT_TRUE(mentions(report, "tets 0 and 6 are duplicates")) << report.summary();
  EXPECT_TRUE(mentions(report, "more than two tets")) << report.summary();

  mesh = kuhn_cube();
  mesh.tets[1][2] = VertId(42);
  report = mesh.validate();
  EXPECT_TRUE(mentions(report, "tet 1 refers to vertex 42")) << report.summary();
}

TEST(TetMesh, ValidateNamesDegenerateAndOverlappingTets) {
  TetMesh mesh = kuhn_cube();
  mesh.positions[7] = Vec3(0.5, 0.5, 0);  // flattens the tets that share 0 and 7 in z = 0
  auto report = mesh.validate();
  EXPECT_FALSE(report.ok());
  EXPECT_TRUE(mentions(report, "degenerate") || mentions(report, "negatively")) << report.summary();

  // Two tets on the same side of their shared face overlap.
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.2, 0.5}};
  mesh = make_tet_mesh(p, {{0, 1, 2, 3}, {0, 1, 2, 4}}, "overlap");
  report = mesh.validate();
  EXPECT_TRUE(mentions(report, "overlap")) << report.summary();
}

TEST(TetMesh, ValidateNamesNonManifoldBoundary) {
  // Two tets touching at a single edge: the boundary is pinched there.
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {0, 0, -1}};
  const TetMesh mesh = make_tet_mesh(p, {{0, 1, 2, 3}, {0, 1, 4, 5}}, "pinched");
  const auto report = mesh.validate();
  EXPECT_TRUE(mentions(report, "not manifold")) << report.summary();
}

// Two cubes touching along an edge or at a vertex: each part gets its own
// copy of the shared vertices, and the mesh is valid, with the same tets
// and volume.
TEST(TetMesh, PinchedVerticesAreSplitSoPartsOnlyTouchingComeApart) {
  for (const int z_step : {0, 1}) {
    const RawMesh raw = mtcut::test::touching_cubes(0.05, z_step);
    TetMesh mesh = make_tet_mesh(raw.positions, raw.tets, "cubes");
    if (z_step == 0) {
      EXPECT_FALSE(mesh.validate().ok());  // an edge on four boundary faces
    }
    const double volume = mesh.total_volume();
    const std::size_t shared = z_step == 0 ? 2 : 1;
    EXPECT_EQ(split_pinched_vertices(mesh), shared) << z_step;
    EXPECT_EQ(mesh.num_vertices(), 16u);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().summary();
    EXPECT_NEAR(mesh.total_volume(), volume, 1e-15);
    // No tet of the first cube shares a vertex with the second now.
    for (std::size_t t = 0; t < 6; ++t)
      for (std::size_t u = 6; u < 12; ++u)
        for (VertId a : mesh.tets[t])
          for (VertId b : mesh.tets[u]) EXPECT_NE(a, b) << t << " " << u;
    EXPECT_EQ(split_pinched_vertices(mesh), 0u);  // nothing left to split
  }
  TetMesh cube = kuhn_cube();
  EXPECT_EQ(split_pinched_vertices(cube), 0u);
  EXPECT_EQ(cube.num_vertices(), 8u);
}

}  // namespace
}  // namespace mtcut::engine
