#include "app/hid/profile_file.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "app/material_file.h"
#include "app/toml_table.h"
#include "engine/input_error.h"

namespace mtcut::app::hid {
namespace {

// An optional integer in [lo, hi].
std::optional<std::int64_t> bounded_integer(TomlTable& t, const std::string& key, std::int64_t lo, std::int64_t hi) {
  const auto value = t.integer(key);
  if (value && (*value < lo || *value > hi))
    t.fail(t.node(key), "'" + key + "' must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return value;
}

// An optional array of integers in [lo, hi].
std::vector<int> integer_list(TomlTable& t, const std::string& key, int lo, int hi) {
  std::vector<int> out;
  const toml::node* n = t.node(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) t.fail(n, "'" + key + "' must be an array of integers");
  for (const toml::node& item : *a) {
    const auto v = item.value_exact<std::int64_t>();
    if (!item.is_integer() || !v || *v < lo || *v > hi)
      t.fail(&item, "'" + key + "' must hold integers in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    out.push_back(static_cast<int>(*v));
  }
  return out;
}

// An optional number in [lo, hi] (hi_open: strictly below hi).
void read_number(TomlTable& t, const std::string& key, double lo, double hi, bool hi_open, double& out) {
  const auto value = t.number(key);
  if (!value) return;
  if (*value < lo || *value > hi || (hi_open && *value >= hi))
    t.fail(t.node(key), "'" + key + "' must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                            (hi_open ? ")" : "]"));
  out = *value;
}

void read_match(TomlTable& t, MatchDef& match) {
  match.vendor_ids = integer_list(t, "vendor_ids", 0, 0xffff);
  match.product_ids = integer_list(t, "product_ids", 0, 0xffff);
  if (const auto page = bounded_integer(t, "usage_page", 0, 0xffff)) match.usage_page = static_cast<int>(*page);
  match.usages = integer_list(t, "usages", 0, 0xffff);
  if (!match.usages.empty() && match.usage_page < 0) t.fail(t.node("usages"), "'usages' needs 'usage_page'");
  if (match.vendor_ids.empty() && match.usage_page < 0)
    t.fail(nullptr, "[match] needs 'vendor_ids' or 'usage_page'");
  t.finish();
}

FieldDef read_field(TomlTable& t) {
  FieldDef f;
  const auto name = t.string("name");
  if (!name || name->empty()) t.fail(nullptr, "a field needs a 'name'");
  f.name = *name;
  f.byte = static_cast<int>(bounded_integer(t, "byte", 0, 4095).value_or(0));
  f.bit = static_cast<int>(bounded_integer(t, "bit", 0, 7).value_or(0));
  f.bits = static_cast<int>(bounded_integer(t, "bits", 1, 32).value_or(8));
  if (const auto s = t.boolean("signed")) f.is_signed = *s;
  const std::int64_t lo = f.is_signed ? -(std::int64_t{1} << (f.bits - 1)) : 0;
  const std::int64_t hi = f.is_signed ? (std::int64_t{1} << (f.bits - 1)) - 1 : (std::int64_t{1} << f.bits) - 1;
  f.logical_min = bounded_integer(t, "min", lo, hi).value_or(lo);
  f.logical_max = bounded_integer(t, "max", lo, hi).value_or(hi);
  if (f.logical_min >= f.logical_max) t.fail(t.node("max"), "field '" + f.name + "': 'min' must be below 'max'");
  t.finish();
  return f;
}

void read_reports(TomlTable& root, Profile& profile) {
  std::map<std::string, int> names;
  std::vector<TomlTable> reports = root.tables("report");
  if (reports.empty()) root.fail(nullptr, "a profile needs at least one [[report]]");
  for (TomlTable& t : reports) {
    ReportDef report;
    const auto id = bounded_integer(t, "id", 0, 255);
    if (!id) t.fail(nullptr, "a [[report]] needs an 'id' (0 when the device does not number its reports)");
    report.id = static_cast<int>(*id);
    for (const ReportDef& other : profile.reports)
      if (other.id == report.id) t.fail(t.node("id"), "report id " + std::to_string(report.id) + " appears twice");
    if (!profile.reports.empty() && (report.id == 0 || profile.reports.front().id == 0))
      t.fail(t.node("id"), "report id 0 (unnumbered) must be the profile's only report");
    std::vector<TomlTable> fields = t.tables("fields");
    if (fields.empty()) t.fail(nullptr, "a [[report]] needs 'fields'");
    report.size = report.id == 0 ? 0 : 1;
    for (TomlTable& ft : fields) {
      FieldDef field = read_field(ft);
      if (report.id != 0 && field.byte == 0) ft.fail(ft.node("byte"), "field '" + field.name + "': byte 0 is the report id");
      if (!names.emplace(field.name, static_cast<int>(profile.fields.size())).second)
        ft.fail(nullptr, "field '" + field.name + "' is defined twice");
      report.size = std::max(report.size, (field.byte * 8 + field.bit + field.bits + 7) / 8);
      report.fields.push_back(static_cast<int>(profile.fields.size()));
      profile.fields.push_back(std::move(field));
    }
    t.finish();
    profile.reports.push_back(std::move(report));
  }
}

// The index of the field named by `key`, or -1 when the key is absent.
int field_ref(TomlTable& t, const std::string& key, const Profile& profile) {
  const auto name = t.string(key);
  if (!name) return -1;
  for (std::size_t i = 0; i < profile.fields.size(); ++i)
    if (profile.fields[i].name == *name) return static_cast<int>(i);
  t.fail(t.node(key), "'" + key + "' names no field of this profile: '" + *name + "'");
}

AxisTarget read_target(TomlTable& t) {
  static const std::map<std::string, AxisTarget> targets = {
      {"x", AxisTarget::x},   {"y", AxisTarget::y},   {"z", AxisTarget::z},           {"rx", AxisTarget::rx},
      {"ry", AxisTarget::ry}, {"rz", AxisTarget::rz}, {"tilt_x", AxisTarget::tilt_x}, {"tilt_y", AxisTarget::tilt_y}};
  const auto name = t.string("target");
  if (!name) t.fail(nullptr, "an axis needs a 'target' (x, y, z, rx, ry, rz, tilt_x, tilt_y)");
  const auto it = targets.find(*name);
  if (it == targets.end())
    t.fail(t.node("target"), "'target' must be one of x, y, z, rx, ry, rz, tilt_x, tilt_y, not '" + *name + "'");
  return it->second;
}

void read_mapping(TomlTable& t, Profile& profile) {
  MappingDef& m = profile.mapping;
  if (const auto mode = t.string("mode")) {
    if (*mode != "integrate" && *mode != "absolute")
      t.fail(t.node("mode"), "'mode' must be \"integrate\" or \"absolute\", not '" + *mode + "'");
    m.mode = *mode == "integrate" ? PoseMode::integrate : PoseMode::absolute;
  }
  t.read("home", m.home);
  t.read("workspace", m.workspace);
  if (!(m.workspace.minCoeff() > 0)) t.fail(t.node("workspace"), "'workspace' half extents must be positive");
  read_number(t, "blade_length", 1e-4, 1.0, false, m.blade_length);
  read_number(t, "smoothing", 0.0, 1.0, true, m.smoothing);
  read_number(t, "max_dt", 1e-4, 10.0, false, m.max_dt);
  m.engage_field = field_ref(t, "engage", profile);
  if (const auto mode = t.string("engage_mode")) {
    if (*mode != "hold" && *mode != "toggle")
      t.fail(t.node("engage_mode"), "'engage_mode' must be \"hold\" or \"toggle\", not '" + *mode + "'");
    m.engage_mode = *mode == "hold" ? EngageMode::hold : EngageMode::toggle;
  }
  m.depth_field = field_ref(t, "depth", profile);
  read_number(t, "depth_max", 0.0, 1.0, false, m.depth_max);
  if (m.depth_field >= 0 && !t.node("depth_max")) t.fail(t.node("depth"), "'depth' needs 'depth_max'");
  bool rotation = false, tilt = false;
  for (TomlTable& at : t.tables("axes")) {
    AxisDef axis;
    axis.field = field_ref(at, "field", profile);
    if (axis.field < 0) at.fail(nullptr, "an axis needs a 'field'");
    axis.target = read_target(at);
    const auto gain = at.number("gain");
    if (!gain) at.fail(nullptr, "an axis needs a 'gain'");
    axis.gain = *gain;
    read_number(at, "dead_zone", 0.0, 1.0, true, axis.dead_zone);
    at.finish();
    rotation |= axis.target == AxisTarget::rx || axis.target == AxisTarget::ry || axis.target == AxisTarget::rz;
    tilt |= axis.target == AxisTarget::tilt_x || axis.target == AxisTarget::tilt_y;
    if (rotation && tilt) at.fail(at.node("target"), "an orientation comes from rotation axes or pen tilt, not both");
    if (tilt && m.mode == PoseMode::integrate) at.fail(at.node("target"), "tilt axes need mode = \"absolute\"");
    m.axes.push_back(axis);
  }
  t.finish();
}

}  // namespace

std::string profile_dir() { return config_dir() + "/hid"; }

std::vector<std::string> list_profile_files() {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(profile_dir(), ec))
    if (entry.path().extension() == ".toml") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

Profile load_profile(const std::string& name_or_path) {
  std::string path = name_or_path;
  if (std::filesystem::path(name_or_path).extension() != ".toml") {
    path = profile_dir() + "/" + name_or_path + ".toml";
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
      throw engine::InputError("HID profile '" + name_or_path + "': no such profile (see " + profile_dir() + "/)");
  }
  const toml::table root_table = parse_toml_file(path);
  TomlTable root(root_table, path);
  Profile profile;
  profile.name = std::filesystem::path(path).stem().string();
  profile.file = path;
  root.read("description", profile.description);
  auto match = root.table("match");
  if (!match) root.fail(nullptr, "a profile needs a [match] table");
  read_match(*match, profile.match);
  read_reports(root, profile);
  auto mapping = root.table("mapping");
  if (!mapping) root.fail(nullptr, "a profile needs a [mapping] table");
  read_mapping(*mapping, profile);
  root.finish();
  return profile;
}

std::vector<Profile> load_all_profiles() {
  std::vector<Profile> profiles;
  for (const std::string& file : list_profile_files()) profiles.push_back(load_profile(file));
  return profiles;
}

int match_score(const Profile& profile, const DeviceInfo& device) {
  const MatchDef& m = profile.match;
  const auto has = [](const std::vector<int>& list, int value) {
    return list.empty() || std::find(list.begin(), list.end(), value) != list.end();
  };
  if (!has(m.vendor_ids, device.vendor_id) || !has(m.product_ids, device.product_id)) return 0;
  if (m.usage_page >= 0 && (device.usage_page != m.usage_page || !has(m.usages, device.usage))) return 0;
  return m.vendor_ids.empty() ? 1 : 2;
}

const Profile* find_profile(const std::vector<Profile>& profiles, const DeviceInfo& device) {
  const Profile* best = nullptr;
  int best_score = 0;
  for (const Profile& p : profiles)
    if (const int s = match_score(p, device); s > best_score) best = &p, best_score = s;
  return best;
}

}  // namespace mtcut::app::hid
