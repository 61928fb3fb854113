#include "app/hid/hid_command.h"

#include <csignal>
#include <cstdio>
#include <iostream>

#include "app/cli_checks.h"
#include "app/hid/device_choice.h"
#include "app/hid/hid_path.h"
#include "app/hid/hidapi_transport.h"
#include "app/hid/input_thread.h"
#include "app/hid/profile_file.h"
#include "app/hid/recording.h"
#include "engine/input_error.h"
#include "sim/scalpel_trace.h"

namespace mtcut::app::hid {
namespace {

struct MonitorOptions {
  std::string profile;
  std::string device;
  double seconds = 0;
  std::string record;
};

volatile std::sig_atomic_t interrupted = 0;

std::string hex4(int v) {
  char s[8];
  std::snprintf(s, sizeof s, "%04x", v & 0xffff);
  return s;
}

void run_list() {
  const std::vector<Profile> profiles = load_all_profiles();
  HidapiTransport transport;
  const std::vector<DeviceInfo> devices = transport.enumerate();
  if (devices.empty()) std::cout << "no HID device found\n";
  for (const DeviceInfo& d : devices) {
    const Profile* p = find_profile(profiles, d);
    std::cout << hex4(d.vendor_id) << ":" << hex4(d.product_id) << "  usage " << hex4(d.usage_page) << ":"
              << hex4(d.usage) << "  " << d.path << "  \"" << d.manufacturer << "\" \"" << d.product << "\"  "
              << (p ? "profile " + p->name : std::string("no profile")) << "\n";
  }
  std::cout << "profiles (" << profile_dir() << "):";
  for (const Profile& p : profiles) std::cout << " " << p.name;
  std::cout << "\n";
}

void print_sample(const Sample& s) {
  std::printf("%12.6f  tip %8.4f %8.4f %8.4f  base %8.4f %8.4f %8.4f  %s\n", s.time(), s.pose.tip.x(), s.pose.tip.y(),
              s.pose.tip.z(), s.pose.base.x(), s.pose.base.y(), s.pose.base.z(), s.pose.engaged ? "engaged" : "-");
}

void run_monitor(const MonitorOptions& options) {
  HidapiTransport transport;
  auto [profile, device] = choose_device(transport, options.profile, options.device);
  InputDef def;
  def.device_path = device;
  def.record_path = options.record;
  InputThread input(transport, profile, def);
  input.start();
  // The first connection decides: a device we cannot open is the user's to fix.
  input.wait_until([](const InputStatus& s) { return s.connected || s.open_failures > 0 || s.stopped; },
                   std::chrono::seconds(10));
  if (!input.status().connected) {
    input.stop();
    for (const InputEvent& e : input.take_events())
      if (e.kind == InputEvent::Kind::permission_denied || e.kind == InputEvent::Kind::open_failed ||
          e.kind == InputEvent::Kind::no_device)
        throw engine::InputError(e.message);
    throw engine::InputError("the HID device did not open in time");
  }
  interrupted = 0;
  auto previous = std::signal(SIGINT, [](int) { interrupted = 1; });
  const auto end = input.epoch() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                       std::chrono::duration<double>(options.seconds));
  long rejected = 0;
  while (!interrupted && (options.seconds <= 0 || std::chrono::steady_clock::now() < end)) {
    const long seen = input.status().samples;
    input.wait_until([seen](const InputStatus& s) { return s.samples != seen; }, std::chrono::milliseconds(50));
    for (const InputEvent& e : input.take_events()) std::fprintf(stderr, "mtcut: hid: %s\n", e.message.c_str());
    for (const Sample& s : input.take_all()) print_sample(s);
    const InputStatus status = input.status();
    if (status.counts.rejected() != rejected) {
      rejected = status.counts.rejected();
      std::fprintf(stderr, "mtcut: hid: rejected: %s\n", status.last_reject.c_str());
    }
    std::fflush(stdout);
  }
  std::signal(SIGINT, previous);
  input.stop();
  for (const Sample& s : input.take_all()) print_sample(s);
  const InputStatus status = input.status();
  const DecodeCounts& c = status.counts;
  std::printf("%ld reports decoded, %ld rejected (too short %ld, unknown report id %ld, out of range %ld)\n",
              c.accepted, c.rejected(), c.too_short, c.unknown_report, c.out_of_range);
  if (!options.record.empty()) std::printf("raw reports recorded to %s\n", options.record.c_str());
}

void run_replay(const std::string& recording, const std::string& profile_name) {
  const Profile profile = load_profile(profile_name);
  DecodeCounts c;
  for (const Sample& s : replay_recording(recording, profile, &c)) print_sample(s);
  std::printf("%ld reports decoded, %ld rejected (too short %ld, unknown report id %ld, out of range %ld)\n",
              c.accepted, c.rejected(), c.too_short, c.unknown_report, c.out_of_range);
}

// The recording decoded with `profile_name` as a scalpel trace: the path
// `mtcut run --hid-replay` feeds the World (hid_path.h).
void run_convert(const std::string& recording, const std::string& profile_name, const std::string& out) {
  const Profile profile = load_profile(profile_name);
  DecodeCounts c;
  const std::vector<Sample> samples = replay_recording(recording, profile, &c);
  const std::vector<sim::ScalpelKeyframe> keys = to_keyframes(profile, samples);
  sim::write_scalpel_trace(out, keys);
  std::printf("%s: %zu poses from %ld reports (%ld rejected) over %.3f s\n", out.c_str(), keys.size(), c.accepted,
              c.rejected(), keys.back().time);
}

}  // namespace

void register_hid_command(CLI::App& app) {
  CLI::App* hid = app.add_subcommand("hid", "HID input devices (3D mouse, pen tablet, gamepad) as the scalpel");
  hid->require_subcommand(1);

  CLI::App* list = hid->add_subcommand("list", "every HID device: ids, usage, path, names, and the profile that fits");
  list->callback([] { run_list(); });

  auto options = std::make_shared<MonitorOptions>();
  CLI::App* monitor = hid->add_subcommand("monitor", "live decoded scalpel poses from a HID device");
  monitor->add_option("--profile", options->profile, "a profile name in config/hid or a .toml file (default: the one that fits)");
  monitor->add_option("--device", options->device, "the device's path (default: the first one a profile fits)");
  monitor->add_option("--seconds", options->seconds, "stop after this long (default: until Ctrl-C)")
      ->check(non_negative_number());
  monitor->add_option("--record-hid", options->record, "record the raw reports to this file (.hidrec)");
  monitor->callback([options] { run_monitor(*options); });

  auto replay = std::make_shared<std::pair<std::string, std::string>>();
  CLI::App* replay_cmd = hid->add_subcommand("replay", "decode a raw recording (.hidrec) and print its poses");
  replay_cmd->add_option("recording", replay->first, "a file written by --record-hid")->required();
  replay_cmd->add_option("--profile", replay->second, "the profile to decode it with")->required();
  replay_cmd->callback([replay] { run_replay(replay->first, replay->second); });

  struct ConvertOptions {
    std::string recording, profile, out;
  };
  auto convert = std::make_shared<ConvertOptions>();
  CLI::App* convert_cmd = hid->add_subcommand(
      "convert", "decode a raw recording (.hidrec) into a scalpel trace (CSV) that a scenario can replay");
  convert_cmd->add_option("recording", convert->recording, "a file written by --record-hid")->required();
  convert_cmd->add_option("--profile", convert->profile, "the profile to decode it with")->required();
  convert_cmd->add_option("-o,--out", convert->out, "the trace file to write")->required();
  convert_cmd->callback([convert] { run_convert(convert->recording, convert->profile, convert->out); });
}

}  // namespace mtcut::app::hid
