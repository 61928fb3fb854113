// The real hidapi enumeration runs here and opening a missing node fails
// cleanly. What it finds is checked against the kernel's own list of hidraw
// nodes (/sys/class/hidraw), so the check runs on a machine without devices
// too: hidapi may leave out a node whose device it cannot describe, never
// add one (it lists a node once per top-level collection of its report
// descriptor).

#include "app/hid/hidapi_transport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

namespace mtcut::app::hid {
namespace {

std::set<std::string> hidraw_nodes() {
  std::set<std::string> nodes;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/sys/class/hidraw", error))
    nodes.insert("/dev/" + entry.path().filename().string());
  return nodes;
}

TEST(HidapiTransport, EnumeratesTheKernelsHidrawNodes) {
  HidapiTransport transport;
  const std::vector<DeviceInfo> devices = transport.enumerate();
  const std::set<std::string> nodes = hidraw_nodes();
  std::cout << "hidapi: " << devices.size() << " of " << nodes.size() << " hidraw nodes\n";
  for (const DeviceInfo& d : devices) {
    EXPECT_TRUE(nodes.contains(d.path)) << d.path << " is no hidraw node of this machine";
    std::cout << "hidapi: " << d.path << " " << d.product << "\n";
  }
  EXPECT_EQ(transport.enumerate().size(), devices.size());
}

TEST(HidapiTransport, OpeningAMissingNodeFails) {
  HidapiTransport transport;
  const OpenResult r = transport.open("/dev/hidraw-mtcut-does-not-exist");
  EXPECT_EQ(r.status, OpenStatus::failed);
  EXPECT_EQ(r.device, nullptr);
  EXPECT_FALSE(r.message.empty());
}

TEST(HidapiTransport, WideStringsBecomeUtf8) {
  EXPECT_EQ(to_utf8(nullptr), "");
  EXPECT_EQ(to_utf8(L"SpaceMouse"), "SpaceMouse");
  EXPECT_EQ(to_utf8(L"\u00e9\u20ac"), "\xc3\xa9\xe2\x82\xac");
}

}  // namespace
}  // namespace mtcut::app::hid
