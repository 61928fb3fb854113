// The viewer's session without a window: a user's mouse stroke recorded to a
// scalpel trace and replayed gives the very same World, and an attached HID
// device drives the blade (its samples reach the World, with a latency).

#include "app/view/viewer_session.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <optional>

#include "app/hid/profile_file.h"
#include "app/view/viewer_input.h"
#include "engine/input_error.h"
#include "tests/app/hid/fake_transport.h"
#include "tests/app/hid/hid_test_util.h"
#include "tests/test_paths.h"

namespace mtcut::app::view {
namespace {

ScenarioDef coarse_default() {
  ScenarioDef scenario = load_scenario(test::source_path("config/scenarios/default.toml"));
  scenario.mesh_load.builtin_tets = 1500;
  return scenario;
}

std::string temp_file(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("mtcut-" + std::to_string(::getpid()) + "-" + name)).string();
}

TEST(ViewerSessionTrace, ARecordedMouseStrokeReplaysToTheSameWorld) {
  ViewerSession s(coarse_default());
  s.settings().play_script = false;
  OrbitCamera camera;
  camera.frame(s.lo(), s.hi());
  ViewerInput input(s, camera);
  input.set_viewport(1280, 720);

  s.start_recording();
  for (int k = 0; k < 80; ++k) s.step();  // the organ settles (viewer_input_test says why)
  input.on_mouse_button(MouseButton::kLeft, true, true, 640, 360);
  ASSERT_TRUE(s.mouse_scalpel().active());
  for (int i = 0; i <= 20; ++i) {
    s.step();
    input.on_cursor(640 + 8 * i, 360);
  }
  input.on_mouse_button(MouseButton::kLeft, false, true, 800, 360);
  for (int k = 0; k < 5; ++k) s.step();
  ASSERT_GT(s.world().mt().num_vertices(), s.loaded_vertices()) << "the stroke did not cut";
  const std::uint64_t frames = s.world().frame();
  const std::uint64_t hash = s.world().state_hash();
  const std::string trace = temp_file("viewer-trace.csv");
  EXPECT_EQ(s.stop_recording(trace), frames);
  EXPECT_FALSE(s.recording());

  s.replay_trace(trace);
  EXPECT_TRUE(s.replaying());
  EXPECT_EQ(s.world().frame(), 0u);
  while (s.world().frame() < frames) s.step();
  EXPECT_EQ(s.world().state_hash(), hash) << "the replay differs from the recorded session";
  s.reset();
  EXPECT_FALSE(s.replaying());
  std::filesystem::remove(trace);
}

// The World starts on the frontier around the blade's pose at time 0, the
// one its first frame gets: the scenario's path while it plays, else the
// parked blade; so the first frame moves no frontier.
TEST(ViewerSessionStart, TheWorldStartsAroundTheBladesFirstPose) {
  ViewerSession s(coarse_default());
  for (const bool script : {true, false}) {
    s.settings().play_script = script;
    s.reset();
    const std::optional<sim::ScalpelPose> start = s.start_pose();
    ASSERT_TRUE(start.has_value());
    const sim::ScalpelPose expected = script ? s.scenario().scalpel.pose_at(0.0) : s.parked_pose();
    EXPECT_EQ(start->base, expected.base);
    EXPECT_EQ(start->tip, expected.tip);
    const sim::FrameMetrics& first = s.step();
    EXPECT_EQ(first.lod_changes, 0u) << (script ? "script" : "parked");
    EXPECT_EQ(first.springs_built, 0) << (script ? "script" : "parked");
  }
}

TEST(ViewerSessionTrace, ABadTraceIsAnInputErrorAndTheSessionGoesOn) {
  ViewerSession s(coarse_default());
  EXPECT_THROW(s.replay_trace(temp_file("missing.csv")), engine::InputError);
  EXPECT_FALSE(s.replaying());
  s.step();
  EXPECT_EQ(s.world().frame(), 1u);
}

TEST(ViewerSessionHid, AnAttachedPenDrivesTheBlade) {
  ViewerSession s(coarse_default());
  s.settings().play_script = false;
  test::FakeTransport transport({"/dev/hidraw7", 0x256c, 0x006d, 0x0d, 0x02, 0, "HUION", "Tablet", ""});
  hid::InputDef def;
  def.read_timeout_ms = 5;
  hid::InputThread input(transport, hid::load_profile("pen_tablet"), def);
  input.start();
  hid::HidFeed feed(input, 0.0);
  s.attach_hid(&feed);
  // The pen pressed at the tablet's centre: the blade straight down from 4 cm above the origin.
  transport.queue_bytes(test::pen_report(true, 16384, 16384, 8191, 0, 0));
  ASSERT_TRUE(input.wait_until([](const hid::InputStatus& st) { return st.samples == 1; }, std::chrono::seconds(10)));
  // The session follows the device one step behind its clock: step until that passes the sample.
  while (!s.last_pose().engaged && s.world().frame() < 10000) {
    s.poll_hid();
    s.step();
  }
  EXPECT_TRUE(s.last_pose().engaged);
  EXPECT_NEAR(s.last_pose().tip.z(), 0.04 - 0.11, 1e-9);
  EXPECT_NE(s.hid_message().find("connected /dev/hidraw7"), std::string::npos) << s.hid_message();
  s.step();
  EXPECT_EQ(feed.latency().count, 1);
  s.attach_hid(nullptr);
  input.stop();
}

}  // namespace
}  // namespace mtcut::app::view
