#include "sim/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>

#include "engine/mesh_loader.h"
#include "engine/mt/frontier.h"
#include "engine/mt/mt_builder.h"
#include "tests/sim/organ_world.h"

namespace mtcut::sim {
namespace {

using test::flap_def;
using test::flap_stroke;
using test::organ_def;

engine::Mt organ_mt(int tets) {
  engine::MeshLoadDef load;
  load.builtin_tets = tets;
  return engine::build_mt(engine::load_mesh("builtin:ellipsoid", load).mesh);
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
    const auto report = world.validate();
    ASSERT_TRUE(report.ok()) << "frame " << f << ": " << report.summary();
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

// The flap stroke's poses in one frame (a trace sampled slower than the
// blade moves, or a script's whole stroke): its polygon is one cut for
// good, which a budget spreads over the frames after it (a part cut
// progressively is cut frame by frame, each frame whole:
// TimeCriticalCutter::run). Then the blade stays away, disengaged.
std::vector<ScalpelPose> flap_in_one_frame() {
  return {{Vec3(0.04, -0.06, 0.06), Vec3(0.04, -0.06, -0.07), true},
          {Vec3(0.04, 0.06, 0.06), Vec3(0.04, 0.06, -0.07), true},
          {Vec3(0.04, 0.06, 0.06), Vec3(0.04, 0.06, -0.07), false}};
}
const ScalpelPose kAway{Vec3(0.04, 0.06, 0.06), Vec3(0.04, 0.06, -0.07), false};

// A tet as its corners' rest positions, sorted: what it is whatever the
// numbering (the cutter reclaims dead slots and renumbers, at frames that
// depend on its budget).
using TetCorners = std::array<std::array<double, 3>, 4>;
TetCorners tet_corners(const engine::Mt& mt, engine::TetId t) {
  TetCorners c;
  for (int i = 0; i < 4; ++i) {
    const Vec3& p = mt.position(mt.tet(t)[i]);
    c[static_cast<std::size_t>(i)] = {p.x(), p.y(), p.z()};
  }
  std::sort(c.begin(), c.end());
  return c;
}

// The MT's live tets, up to numbering, sorted.
std::vector<TetCorners> mt_contents(const engine::Mt& mt) {
  std::vector<TetCorners> tets;
  for (std::size_t t = 0; t < mt.num_tets(); ++t)
    if (mt.alive(engine::TetId(t))) tets.push_back(tet_corners(mt, engine::TetId(t)));
  std::sort(tets.begin(), tets.end());
  return tets;
}

// The frontier's tets, up to numbering, sorted.
std::vector<TetCorners> frontier_contents(const engine::Mt& mt, const engine::Frontier& frontier) {
  std::vector<TetCorners> tets;
  for (const engine::TetId t : frontier.tets()) tets.push_back(tet_corners(mt, t));
  std::sort(tets.begin(), tets.end());
  return tets;
}

TEST(World, StrokeCutsOffAFlapThatFallsToTheFloor) {
  World world(organ_mt(3000), flap_def());
  const ScalpelPath path = flap_stroke(0.5);
  const std::size_t vertices_before = world.mt().num_vertices();
  for (int f = 0; f < 120; ++f) {
    world.step(path.pose_at(world.time()));
    const auto report = world.validate();
    ASSERT_TRUE(report.ok()) << "frame " << f << ": " << report.summary();
  }
  EXPECT_GT(world.mt().num_vertices(), vertices_before);
  EXPECT_EQ(world.pieces(), 2u);
  EXPECT_EQ(world.nan_events(), 0u);
  // The flap (rest x > 4 cm) lies on the floor; the part held at the back
  // (rest x < -6 cm) did not move.
  double flap_lowest = 1, flap_mean_z = 0;
  std::size_t flap = 0;
  for (std::size_t p = 0; p < world.model().num_particles(); ++p) {
    const Vec3& rest = world.mt().position(world.model().particle_vertex[p]);
    const Vec3& x = world.state().x[p];
    if (rest.x() > 0.045) {
      flap_lowest = std::min(flap_lowest, x.z());
      flap_mean_z += x.z();
      ++flap;
    }
    if (rest.x() < -0.065) {
      EXPECT_EQ(x, rest);
    }
  }
  ASSERT_GT(flap, 0u);
  flap_mean_z /= static_cast<double>(flap);
  EXPECT_NEAR(flap_lowest, -0.05, 0.002);
  EXPECT_LT(flap_mean_z, -0.03);  // the flap's rest centre is near z = 0
}

TEST(World, TinyCutBudgetEndsWithTheSameMtAndFreezesTheFrontier) {
  const std::vector<ScalpelPose> stroke = flap_in_one_frame();
  // On the finest frontier only the root is visible: every other
  // fragment's job waits for later frames under a small budget.
  WorldDef def = flap_def();
  def.lod.enabled = false;
  WorldDef tiny_def = def;
  tiny_def.cut_budget = {CutBudgetDef::Unit::kTets, 20};
  World unlimited(organ_mt(2000), def), tiny(organ_mt(2000), tiny_def);
  int frozen_frames = 0;
  for (int f = 0; f < 80; ++f) {
    const std::span<const ScalpelPose> poses = f == 0 ? std::span(stroke) : std::span(&kAway, 1);
    unlimited.step(poses);
    const std::size_t tets_before = tiny.frontier().tets().size();
    const std::uint64_t version = tiny.frontier().version();
    const FrameMetrics& m = tiny.step(poses);
    if (m.frozen) {
      ++frozen_frames;
      EXPECT_EQ(m.lod_changes, 0u);
      // Only the cutter changed the frontier: it is not a refine/coarsen.
      if (m.cut_tets == 0) {
        EXPECT_EQ(tiny.frontier().version(), version);
        EXPECT_EQ(tiny.frontier().tets().size(), tets_before);
      }
    }
  }
  EXPECT_GT(frozen_frames, 3);  // the hidden fragments' jobs waited
  EXPECT_FALSE(tiny.cutter().frozen());  // the queue drained
  EXPECT_TRUE(mt_contents(tiny.mt()) == mt_contents(unlimited.mt()));
  EXPECT_EQ(tiny.pieces(), unlimited.pieces());
  EXPECT_TRUE(tiny.validate().ok());
}

// A vertical blade at (x, y), engaged or not (the organ spans |z| < 3.5 cm).
ScalpelPose blade_at(double x, double y, bool engaged = true) {
  return {Vec3(x, y, 0.06), Vec3(x, y, -0.07), engaged};
}

// An L-shaped stroke as samples: along y at x = 4 cm from y = -6 cm to the
// corner at y = 0, then along x at y = 0 back to x = -2 cm, engaged.
std::vector<ScalpelPose> l_stroke() {
  std::vector<ScalpelPose> poses;
  for (int k = 0; k <= 8; ++k) poses.push_back(blade_at(0.04, -0.06 + 0.06 * k / 8));
  for (int k = 1; k <= 8; ++k) poses.push_back(blade_at(0.04 - 0.06 * k / 8, 0.0));
  return poses;
}

// Runs the frames (each a list of poses), validating after each, then
// frames with the blade lifted until the cutter's queue drains; returns the
// rest positions of the MT vertices the cuts made that live tets use (a
// retracted provisional cut's are left unused).
std::vector<Vec3> made_vertices(const std::vector<std::vector<ScalpelPose>>& frames,
                                const WorldDef& def = organ_def()) {
  World world(organ_mt(2000), def);
  const std::size_t before = world.mt().num_vertices();
  for (const auto& poses : frames) {
    world.step(poses);
    const auto report = world.validate();
    EXPECT_TRUE(report.ok()) << "frame " << world.frame() << ": " << report.summary();
  }
  const ScalpelPose lifted = blade_at(-0.02, 0.0, false);
  for (int f = 0; f < 40 && (f < 2 || world.cutter().frozen()); ++f) world.step(lifted);
  EXPECT_FALSE(world.cutter().frozen());
  EXPECT_TRUE(world.validate().ok());
  EXPECT_EQ(world.nan_events(), 0u);
  std::vector<char> used(world.mt().num_vertices(), 0);
  for (std::size_t t = 0; t < world.mt().num_tets(); ++t)
    if (world.mt().alive(engine::TetId(t)))
      for (engine::VertId v : world.mt().tet(engine::TetId(t))) used[v.index()] = 1;
  std::vector<Vec3> out;
  for (std::size_t v = before; v < used.size(); ++v)
    if (used[v]) out.push_back(world.mt().position(engine::VertId(v)));
  return out;
}

// Made vertices near the middle of the first leg (the plane x = 4 cm) and of
// the second (y = 0), away from the corner and the ends.
std::pair<int, int> near_legs(const std::vector<Vec3>& made) {
  int first = 0, second = 0;
  for (const Vec3& p : made) {
    first += std::abs(p.x() - 0.04) < 0.003 && p.y() > -0.035 && p.y() < -0.01;
    second += std::abs(p.y()) < 0.003 && p.x() > -0.005 && p.x() < 0.025;
  }
  return {first, second};
}

TEST(World, AStrokeThatTurnsWithinOneFrameIsCutAlongBothLegsNotItsChord) {
  const std::vector<ScalpelPose> stroke = l_stroke();
  // The whole L in one frame, as the HID hands a fast stroke's samples.
  const std::vector<Vec3> polyline = made_vertices({stroke});
  // Only the frame's last pose after the first: the blade jumps along the chord.
  const std::vector<Vec3> chord = made_vertices({{stroke.front()}, {stroke.back()}});

  ASSERT_FALSE(chord.empty()) << "the chord itself cuts";
  EXPECT_EQ(near_legs(chord), std::make_pair(0, 0));
  const auto [first, second] = near_legs(polyline);
  EXPECT_GT(first, 0) << "the first leg was not cut";
  EXPECT_GT(second, 0) << "the second leg was not cut";
}

// The same L at 2 mm a frame, without gravity (the tissue stays where it
// rests, so its cut vertices lie on the legs in rest space too): each leg is
// cut while the blade moves along it (the part in progress provisionally),
// and both are cut in the end.
TEST(World, AStrokeThatTurnsAcrossFramesIsCutAlongBothLegs) {
  std::vector<std::vector<ScalpelPose>> frames;
  for (int k = 0; k <= 30; ++k) frames.push_back({blade_at(0.04, -0.06 + 0.06 * k / 30)});
  for (int k = 1; k <= 30; ++k) frames.push_back({blade_at(0.04 - 0.06 * k / 30, 0.0)});
  WorldDef def = organ_def();
  def.environment.gravity = Vec3::Zero();
  const auto [first, second] = near_legs(made_vertices(frames, def));
  EXPECT_GT(first, 0) << "the first leg was not cut";
  EXPECT_GT(second, 0) << "the second leg was not cut";
}

// The default scenario's stroke, one pose a frame: the blade starts just
// off the ellipsoid's edge (y = -4.8 cm; the mesh spans y = +-4.64 cm at
// x = 3 cm) and enters it in the first frame. The incision shows on the
// frontier by frame 3 and in every frame the blade is in the tissue from
// there, grows with the blade in at least 90% of them, and the flap comes
// off within two frames of the blade's exit from the mesh. Every frame is
// valid: MT, frontier, BVH, cutter and springs.
TEST(World, TheIncisionOpensBehindTheBladeEveryFrame) {
  WorldDef def = organ_def();
  def.environment.floor = Plane{Vec3(0, 0, 1), -0.036};  // as the default scenario's: the organ lies on it
  World world(organ_mt(8000), def);
  constexpr double kFromY = -0.048, kToY = 0.06, kSeconds = 0.9;  // 12 cm/s
  const ScalpelPath path(std::vector<ScalpelKeyframe>{
      {0.0, {Vec3(0.03, kFromY, 0.06), Vec3(0.03, kFromY, -0.07), true}},
      {kSeconds, {Vec3(0.03, kToY, 0.06), Vec3(0.03, kToY, -0.07), true}},
      {kSeconds + 0.001, {Vec3(0.03, kToY, 0.06), Vec3(0.03, kToY, -0.07), false}}});
  // The first frame at whose start the blade has passed the mesh's last
  // vertex near its plane x = 3 cm.
  double exit_y = -1;
  for (const Vec3& p : world.mt().positions())
    if (std::abs(p.x() - 0.03) < 0.004) exit_y = std::max(exit_y, p.y());
  const int exit_frame = static_cast<int>(std::ceil((exit_y - kFromY) / (kToY - kFromY) * kSeconds * 60.0)) + 1;
  constexpr int kFirstCutFrame = 3;  // the blade enters in frame 1
  const std::size_t original = world.mt().num_vertices();
  const auto cut_vertices_shown = [&] {
    std::size_t n = 0;
    for (engine::VertId v : world.frontier().vertices()) n += v.index() >= original;
    return n;
  };
  const auto cut_vertices_used = [&] {  // at any resolution
    std::vector<char> used(world.mt().num_vertices(), 0);
    for (std::size_t t = 0; t < world.mt().num_tets(); ++t)
      if (world.mt().alive(engine::TetId(t)))
        for (engine::VertId v : world.mt().tet(engine::TetId(t))) used[v.index()] = v.index() >= original;
    return static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  };
  std::size_t grew = 0, inside = 0, last = 0, most_dead = 0;
  int separated_at = -1;
  for (int f = 1; f <= 70; ++f) {
    const FrameMetrics& m = world.step(path.pose_at(world.time()));
    const auto report = world.validate();
    ASSERT_TRUE(report.ok()) << "frame " << f << ": " << report.summary();
    most_dead = std::max(most_dead, world.mt().num_dead_tets());
    EXPECT_EQ(m.cut_vertices, cut_vertices_used()) << "frame " << f;
    const std::size_t shown = cut_vertices_shown();
    if (f >= kFirstCutFrame && f < exit_frame) {
      EXPECT_GT(shown, 0u) << "no incision on the frontier at frame " << f;
      EXPECT_GT(m.provisional_tets, 0u) << "frame " << f;
      ++inside;
      grew += m.cut_vertices > last;
    }
    last = m.cut_vertices;
    if (separated_at < 0 && world.pieces() == 2) separated_at = f;
  }
  EXPECT_GE(grew * 10, inside * 9) << grew << " of " << inside << " frames in the tissue grew the incision";
  EXPECT_GE(separated_at, exit_frame - 6) << "the flap came off before the blade reached the end";
  EXPECT_LE(separated_at, exit_frame + 2) << "the flap came off late";
  EXPECT_EQ(world.pieces(), 2u);
  EXPECT_EQ(world.nan_events(), 0u);
  ASSERT_EQ(world.strokes().size(), 1u);
  EXPECT_TRUE(world.strokes()[0].finished);
  EXPECT_EQ(world.last_frame().provisional_tets, 0u);
  // The slots the retracted cuts left were reclaimed whenever they
  // outnumbered the live tets, during the stroke and after it.
  const std::size_t bound = std::max(world.mt().num_live_tets(), cut::TimeCriticalCutter::kReclaimMin);
  EXPECT_LE(most_dead, 2 * bound);
  EXPECT_LE(world.mt().num_dead_tets(), bound);
}

// A curved stroke through the whole organ (it lies on the floor), one pose a
// frame, bending by `curvature` metres at its ends: every frame valid (MT,
// frontier, BVH, cutter, springs), no cut refused, no NaN, and cut along
// both halves of its path. Returns the pieces.
std::size_t cut_curved_stroke(double curvature, bool gravity) {
  const std::string where = "curvature " + std::to_string(curvature) + (gravity ? "" : ", no gravity");
  WorldDef def = organ_def();
  def.environment.floor = Plane{Vec3(0, 0, 1), -0.036};  // as in the default scenario
  if (!gravity) def.environment.gravity = Vec3::Zero();
  World world(organ_mt(2000), def);
  const std::size_t before = world.mt().num_vertices();
  std::vector<ScalpelKeyframe> keys;
  for (int k = 0; k <= 24; ++k) {
    const double y = -0.06 + 0.12 * k / 24, x = 0.03 + curvature * (y / 0.06) * (y / 0.06);
    keys.push_back({k / 24.0, {Vec3(x, y, 0.06), Vec3(x, y, -0.07), true}});
  }
  keys.push_back({1.001, {keys.back().pose.base, keys.back().pose.tip, false}});
  const ScalpelPath path(keys);
  for (int f = 1; f <= 75; ++f) {
    world.step(path.pose_at(world.time()));
    const auto report = world.validate();
    EXPECT_TRUE(report.ok()) << where << ", frame " << f << ": " << report.summary();
    if (!report.ok()) return 0;
  }
  EXPECT_FALSE(world.cutter().frozen()) << where;
  EXPECT_EQ(world.cutter().cuts_refused(), 0u) << where;
  EXPECT_EQ(world.nan_events(), 0u) << where;
  int halves[2] = {0, 0};  // live vertices made by cuts, by the half of the path (rest space)
  for (std::size_t t = 0; t < world.mt().num_tets(); ++t)
    if (world.mt().alive(engine::TetId(t)))
      for (engine::VertId v : world.mt().tet(engine::TetId(t)))
        if (v.index() >= before) ++halves[world.mt().position(v).y() > 0 ? 1 : 0];
  EXPECT_GT(halves[0], 0) << where << ": the first half was not cut";
  EXPECT_GT(halves[1], 0) << where << ": the second half was not cut";
  return world.pieces();
}

// Without gravity the tissue rests where it lies, so the map to rest space
// is near the identity: the stroke's straight parts go on from each other's
// cracks at every turn (under 45 degrees), and the flap it goes round comes
// off, whichever way it bends.
TEST(World, ACurvedStrokeThroughTheRestingOrganCutsOffTheFlap) {
  for (const double curvature : {0.006, 0.012, 0.02, 0.03, -0.02})
    EXPECT_EQ(cut_curved_stroke(curvature, false), 2u) << "curvature " << curvature;
}

// With gravity the organ sags onto the floor, and the affine map to rest
// space stretches each frame's polygon three to four times, so two parts
// meet at a turn only at some curvatures (docs/progressive_cutting.md):
// whether the flap comes off is not asserted, the rest is.
TEST(World, CurvedStrokesThroughTheSaggingOrganKeepEveryFrameValid) {
  for (const double curvature : {0.006, 0.012, 0.02, 0.03, -0.02}) cut_curved_stroke(curvature, true);
}

// A stroke through the whole depth that turns sharply inside the organ, at
// 2 mm a frame: along y at x = 3 cm from outside to the corner at y = 0,
// then on to `end` (x, y) out of the organ. Without gravity the map to rest
// space is near the identity: the two legs' cracks cross at the corner and
// the part of the organ they go round comes off. Every frame valid, no cut
// refused.
void cut_off_the_corner(const Vec3& end) {
  WorldDef def = organ_def();
  def.environment.gravity = Vec3::Zero();
  World world(organ_mt(2000), def);
  std::vector<ScalpelPose> poses;
  for (int k = 0; k <= 30; ++k) poses.push_back(blade_at(0.03, -0.06 + 0.06 * k / 30));
  const Vec3 corner(0.03, 0.0, 0.0);
  const int frames = static_cast<int>(std::ceil((end - corner).norm() / 0.002));
  for (int k = 1; k <= frames; ++k) {
    const Vec3 at = corner + (end - corner) * k / frames;
    poses.push_back(blade_at(at.x(), at.y()));
  }
  poses.push_back(blade_at(end.x(), end.y(), false));
  for (const ScalpelPose& pose : poses) {
    world.step(pose);
    const auto report = world.validate();
    ASSERT_TRUE(report.ok()) << "frame " << world.frame() << ": " << report.summary();
  }
  for (int f = 0; f < 40 && world.cutter().frozen(); ++f) world.step(poses.back());
  EXPECT_FALSE(world.cutter().frozen());
  EXPECT_EQ(world.cutter().cuts_refused(), 0u);
  EXPECT_EQ(world.nan_events(), 0u);
  EXPECT_EQ(world.pieces(), 2u);
}

// An L: along +x out of the front end.
TEST(World, ASharpTurnThroughTheRestingOrganCutsOffTheCorner) { cut_off_the_corner(Vec3(0.1, 0.0, 0.0)); }

// A V: back towards -y, 153 degrees from the first leg (the two legs'
// planes 27 degrees apart): the wedge between the legs comes off.
TEST(World, AVThroughTheRestingOrganCutsOffTheWedge) { cut_off_the_corner(Vec3(0.06, -0.06, 0.0)); }

// The frontier's tets, ascending.
std::vector<std::int32_t> sorted_tets(const engine::Frontier& frontier) {
  std::vector<std::int32_t> ids;
  for (const auto t : frontier.tets()) ids.push_back(t.value);
  std::sort(ids.begin(), ids.end());
  return ids;
}

// A frontier move the blade asks for at one frame is simulated from
// def.lod.build_frames later: the frames in between still simulate the
// frontier it started with and decide no other move, and the frame that
// takes it simulates S* of the error field around the blade (base to tip).
class WorldMoveLatency : public ::testing::TestWithParam<int> {};

TEST_P(WorldMoveLatency, AFrontierMoveTakesEffectBuildFramesAfterTheBladeAskedForIt) {
  WorldDef def = organ_def();
  def.lod.build_frames = GetParam();
  World world(organ_mt(2000), def);
  const ScalpelPose pose{Vec3(0.02, 0, 0.06), Vec3(0.02, 0, 0.0), false};  // the tip in the organ
  const std::vector<std::int32_t> coarsest = sorted_tets(world.frontier());
  const FrameMetrics& first = world.step(pose);
  ASSERT_GT(first.lod_changes, 0u);
  EXPECT_EQ(first.springs_built, 0);
  for (int f = 1; f < def.lod.build_frames; ++f) {
    const FrameMetrics& waiting = world.step(pose);
    EXPECT_EQ(waiting.springs_built, 0) << "frame " << f;
    EXPECT_EQ(waiting.lod_changes, 0u) << "frame " << f << ": a move is pending";
    EXPECT_EQ(sorted_tets(world.frontier()), coarsest) << "frame " << f;
    EXPECT_EQ(world.model().num_particles(), world.frontier().vertices().size());
  }
  EXPECT_EQ(sorted_tets(world.frontier()), coarsest);
  const FrameMetrics& taken = world.step(pose);
  EXPECT_EQ(taken.springs_built, 1);
  EXPECT_EQ(taken.lod_changes, 0u);  // the blade stays: nothing more to move

  engine::ErrorField field;
  field.focus = engine::Segment{pose.base, pose.tip};
  field.radius = def.lod.near_radius;
  field.near_error = def.lod.near_error;
  field.growth = (def.lod.far_error - def.lod.near_error) / (def.lod.far_radius - def.lod.near_radius);
  const std::vector<std::int32_t> asked = sorted_tets(engine::extract_frontier(world.mt(), field));
  EXPECT_NE(asked, coarsest);
  EXPECT_EQ(sorted_tets(world.frontier()), asked);
  EXPECT_EQ(world.model().num_particles(), world.frontier().vertices().size());
  const auto report = world.validate();
  EXPECT_TRUE(report.ok()) << report.summary();
}

INSTANTIATE_TEST_SUITE_P(BuildFrames, WorldMoveLatency, ::testing::Values(1, 2, 3));

// A World told the blade's first pose starts on the frontier the LOD stage
// asks for around it, with its springs: the first frame with that pose
// moves nothing, and the run from there is the one a World made without
// the pose reaches once it has taken its first move.
TEST(World, ABladeKnownAtTheStartStartsTheFrontierAroundIt) {
  const WorldDef def = organ_def();
  const ScalpelPose pose{Vec3(0.02, 0, 0.06), Vec3(0.02, 0, 0.0), false};  // the tip in the organ
  World told(organ_mt(2000), def, pose);
  World untold(organ_mt(2000), def);
  EXPECT_TRUE(told.validate().ok()) << told.validate().summary();
  EXPECT_NE(sorted_tets(told.frontier()), sorted_tets(untold.frontier()));
  EXPECT_EQ(told.model().num_particles(), told.frontier().vertices().size());
  for (int f = 0; f <= def.lod.build_frames; ++f) untold.step(pose);
  EXPECT_EQ(sorted_tets(told.frontier()), sorted_tets(untold.frontier()));
  for (int f = 0; f < 5; ++f) {
    const FrameMetrics& m = told.step(pose);
    EXPECT_EQ(m.lod_changes, 0u) << "frame " << f;
    EXPECT_EQ(m.springs_built, 0) << "frame " << f;
    const auto report = told.validate();
    ASSERT_TRUE(report.ok()) << "frame " << f << ": " << report.summary();
  }
  EXPECT_EQ(sorted_tets(told.frontier()), sorted_tets(untold.frontier()));
  // With LOD off the frontier is the finest level, pose or not.
  WorldDef fixed = def;
  fixed.lod.enabled = false;
  EXPECT_EQ(sorted_tets(World(organ_mt(2000), fixed, pose).frontier()),
            sorted_tets(World(organ_mt(2000), fixed).frontier()));
}

// Two Worlds that differ only in how their springs are made take a
// disengaged sweep and then an L stroke cut one sample per frame while the
// frontier follows the blade. Every frame: equal state hashes, frontiers,
// metrics and spring models, and both valid.
void expect_same_runs(const WorldDef& a_def, const WorldDef& b_def) {
  World a_world(organ_mt(2000), a_def), b_world(organ_mt(2000), b_def);
  const ScalpelPath approach = sweep();
  std::vector<ScalpelPose> stroke = l_stroke();
  for (ScalpelPose& p : stroke) p.tip.z() = -0.02;  // the tip, the LOD's focus, in the organ
  const auto stroke_frames = static_cast<int>(stroke.size());
  std::size_t moves = 0, cut_tets = 0, cut_while_moving = 0;
  for (int f = 0; f < 40 + stroke_frames + 20; ++f) {
    const ScalpelPose pose = f < 40                   ? approach.pose_at(f / 60.0)
                             : f < 40 + stroke_frames ? stroke[static_cast<std::size_t>(f - 40)]
                                                      : blade_at(-0.02, 0.0, false);
    const FrameMetrics a = a_world.step(pose);
    const FrameMetrics& b = b_world.step(pose);
    ASSERT_EQ(a_world.state_hash(), b_world.state_hash()) << "frame " << f;
    ASSERT_EQ(a.lod_changes, b.lod_changes) << "frame " << f;
    ASSERT_EQ(a.cut_tets, b.cut_tets) << "frame " << f;
    ASSERT_EQ(sorted_tets(a_world.frontier()), sorted_tets(b_world.frontier())) << "frame " << f;
    const SpringModel &a_model = a_world.model(), &b_model = b_world.model();
    ASSERT_EQ(a_model.particle_vertex, b_model.particle_vertex) << "frame " << f;
    ASSERT_EQ(a_model.mass, b_model.mass) << "frame " << f;
    ASSERT_EQ(a_model.spring_a, b_model.spring_a) << "frame " << f;
    ASSERT_EQ(a_model.spring_b, b_model.spring_b) << "frame " << f;
    ASSERT_EQ(a_model.stiffness, b_model.stiffness) << "frame " << f;
    cut_while_moving += a.cuts_started > 0 && moves > 0 && !a.frozen;
    moves += a.lod_changes;
    cut_tets += a.cut_tets;
    for (const World* w : {&a_world, &b_world}) {
      const auto report = w->validate();
      ASSERT_TRUE(report.ok()) << "frame " << f << ": " << report.summary();
    }
  }
  EXPECT_GT(moves, 0u);
  EXPECT_GT(cut_tets, 0u);
  EXPECT_GT(cut_while_moving, 0u);
  EXPECT_EQ(a_world.pieces(), b_world.pieces());
  EXPECT_EQ(a_world.nan_events(), 0u);
}

// Springs built on the worker thread give the inline builds' bits: where a
// move is taken is fixed by the frame loop (before a cut changes the MT,
// else build_frames after it was decided), not by when its build ends. The
// L stroke runs 2 cm short of the organ's bottom; its turn cuts the first
// leg while the frontier follows the blade.
TEST(World, SpringsBuiltInTheBackgroundGiveTheInlineBuildsBits) {
  WorldDef background_def = organ_def();
  background_def.environment.gravity.setZero();  // the organ keeps its shape: the blade's tip stays in it
  ASSERT_TRUE(background_def.lod.background_build);
  WorldDef inline_def = background_def;
  inline_def.lod.background_build = false;
  expect_same_runs(background_def, inline_def);
}

// Springs updated by the tets each move and cut changed give the bits of
// springs built from every tet (spring_model_update.h).
TEST(World, SpringsUpdatedByEachChangeGiveTheFullBuildsBits) {
  WorldDef update_def = organ_def();
  update_def.environment.gravity.setZero();
  ASSERT_TRUE(update_def.lod.update_springs);
  WorldDef build_def = update_def;
  build_def.lod.update_springs = false;
  expect_same_runs(update_def, build_def);
}

// A stroke cut progressively under a small budget: each frame's part is cut
// whole (its commit and its front), so the mesh the World simulates
// conforms in every frame, frozen or not, and the cut is the same as
// without a budget.
TEST(World, AProgressiveStrokeUnderASmallBudgetConformsInEveryFrame) {
  const ScalpelPath path = flap_stroke(0.3);
  WorldDef def = flap_def();
  def.lod.enabled = false;
  WorldDef tiny_def = def;
  tiny_def.cut_budget = {CutBudgetDef::Unit::kTets, 5};
  World unlimited(organ_mt(2000), def), tiny(organ_mt(2000), tiny_def);
  std::size_t cut_frames = 0;
  for (int f = 0; f < 80; ++f) {
    unlimited.step(path.pose_at(unlimited.time()));
    const auto whole = unlimited.validate();
    ASSERT_TRUE(whole.ok()) << "frame " << f << ": " << whole.summary();
    const FrameMetrics& m = tiny.step(path.pose_at(tiny.time()));
    cut_frames += m.cut_tets > 0;
    const auto frontier = engine::validate_frontier(tiny.mt(), tiny.frontier());
    ASSERT_TRUE(frontier.ok()) << "frame " << f << ": " << frontier.summary();
    const auto report = m.frozen ? tiny.cutter().validate(tiny.mt()) : tiny.validate();
    ASSERT_TRUE(report.ok()) << "frame " << f << ": " << report.summary();
  }
  EXPECT_GT(cut_frames, 10u);  // cut frame by frame
  EXPECT_FALSE(tiny.cutter().frozen());
  EXPECT_TRUE(mt_contents(tiny.mt()) == mt_contents(unlimited.mt()));
  EXPECT_EQ(tiny.pieces(), 2u);
}

// Under a small budget the jobs of hidden fragments run in later frames.
// They change no tet of the frontier, so those frames keep the springs and
// the state; a frame whose frontier changed builds them once.
TEST(World, FramesThatOnlyCutHiddenFragmentsKeepTheSprings) {
  const std::vector<ScalpelPose> stroke = flap_in_one_frame();
  WorldDef def = flap_def();
  def.lod.enabled = false;  // the finest frontier: only the root is visible
  def.cut_budget = {CutBudgetDef::Unit::kTets, 5};
  World world(organ_mt(2000), def);
  int hidden_only = 0, built = 0;
  for (int f = 0; f < 80; ++f) {
    const std::vector<TetCorners> before = frontier_contents(world.mt(), world.frontier());
    const FrameMetrics& m = world.step(f == 0 ? std::span(stroke) : std::span(&kAway, 1));
    const bool mesh_changed = frontier_contents(world.mt(), world.frontier()) != before;
    EXPECT_EQ(m.springs_built, mesh_changed ? 1 : 0) << "frame " << f;
    EXPECT_EQ(world.model().num_particles(), world.frontier().vertices().size()) << "frame " << f;
    hidden_only += m.cut_tets > 0 && !mesh_changed;
    built += m.springs_built;
    // Half a cut is not a valid MT: while jobs wait, the cut's bookkeeping and the springs are.
    const auto report = m.frozen ? world.cutter().validate(world.mt()) : world.validate();
    ASSERT_TRUE(report.ok()) << "frame " << f << ": " << report.summary();
    ASSERT_TRUE(world.model().validate().ok()) << "frame " << f;
  }
  EXPECT_GT(hidden_only, 3);
  EXPECT_GT(built, 0);
  EXPECT_FALSE(world.cutter().frozen());
  EXPECT_EQ(world.pieces(), 2u);
}

TEST(World, AFrameNeedsAPose) {
  World world(organ_mt(2000), organ_def());
  EXPECT_THROW(world.step(std::span<const ScalpelPose>()), std::invalid_argument);
  EXPECT_EQ(world.frame(), 0u);
}

}  // namespace
}  // namespace mtcut::sim
