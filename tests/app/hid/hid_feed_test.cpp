// The HID feeding a World frame by frame, live from the input thread over a
// scripted transport: a stroke, then the device unplugged mid-stroke (its
// read returns an error), then back. The unplug is told once, the blade
// disengages at once (so the World cuts the stroke's part so far),
// reconnection is retried until it succeeds, and the World runs on: no
// reset, no frame lost, the cut kept, the stroke resumed. Waits are the
// feed's own real-time pacing; nothing is timed.

#include "app/hid/hid_feed.h"

#include <gtest/gtest.h>

#include <cmath>

#include "app/hid/profile_file.h"
#include "app/run_command.h"
#include "sim/world.h"
#include "tests/app/hid/fake_transport.h"
#include "tests/app/hid/hid_test_util.h"
#include "tests/test_paths.h"

namespace mtcut::app::hid {
namespace {

const DeviceInfo kPen{"/dev/hidraw7", 0x256c, 0x006d, 0x0d, 0x02, 0, "HUION", "Tablet", ""};

int raw_axis(double u) { return static_cast<int>(std::lround((u + 1.0) / 2.0 * 32767.0)); }

// The pen pressed fully at (x, y) over the organ (pen_tablet's mapping).
std::vector<std::uint8_t> pen_at(double x, double y) {
  return test::pen_report(true, raw_axis(x / 0.1), raw_axis(-y / 0.1), 8191, 0, 0);
}

TEST(HidFeed, AnUnplugMidStrokeIsToldOnceDisengagesAndTheWorldRunsOn) {
  ScenarioDef scenario = load_scenario(test::source_path("config/scenarios/default.toml"));
  scenario.mesh_load.builtin_tets = 1500;
  sim::World world(build_organ_mt(scenario), scenario.world);
  const std::size_t loaded_vertices = world.mt().num_vertices();
  const double dt = scenario.world.dt;

  test::FakeTransport transport(kPen);
  InputDef def;
  def.read_timeout_ms = 5;
  def.retry_seconds = 0.002;
  InputThread input(transport, load_profile("pen_tablet"), def);
  input.start();
  HidFeed feed(input, dt);

  constexpr int kUnplugFrame = 20, kBackFrame = 30, kFrames = 60;
  std::vector<sim::ScalpelPose> poses;
  std::vector<InputEvent> events;
  std::size_t cuts_started = 0, vertices_at_reconnect = 0;
  for (int f = 0; f < kFrames; ++f) {
    // The pen crosses the front end at x = 4 cm: y from -6 cm to 0, then
    // (after the unplug) on to +6 cm.
    if (f < kUnplugFrame) transport.queue_bytes(pen_at(0.04, -0.06 + 0.06 * f / kUnplugFrame));
    if (f == kUnplugFrame) transport.queue_unplug(3);  // gone for three lookups
    if (f >= kBackFrame) transport.queue_bytes(pen_at(0.04, 0.06 * (f - kBackFrame) / (kFrames - kBackFrame)));
    const double t = world.time();
    poses.push_back(feed.pose_at(t));
    world.step(poses.back());
    feed.reached(t, feed.clock());
    cuts_started += world.last_frame().cuts_started;
    for (InputEvent& e : feed.take_events()) events.push_back(std::move(e));
    if (f == kBackFrame - 1) vertices_at_reconnect = world.mt().num_vertices();
  }
  input.stop();

  // Told once, reconnected after retries.
  const auto count = [&](InputEvent::Kind kind) {
    return std::count_if(events.begin(), events.end(), [&](const InputEvent& e) { return e.kind == kind; });
  };
  EXPECT_EQ(count(InputEvent::Kind::unplugged), 1);
  EXPECT_EQ(count(InputEvent::Kind::connected), 2);
  EXPECT_EQ(count(InputEvent::Kind::no_device), 0);  // the unplug message says it is looking
  const InputStatus status = input.status();
  EXPECT_EQ(status.unplugs, 1);
  EXPECT_GE(status.open_attempts, 5);  // 1 + 3 lookups that found nothing + 1
  EXPECT_EQ(feed.samples(), kUnplugFrame + 1 + (kFrames - kBackFrame));  // every report and the unplug

  // Engaged through the stroke, disengaged from the unplug until the pen is back.
  EXPECT_TRUE(poses[kUnplugFrame - 2].engaged);
  const auto released = std::find_if(poses.begin() + kUnplugFrame - 1, poses.end(),
                                     [](const sim::ScalpelPose& p) { return !p.engaged; });
  ASSERT_NE(released, poses.end()) << "the unplug did not disengage the blade";
  EXPECT_LE(released - poses.begin(), kUnplugFrame + 2);
  EXPECT_FALSE(poses[kBackFrame - 1].engaged);
  EXPECT_TRUE(poses.back().engaged) << "the stroke did not resume after reconnection";

  // The World ran every frame on one state: the part of the stroke before
  // the unplug was cut when the blade disengaged, and the cut is still there.
  EXPECT_EQ(world.frame(), static_cast<std::uint64_t>(kFrames));
  EXPECT_GE(cuts_started, 1u);
  EXPECT_GT(vertices_at_reconnect, loaded_vertices) << "the disengaged blade did not cut the stroke so far";
  EXPECT_GE(world.mt().num_vertices(), vertices_at_reconnect);
  EXPECT_EQ(world.nan_events(), 0u);
  const engine::ValidationReport valid = world.validate();
  EXPECT_TRUE(valid.ok()) << (valid.ok() ? "" : valid.problems.front());

  // Every sample up to the last frame's time reached the World, with a latency.
  const LatencySummary latency = feed.latency();
  EXPECT_GT(latency.count, 0);
  EXPECT_GE(latency.median_ms, 0.0);
}

}  // namespace
}  // namespace mtcut::app::hid
