#include "sim/world.h"

#include <gtest/gtest.h>

#include "engine/mesh_loader.h"
#include "engine/mt/mt_builder.h"

namespace mtcut::sim {
namespace {

engine::Mt organ_mt(int tets) {
  engine::MeshLoadDef load;
  load.builtin_tets = tets;
  return engine::build_mt(engine::load_mesh("builtin:ellipsoid", load).mesh);
}

WorldDef organ_def() {
  WorldDef def;
  def.fixed.kind = FixedRegion::Kind::kHalfSpace;  // the back of the organ
  def.fixed.normal = Vec3(1, 0, 0);
  def.fixed.offset = -0.06;
  def.lod.near_radius = 0.02;
  def.lod.near_error = 0.0;
  def.lod.far_radius = 0.06;
  def.lod.far_error = 1.0;
  return def;
}

// The blade sweeps along the organ with its tip at the centre plane, disengaged.
ScalpelPath sweep() {
  std::vector<ScalpelKeyframe> keys = {{0.0, {Vec3(-0.05, 0, 0.06), Vec3(-0.05, 0, 0.0), false}},
                                       {1.0, {Vec3(0.05, 0, 0.06), Vec3(0.05, 0, 0.0), false}}};
  return ScalpelPath(keys);
}

TEST(World, LodFollowsTheBladeAndEveryFrameIsValid) {
  World world(organ_mt(3000), organ_def());
  const ScalpelPath path = sweep();
  std::size_t most = 0, least = SIZE_MAX, changes = 0;
  for (int f = 0; f < 60; ++f) {
    const FrameMetrics& m = world.step(path.pose_at(world.time()));
    most = std::max(most, m.frontier_tets);
    least = std::min(least, m.frontier_tets);
    changes += m.lod_changes;
    if (f % 10 == 0) {
      const auto report = world.validate();
      ASSERT_TRUE(report.ok()) << "frame " << f << ": " << report.summary();
    }
  }
  EXPECT_GT(changes, 0u);
  EXPECT_LT(least, world.mt().num_live_tets());  // never the whole MT
  EXPECT_EQ(world.nan_events(), 0u);
  EXPECT_TRUE(world.validate().ok());
  // Near the blade the frontier is fine: the tets around the tip are the
  // finest ones (born in the root fragment).
  const Vec3 tip = path.pose_at(world.time()).tip;
  int near = 0, fine = 0;
  for (const auto t : world.frontier().tets()) {
    const auto c = world.mt().corners(t);
    if (((c[0] + c[1] + c[2] + c[3]) / 4 - tip).norm() > 0.01) continue;
    ++near;
    fine += world.mt().birth(t) == world.mt().root();
  }
  EXPECT_GT(near, 0);
  EXPECT_EQ(fine, near);
}

TEST(World, SameScenarioTwiceGivesTheSameStateHash) {
  const ScalpelPath path = sweep();
  std::uint64_t hashes[2];
  for (auto& hash : hashes) {
    World world(organ_mt(2000), organ_def());
    for (int f = 0; f < 40; ++f) world.step(path.pose_at(world.time()));
    hash = world.state_hash();
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

TEST(World, DisengagedBladePushesTissue) {
  WorldDef def = organ_def();
  def.environment.gravity.setZero();
  def.lod.enabled = false;
  def.tool_radius = 0.004;
  World world(organ_mt(2000), def);
  // The blade pressed into the top of the organ, not cutting.
  const ScalpelPose press{Vec3(0.02, 0, 0.08), Vec3(0.02, 0, 0.025), false};
  for (int f = 0; f < 10; ++f) world.step(press);
  double closest = 1;
  for (const auto& x : world.state().x) {
    const Vec3 d = x - Vec3(0.02, 0, x.z());
    if (x.z() > 0.025) closest = std::min(closest, d.norm());
  }
  EXPECT_GE(closest, def.tool_radius - 1e-9);
}

}  // namespace
}  // namespace mtcut::sim
