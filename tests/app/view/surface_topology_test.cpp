#include "app/view/surface_topology.h"

#include <gtest/gtest.h>

#include <set>

#include "app/fragment_levels.h"
#include "app/view/surface_geometry.h"
#include "engine/mesh_loader.h"
#include "engine/mt/mt_builder.h"
#include "sim/fixed_region.h"
#include "tests/app/view/tiny_mt.h"

namespace mtcut::app::view {
namespace {

struct Extracted {
  test::TinyWorld world;
  SurfaceTopology topology;
};

Extracted extract(std::size_t first_cut_vertex) {
  Extracted e{test::make_tiny_world(test::three_piece_mesh()), {}};
  const PieceLabels pieces = label_frontier_pieces(e.world.mt, e.world.frontier);
  e.topology = extract_surface(e.world.mt, e.world.frontier, e.world.model, pieces, fragment_levels(e.world.mt),
                               first_cut_vertex);
  return e;
}

TEST(SurfaceTopology, BoundaryFacesWithPiecesAndCornersOnTheirParticles) {
  const Extracted e = extract(12);
  const SurfaceTopology& s = e.topology;
  // A and B share one face: 3 + 3 + 4 + 4 boundary faces.
  ASSERT_EQ(s.num_faces(), 14u);
  EXPECT_EQ(s.pieces, 3);
  EXPECT_EQ(s.corner_point.size(), 42u);
  std::multiset<int> per_piece;
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    per_piece.insert(s.face_piece[f]);
    EXPECT_EQ(s.face_cut[f], 0);
    EXPECT_EQ(s.face_level[f], 0);  // all made by the root
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(e.world.model.particle_vertex[s.corner_point[3 * f + k]], s.faces[f][k]);
  }
  EXPECT_EQ(per_piece.count(0), 6u);
  EXPECT_EQ(per_piece.count(1), 4u);
  EXPECT_EQ(per_piece.count(2), 4u);
  EXPECT_EQ(s.groups, 13);  // every vertex is on the surface, none on a cut
}

TEST(SurfaceTopology, FacesWhoseVerticesAllCameFromACutAreCutFaces) {
  // Pretend vertices 5.. were made by a cut: C's four faces and E's four
  // (on 9 to 12) qualify.
  const Extracted e = extract(5);
  int cut = 0;
  for (std::size_t f = 0; f < e.topology.num_faces(); ++f) {
    bool all_new = true;
    for (engine::VertId v : e.topology.faces[f]) all_new = all_new && v.value >= 5;
    EXPECT_EQ(e.topology.face_cut[f] == 1, all_new);
    cut += e.topology.face_cut[f];
  }
  EXPECT_EQ(cut, 8);
}

TEST(SurfaceGeometry, FlatNormalsPointOutOfTheirTetAndSmoothOnesAreUnit) {
  const Extracted e = extract(12);
  const SurfaceTopology& s = e.topology;
  std::vector<engine::Vec3> x(e.world.model.rest_position.begin(), e.world.model.rest_position.end());
  SurfaceGeometry flat, smooth;
  update_surface_geometry(s, x, Shading::kFlat, flat);
  update_surface_geometry(s, x, Shading::kSmooth, smooth);
  ASSERT_EQ(flat.corner_position.size(), 42u);
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    engine::Vec3 centre = engine::Vec3::Zero();
    for (engine::VertId v : e.world.mt.tet(s.face_tet[f])) centre += e.world.mt.position(v) / 4.0;
    const glm::vec3 face_centre = (flat.corner_position[3 * f] + flat.corner_position[3 * f + 1] +
                                   flat.corner_position[3 * f + 2]) / 3.0f;
    const glm::vec3 outward = face_centre - glm::vec3(centre.x(), centre.y(), centre.z());
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(glm::dot(flat.corner_normal[3 * f + k], outward), 0.0f) << "face " << f;
      EXPECT_NEAR(glm::length(flat.corner_normal[3 * f + k]), 1.0f, 1e-5f);
      EXPECT_NEAR(glm::length(smooth.corner_normal[3 * f + k]), 1.0f, 1e-5f);
    }
  }
  // Moving a particle moves every corner on it.
  x[s.corner_point[0]] += engine::Vec3(0, 0, 0.5);
  update_surface_geometry(s, x, Shading::kFlat, flat);
  EXPECT_FLOAT_EQ(flat.corner_position[0].z, static_cast<float>(x[s.corner_point[0]].z()));
}

}  // namespace
}  // namespace mtcut::app::view

namespace mtcut::app::view {
namespace {

// The finest surface of an organ whose coarse levels have a free boundary,
// on its coarsest frontier: corners on the finest surface's vertices, each
// face with its carrier's piece and level, and at rest every corner where
// its MT vertex rests (placed through its carrier, inside or outside it).
TEST(SurfaceTopology, TheFinestSurfaceIsDrawnAtItsVerticesThroughTheirCarriers) {
  engine::MeshLoadDef load;
  load.builtin_tets = 2000;
  engine::MtBuildOptions options;
  options.preserve_boundary = false;
  const engine::Mt mt = engine::build_mt(engine::load_mesh("builtin:ellipsoid", load).mesh, options);
  const engine::Frontier frontier = engine::Frontier::coarsest(mt);
  std::vector<engine::Tet> tets;
  for (const engine::TetId t : frontier.tets()) tets.push_back(mt.tet(t));
  const sim::SpringModel model =
      sim::build_spring_model(tets, mt.positions(), sim::MaterialDef{}, [](engine::VertId) { return false; });
  const std::vector<std::int32_t> levels = fragment_levels(mt);
  const PieceLabels pieces = label_frontier_pieces(mt, frontier);
  const SurfaceTopology s = extract_finest_surface(mt, frontier, model, pieces, levels, mt.num_vertices());
  const SurfaceTopology own = extract_surface(mt, frontier, model, pieces, levels, mt.num_vertices());
  ASSERT_TRUE(s.finest.has_value());
  EXPECT_FALSE(own.finest.has_value());
  EXPECT_EQ(s.num_faces(), s.finest->num_faces());
  EXPECT_GT(s.num_faces(), 2 * own.num_faces());  // the coarsest level's surface is coarser
  EXPECT_GT(s.finest->outside, 0u);
  EXPECT_EQ(s.pieces, 1);
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    EXPECT_EQ(s.face_piece[f], 0);
    EXPECT_EQ(s.face_level[f], levels[mt.birth(s.face_tet[f]).index()]);
    EXPECT_TRUE(frontier.has_tet(s.face_tet[f]));
  }
  std::vector<engine::Vec3> x(model.rest_position.begin(), model.rest_position.end());
  SurfaceGeometry geometry;
  update_surface_geometry(s, x, Shading::kSmooth, geometry);
  ASSERT_EQ(geometry.corner_position.size(), 3 * s.num_faces());
  for (std::size_t f = 0; f < s.num_faces(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const engine::Vec3& rest = mt.position(s.faces[f][k]);
      const glm::vec3& drawn = geometry.corner_position[3 * f + k];
      EXPECT_NEAR(drawn.x, rest.x(), 1e-6);
      EXPECT_NEAR(drawn.y, rest.y(), 1e-6);
      EXPECT_NEAR(drawn.z, rest.z(), 1e-6);
      EXPECT_NEAR(glm::length(geometry.corner_normal[3 * f + k]), 1.0f, 1e-5f);
    }
}

}  // namespace
}  // namespace mtcut::app::view
