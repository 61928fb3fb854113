#include "sim/spring_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <utility>

#include "engine/mesh_loader.h"
#include "engine/tet_adjacency.h"
#include "engine/tet_geometry.h"
#include "sim/fixed_region.h"
#include "tests/sim/test_box.h"
#include "tests/test_paths.h"

namespace mtcut::sim {
namespace {

using test::box_mesh;

TEST(SpringModel, OneSpringPerEdgeAndExactMass) {
  const engine::TetMesh mesh = engine::load_mesh(mtcut::test::shared_mesh("liver.msh"), {}).mesh;
  MaterialDef material;
  const SpringModel model = build_spring_model(mesh.tets, mesh.positions, material);
  const auto report = model.validate();
  ASSERT_TRUE(report.ok()) << report.summary();
  EXPECT_NEAR(model.total_mass, material.density * mesh.total_volume(), 1e-12 * model.total_mass);
  // Euler for a tet mesh of a ball: V - E + F - T = 1.
  const std::size_t faces = (4 * mesh.num_tets() + engine::build_adjacency(mesh).boundary.size()) / 2;
  EXPECT_EQ(static_cast<long>(model.num_particles()) - static_cast<long>(model.num_springs()) +
                static_cast<long>(faces) - static_cast<long>(mesh.num_tets()),
            1);
}

// A body beyond the fixed-point volume sums (a mesh in millimetres read as
// metres) is refused with the fact and a hint at the mesh's unit; the
// advice in a command line's terms is the app's.
TEST(SpringModel, ABodyTooLargeForTheVolumeSumsIsRefusedWithAUnitsHint) {
  const engine::TetMesh mesh = box_mesh(50, Vec3(100, 60, 50));
  try {
    (void)build_spring_model(mesh.tets, mesh.positions, MaterialDef{});
    FAIL() << "a body of 300000 m^3 was built";
  } catch (const engine::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("m^3, is beyond what the spring model holds; the mesh's coordinates may be millimetres or "
                     "centimetres"),
              std::string::npos)
        << m;
    EXPECT_EQ(m.find("--"), std::string::npos) << m;
    EXPECT_EQ(m.find("[mesh]"), std::string::npos) << m;
    EXPECT_EQ(e.hint().kind, engine::InputHint::Kind::kUnits);
    EXPECT_TRUE(e.hint().unit.empty());
  }
}

// The implicit solver's Gauss-Seidel sweeps walk the springs grouped by
// first particle: build_spring_model emits them sorted by (a, b).
TEST(SpringModel, SpringsAreSortedByFirstThenSecondParticle) {
  const engine::TetMesh mesh = box_mesh(400, Vec3(0.1, 0.05, 0.05));
  const SpringModel model = build_spring_model(mesh.tets, mesh.positions, MaterialDef{});
  ASSERT_GT(model.num_springs(), 1u);
  for (std::size_t s = 1; s < model.num_springs(); ++s)
    EXPECT_TRUE(model.spring_a[s - 1] < model.spring_a[s] ||
                (model.spring_a[s - 1] == model.spring_a[s] && model.spring_b[s - 1] < model.spring_b[s]))
        << "spring " << s;
}

// Against a plain reference on the real liver and on random subsets of its
// tets (as a frontier uses some of the MT's vertices): one spring per
// distinct edge, and its stiffness E * (sum of its tets' volumes) / |e|^2
// with each volume rounded to fixed point and summed exactly (fixed_volume.h), bit for bit (a tet's volume scaled
// by |e|^2 / (kShortEdgeFloor L_T)^2 for an edge below the floor, which
// this liver has none of: AShortEdgeCountsAsTheFloorInVanGelder).
TEST(SpringModel, SpringsMatchAReferenceOnTheLiverAndItsSubsets) {
  const engine::TetMesh mesh = engine::load_mesh(mtcut::test::shared_mesh("liver.msh"), {}).mesh;
  MaterialDef material;
  material.youngs_modulus = 4321;
  std::mt19937 rng(17);
  for (const double keep : {1.0, 0.6, 0.15}) {
    std::bernoulli_distribution kept(keep);
    std::vector<engine::Tet> tets;
    for (const engine::Tet& t : mesh.tets)
      if (kept(rng)) tets.push_back(t);
    const SpringModel model = build_spring_model(tets, mesh.positions, material);
    ASSERT_TRUE(model.validate().ok()) << keep;

    std::map<std::pair<VertId, VertId>, FixedVolume> volume_of;  // by MT vertex ids, exact sums
    for (const engine::Tet& t : tets) {
      const double vol = engine::signed_volume(mesh.position(t[0]), mesh.position(t[1]), mesh.position(t[2]),
                                               mesh.position(t[3]));
      double longest2 = 0;
      for (const auto& e : engine::kTetEdges)
        longest2 = std::max(longest2, (mesh.position(t[e[0]]) - mesh.position(t[e[1]])).squaredNorm());
      const double shortest2 = kShortEdgeFloor * kShortEdgeFloor * longest2;
      for (const auto& e : engine::kTetEdges) {
        const double length2 = (mesh.position(t[e[0]]) - mesh.position(t[e[1]])).squaredNorm();
        volume_of[std::minmax(t[e[0]], t[e[1]])] +=
            to_fixed_volume(length2 < shortest2 ? vol * (length2 / shortest2) : vol);
      }
    }
    ASSERT_EQ(model.num_springs(), volume_of.size()) << keep;
    for (std::size_t s = 0; s < model.num_springs(); ++s) {
      const VertId a = model.particle_vertex[static_cast<std::size_t>(model.spring_a[s])];
      const VertId b = model.particle_vertex[static_cast<std::size_t>(model.spring_b[s])];
      const auto it = volume_of.find(std::minmax(a, b));
      ASSERT_NE(it, volume_of.end()) << "spring " << s;
      const double l = (mesh.position(a) - mesh.position(b)).norm();
      EXPECT_EQ(model.rest_length[s], l) << s;
      EXPECT_EQ(model.stiffness[s], material.youngs_modulus * to_double(it->second) / (l * l)) << s;
      volume_of.erase(it);  // each edge once
    }
  }
}

TEST(SpringModel, VanGelderStiffnessOfOneTet) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<engine::Tet> tets = {{VertId(0), VertId(1), VertId(2), VertId(3)}};
  MaterialDef material;
  material.youngs_modulus = 600;
  const SpringModel model = build_spring_model(tets, p, material);
  ASSERT_EQ(model.num_springs(), 6u);
  for (std::size_t s = 0; s < 6; ++s) {
    const double l = model.rest_length[s];
    EXPECT_NEAR(model.stiffness[s], 600.0 * (1.0 / 6.0) / (l * l), 1e-12);
    EXPECT_NEAR(model.damping[s], material.stiffness_damping * model.stiffness[s], 1e-15);
  }
}

// A sliver: one edge of length eps, the others about 1. Its short spring
// counts the edge as kShortEdgeFloor * sqrt(2) long (the longest edge), so
// its stiffness shrinks with the sliver's volume (eps / 6) as the masses
// at its ends do, where E vol / eps^2 would grow as 1 / eps; the long
// edges keep E vol / |e|^2. An edge above the floor is not touched.
TEST(SpringModel, AShortEdgeCountsAsTheFloorInVanGelder) {
  MaterialDef material;
  material.youngs_modulus = 600;
  for (const double eps : {0.5, 1e-3, 1e-6}) {
    const std::vector<Vec3> p = {{0, 0, 0}, {eps, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<engine::Tet> tets = {{VertId(0), VertId(1), VertId(2), VertId(3)}};
    const SpringModel model = build_spring_model(tets, p, material);
    ASSERT_TRUE(model.validate().ok());
    const double vol = eps / 6, floor = kShortEdgeFloor * std::sqrt(2.0);
    std::size_t short_springs = 0;
    for (std::size_t s = 0; s < model.num_springs(); ++s) {
      const double l = model.rest_length[s];
      const double counted = std::max(l, floor);
      short_springs += l < floor;
      EXPECT_NEAR(model.stiffness[s], 600.0 * vol / (counted * counted), 1e-12 * model.stiffness[s]) << eps << " " << s;
    }
    EXPECT_EQ(short_springs, eps < floor ? 1u : 0u) << eps;
    const double smallest_mass = *std::min_element(model.mass.begin(), model.mass.end());
    const double stiffest = *std::max_element(model.stiffness.begin(), model.stiffness.end());
    // k / m bounded as the sliver thins: E / (density floor^2) times a constant.
    EXPECT_LT(stiffest / smallest_mass, 4 * 600.0 / (material.density * floor * floor) * 2.01) << eps;
  }
}

TEST(SpringModel, FixedRegionPinsParticlesInRestSpace) {
  const engine::TetMesh mesh = box_mesh(500, Vec3(0.2, 0.02, 0.02));
  FixedRegion region;
  region.kind = FixedRegion::Kind::kHalfSpace;
  region.normal = Vec3(1, 0, 0);
  region.offset = -0.1 + 1e-9;  // the face at x = -0.1
  const SpringModel model =
      build_spring_model(mesh.tets, mesh.positions, {}, [&](VertId v) { return region.contains(v, mesh.position(v)); });
  ASSERT_TRUE(model.validate().ok());
  EXPECT_GT(model.num_fixed(), 3u);
  for (std::size_t i = 0; i < model.num_particles(); ++i)
    EXPECT_EQ(model.inv_mass[i] == 0, model.rest_position[i].x() < -0.1 + 1e-9) << i;
}

TEST(SpringModel, ValidateCatchesBrokenModels) {
  const engine::TetMesh mesh = box_mesh(100, Vec3(1, 1, 1));
  SpringModel model = build_spring_model(mesh.tets, mesh.positions, {});
  model.mass[0] *= 2;
  EXPECT_FALSE(model.validate().ok());
  model = build_spring_model(mesh.tets, mesh.positions, {});
  model.spring_b[0] = model.spring_a[0];
  EXPECT_FALSE(model.validate().ok());
}

}  // namespace
}  // namespace mtcut::sim
