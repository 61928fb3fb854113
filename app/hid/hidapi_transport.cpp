#include "app/hid/hidapi_transport.h"

#include <hidapi/hidapi.h>
#include <unistd.h>

#include <cerrno>

#include "engine/input_error.h"

namespace mtcut::app::hid {
namespace {

class HidapiDevice : public Device {
 public:
  explicit HidapiDevice(hid_device* device) : device_(device) {}
  ~HidapiDevice() override { hid_close(device_); }
  HidapiDevice(const HidapiDevice&) = delete;
  HidapiDevice& operator=(const HidapiDevice&) = delete;

  int read(std::span<std::uint8_t> buffer, int timeout_ms) override {
    return hid_read_timeout(device_, buffer.data(), buffer.size(), timeout_ms);
  }
  std::string error() const override { return to_utf8(hid_error(device_)); }

 private:
  hid_device* device_;
};

}  // namespace

std::string to_utf8(const wchar_t* text) {
  std::string out;
  if (!text) return out;
  for (; *text; ++text) {
    const auto c = static_cast<std::uint32_t>(*text);
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xc0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3f));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xe0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
      out += static_cast<char>(0x80 | (c & 0x3f));
    } else {
      out += static_cast<char>(0xf0 | ((c >> 18) & 0x07));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3f));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
      out += static_cast<char>(0x80 | (c & 0x3f));
    }
  }
  return out;
}

HidapiTransport::HidapiTransport() {
  if (hid_init() != 0) throw engine::InputError("hidapi: cannot initialise: " + to_utf8(hid_error(nullptr)));
}

HidapiTransport::~HidapiTransport() { hid_exit(); }

std::vector<DeviceInfo> HidapiTransport::enumerate() {
  std::vector<DeviceInfo> devices;
  hid_device_info* list = hid_enumerate(0, 0);  // null: no device (or no hidraw at all)
  for (const hid_device_info* d = list; d; d = d->next) {
    DeviceInfo info;
    info.path = d->path ? d->path : "";
    info.vendor_id = d->vendor_id;
    info.product_id = d->product_id;
    info.usage_page = d->usage_page;
    info.usage = d->usage;
    info.interface_number = d->interface_number;
    info.manufacturer = to_utf8(d->manufacturer_string);
    info.product = to_utf8(d->product_string);
    info.serial = to_utf8(d->serial_number);
    devices.push_back(std::move(info));
  }
  hid_free_enumeration(list);
  return devices;
}

OpenResult HidapiTransport::open(const std::string& path) {
  OpenResult result;
  if (hid_device* device = hid_open_path(path.c_str())) {
    result.device = std::make_unique<HidapiDevice>(device);
    result.status = OpenStatus::ok;
    return result;
  }
  result.message = to_utf8(hid_error(nullptr));
  // hidapi's message does not say why in a form we can test; the node does.
  errno = 0;
  if (::access(path.c_str(), R_OK | W_OK) != 0 && errno == EACCES) result.status = OpenStatus::permission_denied;
  if (result.message.empty()) result.message = "cannot open " + path;
  return result;
}

}  // namespace mtcut::app::hid
