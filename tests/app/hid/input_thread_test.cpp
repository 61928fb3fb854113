// The input thread over a scripted transport: every report becomes a queued,
// timestamped sample; an unplug is reported once, disengages the blade and
// is followed by reconnection; permission denied says how to fix it; a
// recording replays to the very samples the live run queued. Waits are on
// the thread's condition variable; the timeouts only stop a broken test.

#include "app/hid/input_thread.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "app/hid/profile_file.h"
#include "tests/app/hid/fake_transport.h"
#include "tests/app/hid/hid_test_util.h"

namespace mtcut::app::hid {
namespace {
using std::chrono::seconds;

const DeviceInfo kPen{"/dev/hidraw7", 0x256c, 0x006d, 0x0d, 0x02, 0, "HUION", "Tablet", ""};
const DeviceInfo kSpaceMouse{"/dev/hidraw4", 0x256f, 0xc635, 0x01, 0x08, 0, "3Dconnexion", "SpaceMouse", ""};

InputDef fast_retry() {
  InputDef def;
  def.read_timeout_ms = 5;
  def.retry_seconds = 0.002;
  return def;
}

long count(const std::vector<InputEvent>& events, InputEvent::Kind kind) {
  return std::count_if(events.begin(), events.end(), [&](const InputEvent& e) { return e.kind == kind; });
}

TEST(HidInputThread, QueuesEveryReportInOrderForTheFrameLoop) {
  test::FakeTransport transport(kPen);
  for (int k = 0; k < 50; ++k) transport.queue_bytes(test::pen_report(true, 600 * k, 1000, 4000, 0, 0));
  transport.queue_bytes({2, 1});  // too short: counted, not queued
  InputThread input(transport, load_profile("pen_tablet"), fast_retry());
  input.start();
  ASSERT_TRUE(input.wait_until([](const InputStatus& s) { return s.counts.rejected() == 1; }, seconds(10)));
  EXPECT_TRUE(input.take_until(input.epoch() - std::chrono::microseconds(1)).empty());  // nothing before the epoch
  const std::vector<Sample> samples = input.take_until(std::chrono::steady_clock::now());
  ASSERT_EQ(samples.size(), 50u);  // the whole stroke, one pose per report
  for (std::size_t k = 1; k < samples.size(); ++k) {
    EXPECT_LE(samples[k - 1].time_us, samples[k].time_us);
    EXPECT_GT(samples[k].pose.tip.x(), samples[k - 1].pose.tip.x());
    EXPECT_TRUE(samples[k].pose.engaged);
  }
  EXPECT_TRUE(input.take_all().empty());
  const InputStatus status = input.status();
  EXPECT_TRUE(status.connected);
  EXPECT_EQ(status.device_path, "/dev/hidraw7");
  EXPECT_EQ(status.counts.too_short, 1);
  EXPECT_NE(status.last_reject.find("needs 10"), std::string::npos);
  const auto events = input.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, InputEvent::Kind::connected);
  EXPECT_NE(events[0].message.find("/dev/hidraw7"), std::string::npos);
  input.stop();
  EXPECT_TRUE(input.status().stopped);
}

TEST(HidInputThread, UnplugIsReportedOnceDisengagesAndReconnects) {
  test::FakeTransport transport(kPen);
  transport.queue_bytes(test::pen_report(true, 1000, 1000, 4000, 0, 0));
  transport.queue_unplug(5);  // gone for five lookups
  transport.queue_bytes(test::pen_report(true, 2000, 1000, 4000, 0, 0));
  InputThread input(transport, load_profile("pen_tablet"), fast_retry());
  input.start();
  ASSERT_TRUE(input.wait_until([](const InputStatus& s) { return s.connects == 2 && s.samples == 3; }, seconds(10)));
  const std::vector<Sample> samples = input.take_all();
  ASSERT_EQ(samples.size(), 3u);
  EXPECT_TRUE(samples[0].pose.engaged);
  EXPECT_FALSE(samples[1].pose.engaged);  // the unplug: blade disengaged, pose held
  test::expect_near(samples[1].pose.tip, samples[0].pose.tip, "held tip");
  EXPECT_TRUE(samples[2].pose.engaged);   // back, the pen still down
  const InputStatus status = input.status();
  EXPECT_EQ(status.unplugs, 1);
  EXPECT_GE(status.open_attempts, 7);     // 1 + 5 failed lookups + 1
  const auto events = input.take_events();
  EXPECT_EQ(count(events, InputEvent::Kind::unplugged), 1);
  EXPECT_EQ(count(events, InputEvent::Kind::connected), 2);
  EXPECT_EQ(count(events, InputEvent::Kind::no_device), 0);  // the unplug message said it already
  for (const InputEvent& e : events) {
    if (e.kind == InputEvent::Kind::unplugged) {
      EXPECT_NE(e.message.find("blade disengaged; reconnecting"), std::string::npos) << e.message;
    }
  }
}

TEST(HidInputThread, PermissionDeniedIsReportedOnceWithTheUdevRule) {
  test::FakeTransport transport(kSpaceMouse);
  transport.deny_permission(true);
  InputThread input(transport, load_profile("spacemouse"), fast_retry());
  input.start();
  ASSERT_TRUE(input.wait_until([](const InputStatus& s) { return s.open_failures >= 3; }, seconds(10)));
  auto events = input.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, InputEvent::Kind::permission_denied);
  EXPECT_NE(events[0].message.find("/dev/hidraw4: permission denied; install the udev rule: sudo cp "),
            std::string::npos);
  EXPECT_NE(events[0].message.find("/hid/70-mtcut-hid.rules /etc/udev/rules.d/"), std::string::npos);
  transport.deny_permission(false);
  ASSERT_TRUE(input.wait_until([](const InputStatus& s) { return s.connected; }, seconds(10)));
  events = input.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, InputEvent::Kind::connected);
}

TEST(HidInputThread, NoMatchingDeviceIsReportedOnce) {
  test::FakeTransport transport(kPen);  // a tablet, but we want a SpaceMouse
  InputThread input(transport, load_profile("spacemouse"), fast_retry());
  input.start();
  ASSERT_TRUE(input.wait_until([](const InputStatus& s) { return s.open_attempts >= 3; }, seconds(10)));
  const auto events = input.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, InputEvent::Kind::no_device);
  EXPECT_NE(events[0].message.find("no HID device matches profile 'spacemouse'"), std::string::npos);
  EXPECT_EQ(transport.opens(), 0);
}

TEST(HidInputThread, ARecordingReplaysToTheLiveSamples) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("mtcut-hid-live-" + std::to_string(::getpid()) + ".hidrec")).string();
  test::FakeTransport transport(kSpaceMouse);
  for (int k = 0; k < 30; ++k) transport.queue_bytes(test::spacemouse_report(1 + k % 2, 300, -10 * k, 7 * k));
  transport.queue_bytes({3, 0x01});
  transport.queue_bytes({1, 0x00});  // too short
  transport.queue_unplug(1);
  for (int k = 0; k < 10; ++k) transport.queue_bytes(test::spacemouse_report(1, -300, 0, 100));
  InputDef def = fast_retry();
  def.record_path = path;
  const Profile profile = load_profile("spacemouse");
  std::vector<Sample> live;
  {
    InputThread input(transport, profile, def);
    input.start();
    ASSERT_TRUE(input.wait_until([](const InputStatus& s) { return s.samples == 42; }, seconds(10)));
    input.stop();
    live = input.take_all();
  }
  ASSERT_EQ(live.size(), 42u);
  DecodeCounts counts;
  const std::vector<Sample> replayed = replay_recording(path, profile, &counts);
  EXPECT_TRUE(test::same_samples(live, replayed));
  EXPECT_EQ(counts.too_short, 1);
  EXPECT_TRUE(live[30].pose.engaged);
  EXPECT_FALSE(live[31].pose.engaged);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mtcut::app::hid
