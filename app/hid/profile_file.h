#pragma once
// Reading device profiles (config/hid/NAME.toml) strictly: an unknown key, a
// wrong type, a field that does not fit its bits, or a mapping that names a
// missing field is one InputError "file:line: what". Finding the profile
// that fits a device.

#include <optional>
#include <string>
#include <vector>

#include "app/hid/profile.h"
#include "app/hid/transport.h"

namespace mtcut::app::hid {

// config/hid (under config_dir()).
std::string profile_dir();

// The shipped profiles' files, sorted by name.
std::vector<std::string> list_profile_files();

// `name_or_path` is a profile name in profile_dir() (spacemouse, pen_tablet,
// gamepad) or a .toml path.
Profile load_profile(const std::string& name_or_path);

// Every profile in profile_dir(), sorted by name.
std::vector<Profile> load_all_profiles();

// How well `profile` fits `device`: 0 no, 1 by usage only, 2 by vendor/product.
int match_score(const Profile& profile, const DeviceInfo& device);

// The best-fitting profile (highest score, first by name on a tie), or null.
const Profile* find_profile(const std::vector<Profile>& profiles, const DeviceInfo& device);

}  // namespace mtcut::app::hid
