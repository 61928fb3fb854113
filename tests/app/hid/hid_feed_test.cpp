// The HID feeding a World frame by frame, live from the input thread over a
// scripted transport: a stroke, then the device unplugged mid-stroke (its
// read returns an error), then back. The unplug is told once, the blade
// disengages at once (so the World cuts the stroke's part so far),
// reconnection is retried until it succeeds, and the World runs on: no
// reset, no frame lost, the cut kept, the stroke resumed. The input runs on
// the test's clock (InputClock): each frame's report is stamped half a frame
// after the frame's time and reaches the World in the next frame, however
// fast the machine runs; nothing is timed.
// Also, replayed: each frame gets every sample since the last frame, then
// the pose at its time.

#include "app/hid/hid_feed.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <unistd.h>

#include "app/hid/recording.h"
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

// A vertical blade at (x, y) over the organ, engaged.
sim::ScalpelPose blade_at(double x, double y) {
  return {engine::Vec3(x, y, 0.04), engine::Vec3(x, y, -0.07), true};
}

bool same_pose(const sim::ScalpelPose& a, const sim::ScalpelPose& b) {
  return a.base == b.base && a.tip == b.tip && a.engaged == b.engaged;
}

TEST(HidFeed, EachFrameGetsEverySampleSinceTheLastFrameThenItsPose) {
  const Profile profile = load_profile("pen_tablet");
  // Four samples a frame of 20 ms, a turn at the corner, one sample exactly
  // at a frame's time.
  std::vector<Sample> samples;
  for (int k = 0; k < 12; ++k) {
    Sample s;
    s.time_us = 3000 + 5000 * k;
    s.pose = k < 6 ? blade_at(0.04, -0.06 + 0.01 * k) : blade_at(0.04 - 0.01 * (k - 5), 0.0);
    samples.push_back(s);
  }
  samples.push_back({80000, blade_at(-0.03, 0.0)});
  const sim::ScalpelPath whole(to_keyframes(profile, samples));
  HidFeed feed(profile, samples);
  // A replay knows its pose at time 0 before the run starts (the World is
  // made on the frontier around it), and telling it takes no sample away.
  const std::optional<sim::ScalpelPose> start = feed.start_pose();
  ASSERT_TRUE(start.has_value());
  const std::vector<double> frames = {0.0, 0.02, 0.04, 0.06, samples.back().time(), 0.1};
  std::vector<std::vector<sim::ScalpelKeyframe>> got;
  for (const double t : frames) got.push_back(feed.frame_samples(t));

  ASSERT_EQ(got[0].size(), 1u);  // the initial pose at time 0
  EXPECT_TRUE(same_pose(got[0][0].pose, initial_pose(profile)));
  EXPECT_TRUE(same_pose(got[0][0].pose, *start));
  for (std::size_t f = 1; f < frames.size(); ++f) {
    // The samples in (previous frame, frame], in order, then the path's pose at the frame.
    std::vector<sim::ScalpelPose> want;
    for (const Sample& s : samples)
      if (s.time() > frames[f - 1] && s.time() <= frames[f]) want.push_back(s.pose);
    const bool sample_at_frame = samples.back().time() == frames[f];
    if (!sample_at_frame) want.push_back(whole.pose_at(frames[f]));
    ASSERT_EQ(got[f].size(), want.size()) << "frame " << f;
    for (std::size_t i = 0; i < want.size(); ++i) EXPECT_TRUE(same_pose(got[f][i].pose, want[i])) << f << ", " << i;
    EXPECT_EQ(got[f].back().time, frames[f]);
  }
  EXPECT_EQ(got[1].size(), 5u);  // four samples (3 to 18 ms), then the pose at 20 ms
  EXPECT_EQ(got[3].size(), 5u);  // the turn: 43 to 58 ms, then the pose at 60 ms
  EXPECT_EQ(got[4].size(), 1u);  // the sample at the frame's time is its pose
  EXPECT_EQ(got[5].size(), 1u);  // no sample: the last one's pose holds
}

TEST(HidFeed, AnUnplugMidStrokeIsToldOnceDisengagesAndTheWorldRunsOn) {
  ScenarioDef scenario = load_scenario(test::source_path("config/scenarios/default.toml"));
  scenario.mesh_load.builtin_tets = 1500;
  sim::World world(build_organ_mt(scenario), scenario.world);
  const std::size_t loaded_vertices = world.mt().num_vertices();
  const double dt = scenario.world.dt;

  // The test's clock: the feed's wait for a frame's samples moves it to the
  // frame's due time; the test moves it to where each report is stamped.
  std::atomic<std::int64_t> clock_us{0};
  const auto advance_to = [&](std::int64_t us) {
    std::int64_t now = clock_us.load();
    while (now < us && !clock_us.compare_exchange_weak(now, us)) {
    }
  };
  test::FakeTransport transport(kPen);
  const std::string recording = (std::filesystem::temp_directory_path() /
                                 ("mtcut-hid-feed-" + std::to_string(::getpid()) + ".hidrec")).string();
  InputDef def;
  def.record_path = recording;
  def.read_timeout_ms = 5;
  def.retry_seconds = 0.002;
  def.clock = {[&] { return clock_us.load(); }, advance_to};
  InputThread input(transport, load_profile("pen_tablet"), def);
  input.start();
  HidFeed feed(input, dt);
  EXPECT_FALSE(feed.start_pose().has_value());  // live: the device has not been read

  // The pen reports until kFrames; the frames after it take the last
  // reports (each reaches the World in the frame after the one it is
  // stamped in).
  constexpr int kUnplugFrame = 20, kBackFrame = 30, kFrames = 60, kDrainFrames = 3;
  std::vector<sim::ScalpelPose> poses;             // the frames' poses
  std::vector<sim::ScalpelKeyframe> handed;        // every sample the World got
  std::vector<InputEvent> events;
  std::size_t cuts_started = 0, cut_vertices_at_reconnect = 0;
  long queued = 0;  // samples the input thread is to have queued: every report, and the unplug's
  // Until the input thread has taken what the test queued (a bound on a
  // thread that never does, not a timing).
  const auto settle = [&](auto&& done) {
    ASSERT_TRUE(input.wait_until(done, std::chrono::seconds(60))) << "the input thread did not take the reads";
  };
  for (int f = 0; f < kFrames + kDrainFrames; ++f) {
    const double t = world.time();
    advance_to(static_cast<std::int64_t>(std::llround((t + 0.5 * dt) * 1e6)));
    // The pen crosses the front end at x = 4 cm: y from -6 cm to 0, then
    // (after the unplug) on to +6 cm.
    if (f == kBackFrame) settle([](const InputStatus& s) { return s.connects == 2; });  // back before it reports
    if (f < kUnplugFrame) transport.queue_bytes(pen_at(0.04, -0.06 + 0.06 * f / kUnplugFrame));
    if (f == kUnplugFrame) transport.queue_unplug(3);  // gone for three lookups
    if (f >= kBackFrame && f < kFrames) transport.queue_bytes(pen_at(0.04, 0.06 * (f - kBackFrame) / (kFrames - kBackFrame)));
    queued += f < kUnplugFrame || f == kUnplugFrame || (f >= kBackFrame && f < kFrames);
    settle([&](const InputStatus& s) { return s.samples == queued; });
    if (::testing::Test::HasFatalFailure()) return;
    const std::vector<sim::ScalpelKeyframe> frame = feed.frame_samples(t);
    handed.insert(handed.end(), frame.begin(), frame.end());
    poses.push_back(frame.back().pose);
    world.step(sim::poses_of(frame));
    feed.reached(t, feed.clock());
    cuts_started += world.last_frame().cuts_started;
    for (InputEvent& e : feed.take_events()) events.push_back(std::move(e));
    if (f == kBackFrame - 1) cut_vertices_at_reconnect = world.last_frame().cut_vertices;
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
  // (Cut vertices in use: the MT's own vertex count drops when the cutter
  // reclaims what retracted cuts left.)
  EXPECT_EQ(world.frame(), static_cast<std::uint64_t>(kFrames + kDrainFrames));
  EXPECT_GE(cuts_started, 1u);
  EXPECT_GT(cut_vertices_at_reconnect, 0u) << "the disengaged blade did not cut the stroke so far";
  EXPECT_GE(world.last_frame().cut_vertices, cut_vertices_at_reconnect);
  EXPECT_GE(world.mt().num_vertices(), loaded_vertices + world.last_frame().cut_vertices);
  EXPECT_EQ(world.nan_events(), 0u);
  const engine::ValidationReport valid = world.validate();
  EXPECT_TRUE(valid.ok()) << (valid.ok() ? "" : valid.problems.front());

  // Every sample (as the recording of the reports decodes them) up to the
  // last frame's time reached the World, once, in order: none is left out
  // between two frames.
  const auto keys = to_keyframes(input.profile(), replay_recording(recording, input.profile()));
  std::filesystem::remove(recording);
  std::size_t found = 0;
  for (std::size_t i = 0; i < handed.size(); ++i) {
    if (i > 0) {
      EXPECT_GT(handed[i].time, handed[i - 1].time);
    }
    if (found < keys.size() && handed[i].time == keys[found].time) {
      EXPECT_TRUE(same_pose(handed[i].pose, keys[found].pose)) << "sample at " << keys[found].time;
      ++found;
    }
  }
  ASSERT_LT(0u, found);
  EXPECT_TRUE(found == keys.size() || keys[found].time > handed.back().time)
      << "the sample at " << keys[found].time << " s did not reach the World";
  EXPECT_GT(found, static_cast<std::size_t>(kUnplugFrame));

  // Every sample up to the last frame's time reached the World, with a latency.
  const LatencySummary latency = feed.latency();
  EXPECT_GT(latency.count, 0);
}

}  // namespace
}  // namespace mtcut::app::hid
