// The real hidapi enumeration runs here (on a machine without devices it
// finds none) and opening a missing node fails cleanly.

#include "app/hid/hidapi_transport.h"

#include <gtest/gtest.h>

namespace mtcut::app::hid {
namespace {

TEST(HidapiTransport, EnumeratesWithoutError) {
  HidapiTransport transport;
  const std::vector<DeviceInfo> devices = transport.enumerate();
  if (devices.empty()) std::cout << "hidapi: no HID device on this machine\n";
  for (const DeviceInfo& d : devices) {
    EXPECT_FALSE(d.path.empty());
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
