#pragma once
// The seam between mtcut and the HID system: enumerate devices, open one,
// read its input reports. hidapi_transport.h is the real one; tests inject a
// device that plays recorded bytes or errors.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace mtcut::app::hid {

// What the system tells about a HID device (one entry per top-level collection).
struct DeviceInfo {
  std::string path;          // e.g. /dev/hidraw3
  int vendor_id = 0;
  int product_id = 0;
  int usage_page = 0;
  int usage = 0;
  int interface_number = -1;
  std::string manufacturer;  // UTF-8; may be empty
  std::string product;
  std::string serial;
};

// An open device.
class Device {
 public:
  virtual ~Device() = default;
  // Waits up to timeout_ms for one input report and copies it into `buffer`.
  // Returns its size, 0 on timeout, -1 when the device is gone or failed.
  virtual int read(std::span<std::uint8_t> buffer, int timeout_ms) = 0;
  // The last failure, for a message.
  virtual std::string error() const = 0;
};

enum class OpenStatus { ok, permission_denied, failed };

struct OpenResult {
  std::unique_ptr<Device> device;  // set when status == ok
  OpenStatus status = OpenStatus::failed;
  std::string message;             // why it failed
};

class Transport {
 public:
  virtual ~Transport() = default;
  virtual std::vector<DeviceInfo> enumerate() = 0;
  virtual OpenResult open(const std::string& path) = 0;
};

}  // namespace mtcut::app::hid
