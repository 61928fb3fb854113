#include "app/hid/recording.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "engine/input_error.h"

namespace mtcut::app::hid {
namespace {

constexpr const char* kHeader = "# mtcut-hidrec 1";

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "S.UUUUUU" -> microseconds, or -1 when malformed.
std::int64_t parse_time(const std::string& token) {
  const auto dot = token.find('.');
  if (dot == std::string::npos || dot == 0 || token.size() - dot - 1 != 6 || dot > 12) return -1;
  std::int64_t us = 0;
  for (std::size_t i = 0; i < token.size(); ++i) {
    if (i == dot) continue;
    if (token[i] < '0' || token[i] > '9') return -1;
    us = us * 10 + (token[i] - '0');
  }
  return us;
}

}  // namespace

Recorder::Recorder(const std::string& path) : path_(path), out_(path) {
  if (!out_) throw engine::InputError(path + ": cannot create the HID recording");
  out_ << kHeader << "\n";
  out_.flush();
}

void Recorder::comment(const std::string& text) {
  out_ << "# " << text << "\n";
  out_.flush();
}

void Recorder::write(const RawEvent& event) {
  out_ << format_event(event) << "\n";
  out_.flush();  // a crash or an unplugged laptop keeps what was recorded
}

std::string format_event(const RawEvent& event) {
  char time[32];
  std::snprintf(time, sizeof time, "%lld.%06lld", static_cast<long long>(event.time_us / 1000000),
                static_cast<long long>(event.time_us % 1000000));
  std::string line = time;
  if (event.kind == RawEvent::Kind::unplugged) return line + " unplugged";
  static const char* digits = "0123456789abcdef";
  for (const std::uint8_t b : event.bytes) {
    line += ' ';
    line += digits[b >> 4];
    line += digits[b & 15];
  }
  return line;
}

std::vector<RawEvent> read_recording(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw engine::InputError(path + ": cannot open the HID recording");
  std::vector<RawEvent> events;
  std::string line;
  std::size_t number = 0;
  const auto fail = [&](const std::string& what) {
    throw engine::InputError(path + ":" + std::to_string(number) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) {
      if (line != kHeader) fail("not an mtcut HID recording (the first line must be '" + std::string(kHeader) + "')");
      continue;
    }
    if (line.empty() || line[0] == '#') continue;
    std::istringstream tokens(line);
    std::string token;
    tokens >> token;
    RawEvent event;
    event.time_us = parse_time(token);
    if (event.time_us < 0) fail("'" + token + "' is not a time in seconds with six decimals");
    if (!events.empty() && event.time_us < events.back().time_us) fail("time goes backwards");
    while (tokens >> token) {
      if (token == "unplugged" && event.bytes.empty() && event.kind == RawEvent::Kind::report) {
        event.kind = RawEvent::Kind::unplugged;
        continue;
      }
      if (event.kind == RawEvent::Kind::unplugged) fail("nothing may follow 'unplugged'");
      if (token.size() != 2 || hex_digit(token[0]) < 0 || hex_digit(token[1]) < 0)
        fail("'" + token + "' is not a byte in hex");
      event.bytes.push_back(static_cast<std::uint8_t>(hex_digit(token[0]) * 16 + hex_digit(token[1])));
    }
    if (event.kind == RawEvent::Kind::report && event.bytes.empty()) fail("a report line needs its bytes");
    events.push_back(std::move(event));
  }
  if (number == 0) fail("empty file, not an mtcut HID recording");
  return events;
}

std::string recorded_profile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw engine::InputError(path + ": cannot open the HID recording");
  std::string line;
  const std::string key = "# profile ";
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) return line.substr(key.size());
  return "";
}

std::vector<Sample> replay_recording(const std::string& path, const Profile& profile, DecodeCounts* counts) {
  return decode_events(profile, read_recording(path), counts);
}

std::span<const Sample> samples_between(std::span<const Sample> samples, std::int64_t t0_us, std::int64_t t1_us) {
  const auto by_time = [](const Sample& s, std::int64_t t) { return s.time_us <= t; };
  const auto begin = std::lower_bound(samples.begin(), samples.end(), t0_us, by_time);
  const auto end = std::lower_bound(begin, samples.end(), t1_us, by_time);
  return {begin, end};
}

}  // namespace mtcut::app::hid
