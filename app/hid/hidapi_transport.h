#pragma once
// The real Transport over hidapi (the hidraw backend on Linux). One instance
// owns hid_init()/hid_exit(); create one per process.

#include "app/hid/transport.h"

namespace mtcut::app::hid {

class HidapiTransport : public Transport {
 public:
  // Throws InputError when hidapi cannot initialise.
  HidapiTransport();
  ~HidapiTransport() override;
  HidapiTransport(const HidapiTransport&) = delete;
  HidapiTransport& operator=(const HidapiTransport&) = delete;

  // Every HID device; empty when there is none (never an error).
  std::vector<DeviceInfo> enumerate() override;
  // permission_denied when the node exists but is not readable and writable.
  OpenResult open(const std::string& path) override;
};

// hidapi's wide strings as UTF-8 ("" for null).
std::string to_utf8(const wchar_t* text);

}  // namespace mtcut::app::hid
