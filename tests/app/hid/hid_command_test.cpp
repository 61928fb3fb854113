// End-to-end: `mtcut hid list` and `mtcut hid monitor` as a user runs them.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

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

TEST(HidCommand, ReplayPrintsTheDecodedPosesAndTheRejections) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("mtcut-hid-cmd-" + std::to_string(::getpid()) + ".hidrec")).string();
  std::ofstream(path) << "# mtcut-hidrec 1\n"
                         "0.000000 01 5e 01 00 00 00 00\n"  // tx = 350
                         "0.010000 01 5e 01 00 00 00 00\n"
                         "0.020000 03 01\n"                 // left button: blade on
                         "0.030000 07 00\n"                 // unknown id
                         "0.040000 unplugged\n";
  CommandResult r = run_mtcut("hid replay " + quoted(path) + " --profile spacemouse");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out,
            "    0.000000  tip   0.0400   0.0000   0.0600  base   0.0400   0.0000   0.1600  -\n"
            "    0.010000  tip   0.0410   0.0000   0.0600  base   0.0410   0.0000   0.1600  -\n"
            "    0.020000  tip   0.0420   0.0000   0.0600  base   0.0420   0.0000   0.1600  engaged\n"
            "    0.040000  tip   0.0420   0.0000   0.0600  base   0.0420   0.0000   0.1600  -\n"
            "3 reports decoded, 1 rejected (too short 0, unknown report id 1, out of range 0)\n");
  std::ofstream(path) << "# mtcut-hidrec 1\n0.000000 01 zz\n";
  r = run_mtcut("hid replay " + quoted(path) + " --profile spacemouse");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mtcut: " + path + ":2: 'zz' is not a byte in hex\n");
  std::filesystem::remove(path);
}

TEST(HidCommand, HidNeedsASubcommand) {
  EXPECT_EQ(run_mtcut("hid").exit_code, 2);
}

}  // namespace
}  // namespace mtcut::test
