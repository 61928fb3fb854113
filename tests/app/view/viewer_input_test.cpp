#include "app/view/viewer_input.h"

#include <gtest/gtest.h>

#include <set>

#include "app/run_metrics.h"
#include "tests/test_paths.h"

namespace mtcut::app::view {
namespace {

// The default scenario's organ, coarser so that the test stays quick, with
// the scripted scalpel off: only the mouse moves the blade.
ViewerSession& session() {
  static ViewerSession* s = [] {
    ScenarioDef scenario = load_scenario(test::source_path("config/scenarios/default.toml"));
    scenario.mesh_load.builtin_tets = 1500;
    return new ViewerSession(scenario);
  }();
  return *s;
}

struct Rig {
  ViewerSession& s = session();
  OrbitCamera camera;
  ViewerInput input{s, camera};
  Rig() {
    s.settings() = ViewSettings{};
    s.settings().play_script = false;
    s.reset();
    camera.frame(s.lo(), s.hi());
    input.set_viewport(1280, 720);
  }
};

// Steps until the organ is at rest (kinetic energy below `joules`); false
// when it has not settled within `max_frames`.
bool settle(ViewerSession& s, double joules, int max_frames) {
  for (int k = 0; k < max_frames; ++k) {
    s.step();
    if (kinetic_energy(s.world().model(), s.world().state()) < joules) return true;
  }
  return false;
}

bool inside(const engine::Vec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
  return p.x() > lo.x && p.x() < hi.x && p.y() > lo.y && p.y() < hi.y && p.z() > lo.z && p.z() < hi.z;
}

TEST(ViewerInput, ShiftDragIsAScalpelStrokeThatTheWorldSweeps) {
  Rig rig;
  // The user cuts the organ as it lies. Pressed at frame 0, the soft organ
  // sags up to 7 cm under gravity during the stroke (its free front end
  // reaches the floor): the blade, held where the press put it, ends above
  // the tissue, and the swept polygon misses it.
  ASSERT_TRUE(settle(rig.s, 1e-6, 600)) << "the organ did not come to rest";
  // Shift + left press at the window's centre: on the organ.
  rig.input.on_mouse_button(MouseButton::kLeft, true, true, 640, 360);
  ASSERT_TRUE(rig.input.scalpel_dragging());
  ASSERT_TRUE(rig.s.mouse_scalpel().active());
  rig.s.step();
  EXPECT_FALSE(rig.s.last_pose().engaged) << "the stroke's first frame only places the blade";
  EXPECT_TRUE(inside(rig.s.last_pose().tip, rig.s.lo(), rig.s.hi())) << "the tip is in the tissue";

  for (int i = 1; i <= 20; ++i) {
    rig.input.on_cursor(640 + 8 * i, 360);  // about 5 cm to the right in all
    rig.s.step();
    EXPECT_TRUE(rig.s.last_pose().engaged) << "frame " << i;
  }
  EXPECT_EQ(rig.s.engaged_sweeps(), 19u);  // between the 20 engaged poses
  EXPECT_GT((rig.s.last_pose().tip - rig.s.parked_pose().tip).norm(), 0.0);
  rig.input.on_mouse_button(MouseButton::kLeft, false, true, 800, 360);
  EXPECT_FALSE(rig.s.mouse_scalpel().active());
  rig.s.step();
  EXPECT_FALSE(rig.s.last_pose().engaged) << "released: the blade is parked";

  // The stroke's straight part is cut when the blade leaves the tissue.
  EXPECT_EQ(rig.s.world().last_frame().cuts_started, 1u);
  const std::size_t made = rig.s.world().mt().num_vertices() - rig.s.loaded_vertices();
  EXPECT_GT(made, 0u) << "the World received " << rig.s.engaged_sweeps() << " engaged sweeps but its MT did not grow";
  int cut_faces = 0;
  for (std::uint8_t c : rig.s.topology().face_cut) cut_faces += c;
  EXPECT_GT(cut_faces, 0) << "the stroke made vertices but the surface shows no cut face";
}

TEST(ViewerInput, PlainDragsMoveTheCameraAndAPressOffTheOrganStartsNoStroke) {
  Rig rig;
  const glm::dvec3 eye = rig.camera.eye();
  rig.input.on_mouse_button(MouseButton::kLeft, true, false, 640, 360);
  rig.input.on_cursor(700, 380);
  rig.input.on_mouse_button(MouseButton::kLeft, false, false, 700, 380);
  EXPECT_FALSE(rig.s.mouse_scalpel().active());
  EXPECT_GT(glm::length(rig.camera.eye() - eye), 1e-4);

  const glm::dvec3 target = rig.camera.target();
  rig.input.on_mouse_button(MouseButton::kRight, true, false, 700, 380);
  rig.input.on_cursor(650, 300);
  rig.input.on_mouse_button(MouseButton::kRight, false, false, 650, 300);
  EXPECT_GT(glm::length(rig.camera.target() - target), 1e-4);

  rig.input.on_key(KeyAction::kResetCamera);
  EXPECT_NEAR(glm::length(rig.camera.eye() - eye), 0.0, 1e-12);

  rig.input.on_mouse_button(MouseButton::kLeft, true, true, 3, 3);  // the corner: background
  EXPECT_FALSE(rig.input.scalpel_dragging());
  rig.s.step();
  EXPECT_FALSE(rig.s.last_pose().engaged);
  EXPECT_EQ(rig.s.engaged_sweeps(), 0u);
}

TEST(ViewerInput, KeysPauseStepAndSwitchTheDisplay) {
  Rig rig;
  const auto frame = rig.s.world().frame();
  rig.input.on_key(KeyAction::kStepOnce);
  EXPECT_EQ(rig.s.world().frame(), frame + 1);
  EXPECT_TRUE(rig.s.settings().paused);
  rig.input.on_key(KeyAction::kTogglePause);
  EXPECT_FALSE(rig.s.settings().paused);
  rig.input.on_key(KeyAction::kToggleLodColors);
  EXPECT_EQ(rig.s.settings().color_mode, ColorMode::kLodLevels);
  rig.input.on_key(KeyAction::kToggleShading);
  EXPECT_EQ(rig.s.settings().shading, Shading::kFlat);
  // Flat normals now: the three corners of a face share one.
  const SurfaceGeometry& g = rig.s.geometry();
  ASSERT_GT(g.corner_normal.size(), 3u);
  EXPECT_EQ(g.corner_normal[0], g.corner_normal[1]);
  rig.input.on_key(KeyAction::kToggleShading);
  rig.input.on_key(KeyAction::kToggleLodColors);
  rig.input.on_key(KeyAction::kToggleWireframe);
  EXPECT_TRUE(rig.s.settings().wireframe);
}

TEST(ViewerSession, ResetStartsAgainWithTheNewDefinition) {
  Rig rig;
  rig.s.step();
  sim::WorldDef def = rig.s.world().def();
  def.integrator.kind = sim::IntegratorKind::kSymplecticEuler;
  def.integrator.substeps = 8;
  rig.s.reset(def);
  EXPECT_EQ(rig.s.world().frame(), 0u);
  EXPECT_EQ(rig.s.world().def().integrator.substeps, 8);
  rig.s.step();
  EXPECT_EQ(rig.s.world().frame(), 1u);
  EXPECT_GT(rig.s.topology().num_faces(), 0u);
  EXPECT_EQ(rig.s.topology().pieces, 1);
  rig.s.reset(rig.s.scenario().world);
}

TEST(ViewerInput, BSwitchesBetweenTheFinestSurfaceAndTheSimulatedFrontiers) {
  Rig rig;
  rig.s.step();
  // The scenario's [output] surface: the finest.
  ASSERT_EQ(rig.s.settings().surface, SurfaceKind::kFinest);
  EXPECT_TRUE(rig.s.topology().finest.has_value());
  const std::uint64_t version = rig.s.topology_version();
  rig.input.on_key(KeyAction::kToggleSurface);
  EXPECT_EQ(rig.s.settings().surface, SurfaceKind::kFrontier);
  EXPECT_FALSE(rig.s.topology().finest.has_value());
  EXPECT_GT(rig.s.topology_version(), version);
  EXPECT_EQ(rig.s.geometry().corner_position.size(), 3 * rig.s.topology().num_faces());
  rig.input.on_key(KeyAction::kToggleSurface);
  EXPECT_TRUE(rig.s.topology().finest.has_value());
  EXPECT_EQ(rig.s.geometry().corner_position.size(), 3 * rig.s.topology().num_faces());
}

TEST(ViewerSession, TheLodViewSeesSeveralLevelsOnTheSurface) {
  Rig rig;
  rig.s.step();  // the LOD stage moves the frontier around the parked blade
  const SurfaceTopology& t = rig.s.topology();
  ASSERT_GT(t.max_level, 0);
  std::set<std::int32_t> levels(t.face_level.begin(), t.face_level.end());
  EXPECT_GE(levels.size(), 2u) << "the surface shows one level only";
  for (std::int32_t level : levels) {
    EXPECT_GE(level, 0);
    EXPECT_LE(level, t.max_level);
  }
}

}  // namespace
}  // namespace mtcut::app::view
