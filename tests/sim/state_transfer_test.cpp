#include "sim/state_transfer.h"

#include <gtest/gtest.h>

#include <random>

#include "engine/mesh_loader.h"
#include "engine/mt/mt_builder.h"
#include "sim/fixed_region.h"
#include "sim/forces.h"
#include "tests/test_paths.h"

namespace mtcut::sim {
namespace {

using engine::Frontier;
using engine::Mt;

// An affine deformation and an affine velocity field of the rest shape:
// interpolation must carry both exactly.
struct AffineField {
  Eigen::Matrix3d a;
  Vec3 b;
  Eigen::Matrix3d va;
  Vec3 vb;
  Vec3 x(const Vec3& rest) const { return a * rest + b; }
  Vec3 v(const Vec3& rest) const { return va * rest + vb; }
};

SpringState state_from(const SpringModel& model, const AffineField& field) {
  SpringState s;
  for (const auto& p : model.rest_position) {
    s.x.push_back(field.x(p));
    s.v.push_back(field.v(p));
  }
  for (std::size_t i = 0; i < model.num_particles(); ++i)
    if (model.inv_mass[i] == 0) s.v[i].setZero();
  return s;
}

SpringModel model_of(const Mt& mt, const Frontier& frontier, const MaterialDef& material, const FixedRegion& fixed) {
  std::vector<engine::Tet> tets;
  for (const auto t : frontier.tets()) tets.push_back(mt.tet(t));
  return build_spring_model(tets, mt.positions(), material,
                            [&](VertId v) { return fixed.contains(v, mt.position(v)); });
}

class TransferOnMeshes : public ::testing::TestWithParam<std::string> {};

TEST_P(TransferOnMeshes, RandomLodStepsConserveMassAndMomentumAndCarryAffineFieldsExactly) {
  engine::MeshLoadDef load;
  load.builtin_tets = 3000;
  const engine::TetMesh fine = engine::load_mesh(GetParam(), load).mesh;
  const Mt mt = engine::build_mt(fine);
  const engine::TetBvh bvh(mt);
  MaterialDef material;
  FixedRegion fixed;  // a few pinned vertices: they carry no momentum
  fixed.kind = FixedRegion::Kind::kHalfSpace;
  fixed.normal = Vec3(1, 0, 0);
  fixed.offset = fine.positions[0].x();
  for (const auto& p : fine.positions) fixed.offset = std::min(fixed.offset, p.x());
  fixed.offset += 1e-9;

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  AffineField field;
  field.a = Eigen::Matrix3d::Identity();
  for (int i = 0; i < 9; ++i) field.a(i / 3, i % 3) += u(rng);
  field.b = Vec3(u(rng), u(rng), u(rng));
  // A rigid velocity field (translation + rotation) keeps the momentum test
  // meaningful: a velocity field that is affine but not rigid is carried
  // exactly too, and then the correction must stay at round-off.
  field.va = Eigen::Matrix3d::Zero();
  field.va(0, 1) = 0.5, field.va(1, 0) = -0.5;
  field.vb = Vec3(0.1, -0.2, 0.3);

  Frontier frontier = Frontier::finest(mt);
  SpringModel model = model_of(mt, frontier, material, fixed);
  SpringState state = state_from(model, field);
  const double density_volume = material.density * fine.total_volume();
  int interpolated = 0, walked = 0;
  for (int step = 0; step < 60; ++step) {
    DeformationSnapshot snap = take_snapshot(mt, frontier, model, state);
    // Carried along: the velocities themselves and the positions (as fields
    // with no offset): they must come out as v before its momentum
    // correction, bit for bit, and as the affine x.
    snap.carried = {snap.v, snap.x};
    // A random batch of refine / coarsen operations.
    for (int k = 0; k < 8; ++k) {
      const bool coarsen = rng() % 3 != 0;
      const auto options = coarsen ? frontier.coarsenable(mt) : frontier.refinable(mt);
      if (options.empty()) continue;
      const auto f = options[rng() % options.size()];
      coarsen ? frontier.coarsen(mt, f) : frontier.refine(mt, f);
    }
    ASSERT_TRUE(engine::validate_frontier(mt, frontier).ok());
    model = model_of(mt, frontier, material, fixed);
    ASSERT_TRUE(model.validate().ok()) << model.validate().summary();
    TransferReport report;
    std::vector<std::vector<Vec3>> carried;
    state = transfer_state(mt, bvh, snap, model, {}, &report, &carried);
    interpolated += static_cast<int>(report.interpolated);
    // The same through the DAG from the model's tets: the same state up to
    // round-off (a vertex on a face shared by two old tets may take either).
    TransferReport walk_report;
    std::vector<std::vector<Vec3>> walk_carried;
    const SpringState walk_state =
        transfer_state(mt, bvh, snap, model, {}, &walk_report, &walk_carried, frontier.tets());
    EXPECT_EQ(walk_report.kept, report.kept) << "step " << step;
    EXPECT_EQ(walk_report.interpolated, report.interpolated) << "step " << step;
    EXPECT_EQ(report.walked, 0u) << "step " << step;
    walked += static_cast<int>(walk_report.walked);
    for (std::size_t p = 0; p < model.num_particles(); ++p) {
      ASSERT_LT((walk_state.x[p] - state.x[p]).norm(), 1e-12) << "step " << step << " particle " << p;
      ASSERT_LT((walk_state.v[p] - state.v[p]).norm(), 1e-12) << "step " << step << " particle " << p;
    }
    ASSERT_EQ(carried.size(), 2u);
    for (const auto& field_values : carried) ASSERT_EQ(field_values.size(), model.num_particles());
    for (std::size_t p = 0; p < model.num_particles(); ++p) {
      if (model.inv_mass[p] != 0) {
        const Vec3 corrected = carried[0][p] + report.momentum_correction;
        ASSERT_EQ(corrected, state.v[p]) << "step " << step << " particle " << p;
      }
      ASSERT_LT((carried[1][p] - field.x(model.rest_position[p])).norm(), 1e-9) << "step " << step << " particle " << p;
    }

    EXPECT_NEAR(model.total_mass, density_volume, 1e-12 * density_volume) << "step " << step;
    const Vec3 momentum = linear_momentum(model, state);
    EXPECT_LT((momentum - snap.momentum).norm(), 1e-9 * std::max(1e-12, snap.momentum.norm())) << "step " << step;
    for (std::size_t p = 0; p < model.num_particles(); ++p) {
      const Vec3& rest = model.rest_position[p];
      ASSERT_LT((state.x[p] - field.x(rest)).norm(), 1e-9) << "step " << step << " particle " << p;
    }
    EXPECT_EQ(report.extrapolated, 0u);
  }
  EXPECT_GT(interpolated, 0);  // refinements did bring vertices back
  EXPECT_GE(walked, interpolated * 9 / 10);  // the DAG found (nearly) all of them
}

std::string mesh_name(const ::testing::TestParamInfo<std::string>& param) {
  return param.index == 0 ? "Ellipsoid" : "LiverMsh";
}

INSTANTIATE_TEST_SUITE_P(Meshes, TransferOnMeshes,
                         ::testing::Values(std::string("builtin:ellipsoid"), mtcut::test::shared_mesh("liver.msh")),
                         mesh_name);

TEST(StateTransfer, CutVerticesComeFromTheirParents) {
  engine::MeshLoadDef load;
  load.builtin_tets = 300;
  const engine::TetMesh fine = engine::load_mesh("builtin:box", load).mesh;
  Mt mt = engine::build_mt(fine);
  const Frontier frontier = Frontier::finest(mt);
  const SpringModel model = model_of(mt, frontier, {}, {});
  SpringState state = rest_state(model);
  for (std::size_t p = 0; p < state.x.size(); ++p) state.x[p] += Vec3(0, 0, 0.1 * static_cast<double>(p));
  const DeformationSnapshot snap = take_snapshot(mt, frontier, model, state);
  const engine::TetBvh bvh(mt);
  const VertId a = mt.tet(frontier.tets()[0])[0], b = mt.tet(frontier.tets()[0])[1];
  const VertId made = mt.add_vertex(0.75 * mt.position(a) + 0.25 * mt.position(b));
  cut::MadeVertex record;
  record.id = made;
  record.parents = {a, b, VertId(), VertId()};
  record.weights = {0.75, 0.25, 0, 0};
  const auto [x, v] = sample_vertex(mt, bvh, snap, made, std::span<const cut::MadeVertex>(&record, 1));
  const Vec3 xa = state.x[static_cast<std::size_t>(snap.particle_of[a.index()])];
  const Vec3 xb = state.x[static_cast<std::size_t>(snap.particle_of[b.index()])];
  EXPECT_LT((x - (0.75 * xa + 0.25 * xb)).norm(), 1e-15);
  EXPECT_EQ(v, Vec3::Zero());
}

TEST(StateTransfer, CarriedVectorsOfTheWrongShapeAndMadeVerticesOutOfOrderAreRefused) {
  engine::MeshLoadDef load;
  load.builtin_tets = 300;
  const engine::TetMesh fine = engine::load_mesh("builtin:box", load).mesh;
  const Mt mt = engine::build_mt(fine);
  const Frontier frontier = Frontier::finest(mt);
  const SpringModel model = model_of(mt, frontier, {}, {});
  const engine::TetBvh bvh(mt);
  DeformationSnapshot snap = take_snapshot(mt, frontier, model, rest_state(model));
  snap.carried.assign(DeformationSnapshot::kMaxCarried + 1, snap.v);
  EXPECT_THROW(transfer_state(mt, bvh, snap, model), std::invalid_argument);
  snap.carried = {std::vector<Vec3>(model.num_particles() + 1, Vec3::Zero())};
  EXPECT_THROW(transfer_state(mt, bvh, snap, model), std::invalid_argument);
  snap.carried = {snap.v};
  EXPECT_NO_THROW(transfer_state(mt, bvh, snap, model));
  // The made vertices are looked up by id: they must come in ascending order.
  std::vector<cut::MadeVertex> made(2);
  made[0].id = VertId(static_cast<std::int32_t>(mt.num_vertices()) + 1);
  made[1].id = VertId(static_cast<std::int32_t>(mt.num_vertices()));
  EXPECT_THROW(transfer_state(mt, bvh, snap, model, made), std::invalid_argument);
  std::swap(made[0], made[1]);
  EXPECT_NO_THROW(transfer_state(mt, bvh, snap, model, made));
}

}  // namespace
}  // namespace mtcut::sim
