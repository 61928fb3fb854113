#include "sim/spring_model_update.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "engine/mesh_loader.h"
#include "engine/mt/bvh.h"
#include "engine/tet_geometry.h"
#include "sim/fixed_region.h"
#include "tests/test_paths.h"

namespace mtcut::sim {
namespace {

// Every array and figure of the two models, bit for bit.
void expect_same_bits(const SpringModel& a, const SpringModel& b, const std::string& where) {
  EXPECT_EQ(a.particle_vertex, b.particle_vertex) << where;
  EXPECT_EQ(a.mass, b.mass) << where;
  EXPECT_EQ(a.inv_mass, b.inv_mass) << where;
  EXPECT_EQ(a.rest_position, b.rest_position) << where;
  EXPECT_EQ(a.spring_a, b.spring_a) << where;
  EXPECT_EQ(a.spring_b, b.spring_b) << where;
  EXPECT_EQ(a.rest_length, b.rest_length) << where;
  EXPECT_EQ(a.stiffness, b.stiffness) << where;
  EXPECT_EQ(a.damping, b.damping) << where;
  EXPECT_EQ(a.tet_particles, b.tet_particles) << where;
  EXPECT_EQ(a.rest_volume, b.rest_volume) << where;
  EXPECT_EQ(a.volume_modulus, b.volume_modulus) << where;
  EXPECT_EQ(a.mass_damping, b.mass_damping) << where;
  EXPECT_EQ(a.total_mass, b.total_mass) << where;
  EXPECT_TRUE(a.particle_volume == b.particle_volume) << where;  // 128-bit: gtest cannot print them
  EXPECT_EQ(a.particle_tets, b.particle_tets) << where;
  EXPECT_TRUE(a.spring_volume == b.spring_volume) << where;
  EXPECT_EQ(a.spring_tets, b.spring_tets) << where;
  EXPECT_EQ(a.order_lo, b.order_lo) << where;
  EXPECT_EQ(a.order_hi, b.order_hi) << where;
}

// Splits tet t at its centroid into four (a new vertex, appended), as a cut
// makes vertices inside the body.
std::vector<engine::Tet> split_at_centroid(const engine::Tet& t, std::vector<Vec3>& positions) {
  const VertId c(static_cast<std::int32_t>(positions.size()));
  positions.push_back(0.25 * (positions[t[0].index()] + positions[t[1].index()] + positions[t[2].index()] +
                              positions[t[3].index()]));
  return {{c, t[1], t[2], t[3]}, {t[0], c, t[2], t[3]}, {t[0], t[1], c, t[3]}, {t[0], t[1], t[2], c}};
}

// Random changes of a tet set on the shared meshes (drop and bring back
// random tets and a ball of them, split tets at new vertices): after each,
// the update gives the build's model bit for bit, with and without the
// volume terms and a fixed region.
class SpringModelUpdateOnMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(SpringModelUpdateOnMesh, GivesTheBuildsBitsOverRandomChanges) {
  const engine::TetMesh mesh = engine::load_mesh(mtcut::test::shared_mesh(GetParam()), {}).mesh;
  engine::Aabb box;
  for (const Vec3& p : mesh.positions) box.extend(p);
  const double diagonal = (box.hi - box.lo).norm();
  std::size_t changed = 0;
  for (const double volume_stiffness : {0.0, 0.5}) {
    MaterialDef material;
    material.youngs_modulus = 4321;
    material.volume_stiffness = volume_stiffness;
    std::vector<Vec3> positions(mesh.positions.begin(), mesh.positions.end());
    const double x_fixed = 0.8 * positions[0].x() + 0.2 * positions[1].x();
    const auto is_fixed = [&](VertId v) { return positions[v.index()].x() < x_fixed; };
    std::mt19937 rng(29);
    std::vector<engine::Tet> in = mesh.tets;  // the model's tets
    std::vector<engine::Tet> out;             // tets that left, to bring back
    SpringModel model = build_spring_model(in, positions, material, is_fixed);
    for (int step = 0; step < 30; ++step) {
      const std::string where = "volume term " + std::to_string(volume_stiffness) + ", step " + std::to_string(step);
      std::vector<engine::Tet> removed, added;
      // A ball of tets around a random one leaves; some random ones too.
      const Vec3 centre = positions[in[rng() % in.size()][0].index()];
      const double radius = diagonal * (0.03 + 0.005 * static_cast<double>(rng() % 30));
      std::vector<engine::Tet> kept;
      for (const engine::Tet& t : in) {
        const bool leaves = (positions[t[0].index()] - centre).norm() < radius || rng() % 200 == 0;
        (leaves ? removed : kept).push_back(t);
      }
      // Some that left earlier come back, and a few tets are split.
      std::shuffle(out.begin(), out.end(), rng);
      const std::size_t back = out.size() / 2;
      added.assign(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(back));
      out.erase(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(back));
      for (int k = 0; k < 5 && !kept.empty(); ++k) {
        const std::size_t i = rng() % kept.size();
        const engine::Tet split = kept[i];
        kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(i));
        removed.push_back(split);
        for (const engine::Tet& piece : split_at_centroid(split, positions)) added.push_back(piece);
      }
      for (const engine::Tet& t : removed)
        if (std::find(added.begin(), added.end(), t) == added.end()) out.push_back(t);
      changed += removed.size() + added.size();
      in = kept;
      in.insert(in.end(), added.begin(), added.end());
      std::shuffle(in.begin(), in.end(), rng);  // the frontier's order is its own

      const std::optional<SpringModel> updated =
          update_spring_model(model, removed, added, in, positions, material, is_fixed);
      ASSERT_TRUE(updated.has_value()) << where;
      ASSERT_TRUE(updated->validate().ok()) << where << ": " << updated->validate().problems.front();
      const SpringModel built = build_spring_model(in, positions, material, is_fixed);
      expect_same_bits(*updated, built, where);
      if (::testing::Test::HasFailure()) return;
      model = *updated;
    }
    EXPECT_GT(model.num_fixed(), 0u);
  }
  EXPECT_GT(changed, 2 * mesh.tets.size());  // the changes are not trivial
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, SpringModelUpdateOnMesh,
                         ::testing::Values("liver.msh", "Armadillo_Tetra_4406.vtu"));

// The particles' order is keyed in the box of all rest positions: a vertex
// past it changes every key, and the update declines (the caller builds).
TEST(SpringModelUpdate, DeclinesWhenTheRestPositionsOutgrowTheOrderBox) {
  std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<engine::Tet> tets = {{VertId(0), VertId(1), VertId(2), VertId(3)}};
  const MaterialDef material;
  const SpringModel model = build_spring_model(tets, positions, material);
  positions.push_back({2, 2, 2});
  const std::vector<engine::Tet> grown = {{VertId(4), VertId(1), VertId(2), VertId(3)}};
  EXPECT_FALSE(update_spring_model(model, tets, grown, grown, positions, material).has_value());
  positions.back() = {0.1, 0.1, 0.1};  // inside: the update serves
  const std::vector<engine::Tet> inside = {{VertId(4), VertId(1), VertId(2), VertId(3)}};
  const auto updated = update_spring_model(model, tets, inside, inside, positions, material);
  ASSERT_TRUE(updated.has_value());
  expect_same_bits(*updated, build_spring_model(inside, positions, material), "inside");
}

// A removed tet must be one of the model's: a vertex, an edge or a tet it
// does not have is refused, as is one removed twice, and a tet's vertices
// must have rest positions.
TEST(SpringModelUpdate, RefusesToRemoveWhatTheModelDoesNotHave) {
  const std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {-1, -1, 1}};
  const engine::Tet a{VertId(0), VertId(1), VertId(2), VertId(3)};
  const engine::Tet b{VertId(1), VertId(2), VertId(3), VertId(4)};
  const engine::Tet unknown_vertex{VertId(0), VertId(1), VertId(2), VertId(5)};
  const engine::Tet unknown_edge{VertId(0), VertId(1), VertId(4), VertId(2)};
  const engine::Tet out_of_range{VertId(1), VertId(2), VertId(3), VertId(6)};
  const MaterialDef material;
  const std::vector<engine::Tet> tets = {a, b};
  const SpringModel model = build_spring_model(tets, positions, material);
  const std::vector<engine::Tet> none;
  for (const std::vector<engine::Tet>& removed :
       {std::vector<engine::Tet>{unknown_vertex}, std::vector<engine::Tet>{unknown_edge},
        std::vector<engine::Tet>{a, a}}) {
    EXPECT_THROW(update_spring_model(model, removed, none, none, positions, material), std::invalid_argument);
  }
  const std::vector<engine::Tet> added_out_of_range = {out_of_range};
  EXPECT_THROW(update_spring_model(model, none, added_out_of_range, added_out_of_range, positions, material),
               std::invalid_argument);
  const auto only_b = update_spring_model(model, std::vector<engine::Tet>{a}, none, {&b, 1}, positions, material);
  ASSERT_TRUE(only_b.has_value());
  EXPECT_EQ(only_b->num_particles(), 4u);
  EXPECT_EQ(only_b->num_springs(), 6u);
  expect_same_bits(*only_b, build_spring_model({&b, 1}, positions, material), "only b");
}

}  // namespace
}  // namespace mtcut::sim
