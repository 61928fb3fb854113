#include "app/hid/device_choice.h"

#include "app/hid/profile_file.h"
#include "engine/input_error.h"

namespace mtcut::app::hid {

DeviceChoice choose_device(Transport& transport, const std::string& profile, const std::string& device,
                           bool wait_for_device) {
  const std::vector<Profile> profiles =
      profile.empty() ? load_all_profiles() : std::vector<Profile>{load_profile(profile)};
  for (const DeviceInfo& d : transport.enumerate()) {
    if (!device.empty() && d.path != device) continue;
    if (const Profile* p = find_profile(profiles, d)) return {*p, device};
    if (!device.empty() && !profile.empty()) return {profiles.front(), device};
  }
  if (wait_for_device && !profile.empty()) return {profiles.front(), device};
  if (!device.empty())
    throw engine::InputError("--device " + device + ": no such HID device, or no profile fits it (see `mtcut hid list`; give --profile)");
  if (!profile.empty())
    throw engine::InputError("no connected HID device matches profile '" + profile + "' (see `mtcut hid list`)");
  throw engine::InputError(std::string("no connected HID device has a profile (see `mtcut hid list`") +
                           (wait_for_device ? "; name one, --hid PROFILE, to wait for its device)" : ")"));
}

}  // namespace mtcut::app::hid
