#include "app/view/surface_topology.h"

#include <gtest/gtest.h>

#include <set>

#include "app/fragment_levels.h"
#include "app/view/surface_geometry.h"
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
  EXPECT_EQ(s.corner_particle.size(), 42u);
  std::multiset<int> per_piece;
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    per_piece.insert(s.face_piece[f]);
    EXPECT_EQ(s.face_cut[f], 0);
    EXPECT_EQ(s.face_level[f], 0);  // all made by the root
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(e.world.model.particle_vertex[s.corner_particle[3 * f + k]], s.faces[f][k]);
  }
  EXPECT_EQ(per_piece.count(0), 6u);
  EXPECT_EQ(per_piece.count(1), 4u);
  EXPECT_EQ(per_piece.count(2), 4u);
  EXPECT_EQ(s.groups, 12);  // every vertex is on the surface, none on a cut
}

TEST(SurfaceTopology, FacesWhoseVerticesAllCameFromACutAreCutFaces) {
  // Pretend vertices 5.. were made by a cut: C's four faces qualify, and
  // E's faces (holding vertex 0) only the one without vertex 0.
  const Extracted e = extract(5);
  int cut = 0;
  for (std::size_t f = 0; f < e.topology.num_faces(); ++f) {
    bool all_new = true;
    for (engine::VertId v : e.topology.faces[f]) all_new = all_new && v.value >= 5;
    EXPECT_EQ(e.topology.face_cut[f] == 1, all_new);
    cut += e.topology.face_cut[f];
  }
  EXPECT_EQ(cut, 5);
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
      // Vertex 0, where A and its mirror image E touch: their normals cancel.
      if (s.faces[f][k].value != 0) {
        EXPECT_NEAR(glm::length(smooth.corner_normal[3 * f + k]), 1.0f, 1e-5f);
      }
    }
  }
  // Moving a particle moves every corner on it.
  x[s.corner_particle[0]] += engine::Vec3(0, 0, 0.5);
  update_surface_geometry(s, x, Shading::kFlat, flat);
  EXPECT_FLOAT_EQ(flat.corner_position[0].z, static_cast<float>(x[s.corner_particle[0]].z()));
}

}  // namespace
}  // namespace mtcut::app::view
