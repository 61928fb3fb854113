// The shipped profiles load; faults in a profile are one line "file:line: what".

#include "app/hid/profile_file.h"

#include <gtest/gtest.h>

#include <functional>

#include "engine/input_error.h"
#include "tests/temp_dir.h"

namespace mtcut::app::hid {
namespace {

using mtcut::test::input_error_of;

// A minimal valid profile; tests replace parts of it.
const std::string kValid =
    "description = \"test\"\n"                                       // 1
    "[match]\n"                                                      // 2
    "vendor_ids = [0x1234]\n"                                        // 3
    "[[report]]\n"                                                   // 4
    "id = 1\n"                                                       // 5
    "fields = [\n"                                                   // 6
    "  { name = \"a\", byte = 1, bits = 16, signed = true },\n"      // 7
    "  { name = \"b\", byte = 3, bit = 2, bits = 1 },\n"             // 8
    "]\n"                                                            // 9
    "[mapping]\n"                                                    // 10
    "engage = \"b\"\n"                                               // 11
    "axes = [ { field = \"a\", target = \"x\", gain = 0.1 } ]\n";    // 12

class HidProfileFile : public ::testing::Test {
 protected:
  std::string path() const { return dir_.file("p.toml"); }
  std::string write(const std::string& text) const { return dir_.write("p.toml", text); }
  // kValid with `from` replaced by `to`.
  std::string fault(const std::string& from, const std::string& to) const {
    std::string text = kValid;
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return input_error_of([&] { load_profile(write(text.replace(at, from.size(), to))); });
  }
  mtcut::test::TempDir dir_;
};

TEST_F(HidProfileFile, EveryShippedProfileLoads) {
  const std::vector<Profile> all = load_all_profiles();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].name, "gamepad");
  EXPECT_EQ(all[1].name, "pen_tablet");
  EXPECT_EQ(all[2].name, "spacemouse");
  const Profile sm = load_profile("spacemouse");
  ASSERT_EQ(sm.reports.size(), 3u);
  EXPECT_EQ(sm.reports[0].size, 7);
  EXPECT_EQ(sm.reports[2].size, 2);
  EXPECT_EQ(sm.match.vendor_ids, (std::vector<int>{0x046d, 0x256f}));
  EXPECT_EQ(sm.mapping.mode, PoseMode::integrate);
  EXPECT_EQ(load_profile("pen_tablet").mapping.mode, PoseMode::absolute);
  EXPECT_EQ(load_profile("gamepad").reports[0].id, 0);
}

TEST_F(HidProfileFile, AValidProfileReadsAsWritten) {
  const Profile p = load_profile(write(kValid));
  EXPECT_EQ(p.name, "p");
  ASSERT_EQ(p.fields.size(), 2u);
  EXPECT_EQ(p.fields[0].logical_min, -32768);
  EXPECT_EQ(p.fields[0].logical_max, 32767);
  EXPECT_EQ(p.fields[1].logical_max, 1);
  EXPECT_EQ(p.reports[0].size, 4);
  EXPECT_EQ(p.mapping.engage_field, 1);
  ASSERT_EQ(p.mapping.axes.size(), 1u);
  EXPECT_EQ(p.mapping.axes[0].field, 0);
}

TEST_F(HidProfileFile, FaultsNameTheFileAndLine) {
  EXPECT_EQ(fault("bit = 2, bits = 1", "bit = 2, bits = 1, sign = true"), path() + ":8: unknown key 'report[0].fields[1].sign'");
  EXPECT_EQ(fault("bits = 16, signed = true", "bits = 16, signed = \"yes\""),
            path() + ":7: 'report[0].fields[0].signed' must be true or false, not a string");
  EXPECT_NE(fault("bits = 1 }", "bits = 33 }").find("p.toml:8: 'bits' must be in [1, 32]"), std::string::npos);
  EXPECT_NE(fault("bits = 1 }", "bits = 1, max = 2 }").find("p.toml:8: 'max' must be in [0, 1]"), std::string::npos);
  EXPECT_NE(fault("signed = true }", "signed = true, min = 5, max = 5 }").find("p.toml:7:"), std::string::npos);
  EXPECT_NE(fault("engage = \"b\"", "engage = \"c\"").find("p.toml:11: 'engage' names no field of this profile: 'c'"),
            std::string::npos);
  EXPECT_NE(fault("target = \"x\"", "target = \"w\"").find("p.toml:12: 'target' must be one of"), std::string::npos);
  EXPECT_NE(fault("gain = 0.1", "gain = \"high\"").find("p.toml:12:"), std::string::npos);
  EXPECT_NE(fault("[mapping]\n", "[mapping]\nsmoothing = 1.0\n").find("p.toml:11: 'smoothing' must be in"),
            std::string::npos);
  EXPECT_NE(fault("[mapping]\n", "[mapping]\nmode = \"velocity\"\n").find("p.toml:11: 'mode' must be"),
            std::string::npos);
  EXPECT_NE(fault("name = \"b\", byte = 3", "name = \"a\", byte = 3").find("p.toml:8: field 'a' is defined twice"),
            std::string::npos);
  EXPECT_NE(fault("name = \"a\", byte = 1", "name = \"a\", byte = 0").find("p.toml:7: field 'a': byte 0 is the report id"),
            std::string::npos);
  EXPECT_NE(fault("vendor_ids = [0x1234]", "vendor_ids = [0x12345]").find("p.toml:3: 'vendor_ids' must hold"),
            std::string::npos);
  EXPECT_NE(fault("vendor_ids = [0x1234]", "usages = [2]").find("p.toml:3: 'usages' needs 'usage_page'"),
            std::string::npos);
  EXPECT_NE(fault("description", "descripton").find("p.toml:1: unknown key 'descripton'"), std::string::npos);
  EXPECT_NE(fault("]\n[mapping]", "]\n[[report]]\nid = 1\nfields = [ { name = \"c\", byte = 1 } ]\n[mapping]")
                .find("p.toml:11: report id 1 appears twice"),
            std::string::npos);
  EXPECT_NE(fault("target = \"x\"", "target = \"tilt_x\"").find("p.toml:12: tilt axes need mode = \"absolute\""),
            std::string::npos);
  EXPECT_NE(fault("fields = [\n", "fields = [,\n").find("p.toml:6:"), std::string::npos);  // TOML syntax
  EXPECT_NE(input_error_of([] { load_profile("trackball"); }).find("HID profile 'trackball': no such profile"),
            std::string::npos);
}

TEST_F(HidProfileFile, MatchesByVendorBeforeUsage) {
  const std::vector<Profile> all = load_all_profiles();
  DeviceInfo spacemouse{"/dev/hidraw0", 0x256f, 0xc635, 0x01, 0x08, 0, "3Dconnexion", "SpaceMouse Compact", ""};
  DeviceInfo logitech_mouse{"/dev/hidraw1", 0x046d, 0xc077, 0x01, 0x02, 0, "Logitech", "USB Optical Mouse", ""};
  DeviceInfo pad{"/dev/hidraw2", 0x0079, 0x0006, 0x01, 0x04, 0, "DragonRise", "Generic USB Joystick", ""};
  DeviceInfo pen{"/dev/hidraw3", 0x256c, 0x006d, 0x0d, 0x02, 0, "HUION", "Tablet", ""};
  ASSERT_NE(find_profile(all, spacemouse), nullptr);
  EXPECT_EQ(find_profile(all, spacemouse)->name, "spacemouse");
  EXPECT_EQ(match_score(all[2], spacemouse), 2);
  EXPECT_EQ(find_profile(all, logitech_mouse), nullptr);
  EXPECT_EQ(find_profile(all, pad)->name, "gamepad");
  EXPECT_EQ(match_score(all[0], pad), 1);
  EXPECT_EQ(find_profile(all, pen)->name, "pen_tablet");
}

}  // namespace
}  // namespace mtcut::app::hid
