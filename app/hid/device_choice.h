#pragma once
// Which profile and device a command uses: the profile named (or, without
// one, the best fit among the shipped profiles for a connected device) and
// the device path asked for (or, without one, the first the profile fits).

#include <string>

#include "app/hid/profile.h"
#include "app/hid/transport.h"

namespace mtcut::app::hid {

struct DeviceChoice {
  Profile profile;
  std::string device;  // "" : the first device the profile matches, looked up on every (re)connection
};

// Throws InputError when no connected device fits (see `mtcut hid list`), or
// the named profile does not exist. With `wait_for_device`, a named profile
// is taken even when its device is not connected (the input thread looks
// for it again every second).
DeviceChoice choose_device(Transport& transport, const std::string& profile, const std::string& device,
                           bool wait_for_device = false);

}  // namespace mtcut::app::hid
