// End-to-end: `mtcut hid list` and `mtcut hid monitor` as a user runs them.

#include <gtest/gtest.h>

#include "app/hid/hidapi_transport.h"
#include "tests/app/run_mtcut.h"

namespace mtcut::test {
namespace {

bool no_devices() {
  app::hid::HidapiTransport transport;
  return transport.enumerate().empty();
}

TEST(HidCommand, ListRunsAndSaysWhenThereIsNoDevice) {
  const CommandResult r = run_mtcut("hid list");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  if (no_devices()) {
    EXPECT_NE(r.out.find("no HID device found\n"), std::string::npos) << r.out;
  }
  EXPECT_NE(r.out.find(": gamepad pen_tablet spacemouse\n"), std::string::npos) << r.out;
}

TEST(HidCommand, MonitorWithoutTheDeviceIsAOneLineError) {
  if (!no_devices()) GTEST_SKIP() << "HID devices present";
  CommandResult r = run_mtcut("hid monitor --profile spacemouse --seconds 0.1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mtcut: no connected HID device matches profile 'spacemouse' (see `mtcut hid list`)\n");
  r = run_mtcut("hid monitor --seconds 0.1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mtcut: no connected HID device has a profile (see `mtcut hid list`)\n");
}

TEST(HidCommand, AnUnknownProfileIsAOneLineError) {
  const CommandResult r = run_mtcut("hid monitor --profile trackball");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("mtcut: HID profile 'trackball': no such profile"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
}

TEST(HidCommand, HidNeedsASubcommand) {
  EXPECT_EQ(run_mtcut("hid").exit_code, 2);
}

}  // namespace
}  // namespace mtcut::test
