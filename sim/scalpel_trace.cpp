#include "sim/scalpel_trace.h"

#include <charconv>
#include <cmath>
#include <ostream>
#include <vector>

#include "engine/atomic_file.h"
#include "engine/input_error.h"
#include "engine/io/line_reader.h"

namespace mtcut::sim {
namespace {

constexpr std::size_t kFields = 8;

// The shortest text that reads back as exactly `value`.
void put_real(std::ostream& out, double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.write(buffer, end - buffer);
}

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string_view::npos; start = comma + 1)
    fields.push_back(line.substr(start, comma - start));
  fields.push_back(line.substr(start));
  return fields;
}

// Reads the rows of a trace, failing with "path:line: reason".
class TraceParser {
 public:
  explicit TraceParser(std::string path) : path_(std::move(path)) {}

  ScalpelPath parse(std::string_view text) {
    std::vector<ScalpelKeyframe> samples;
    std::size_t line_no = 0;
    for (std::size_t start = 0; start < text.size();) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      std::string_view line = text.substr(start, end - start);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      start = end + 1;
      line_ = ++line_no;
      if (line_no == 1) {
        if (line != kScalpelTraceHeader)
          fail("the header must be '" + std::string(kScalpelTraceHeader) + "', not " + engine::quote_token(line));
        continue;
      }
      if (line.empty()) continue;  // a blank line (the last line end)
      samples.push_back(row(line));
      if (samples.size() > 1 && !(samples.back().time > samples[samples.size() - 2].time))
        fail("time " + std::string(line.substr(0, line.find(','))) + " is not after the previous sample's");
    }
    line_ = 0;
    if (samples.empty()) fail("the trace has no samples");
    return ScalpelPath(std::move(samples));
  }

 private:
  ScalpelKeyframe row(std::string_view line) const {
    const auto fields = split_commas(line);
    if (fields.size() != kFields)
      fail("expected " + std::to_string(kFields) + " comma-separated fields, found " + std::to_string(fields.size()));
    static const char* names[kFields] = {"time", "base_x", "base_y", "base_z", "tip_x", "tip_y", "tip_z", "engaged"};
    double v[kFields - 1];
    for (std::size_t i = 0; i + 1 < kFields; ++i)
      if (!engine::parse_real(fields[i], v[i]) || !std::isfinite(v[i]))
        fail(std::string(names[i]) + " must be a finite number, not " + engine::quote_token(fields[i]));
    if (fields[7] != "0" && fields[7] != "1") fail("engaged must be 0 or 1, not " + engine::quote_token(fields[7]));
    ScalpelKeyframe sample;
    sample.time = v[0];
    sample.pose.base = Vec3(v[1], v[2], v[3]);
    sample.pose.tip = Vec3(v[4], v[5], v[6]);
    sample.pose.engaged = fields[7] == "1";
    return sample;
  }

  [[noreturn]] void fail(const std::string& reason) const {
    throw engine::InputError(path_ + (line_ ? ":" + std::to_string(line_) : std::string()) + ": " + reason);
  }

  std::string path_;
  std::size_t line_ = 0;  // the line being read; 0 for faults of the whole file
};

}  // namespace

void write_scalpel_trace(const std::string& path, std::span<const ScalpelSample> samples) {
  engine::write_stream_atomically(path, [&](std::ostream& out) {
    out << kScalpelTraceHeader << "\n";
    for (const ScalpelSample& s : samples) {
      put_real(out, s.time);
      for (const Vec3* p : {&s.pose.base, &s.pose.tip})
        for (int k = 0; k < 3; ++k) {
          out << ',';
          put_real(out, (*p)[k]);
        }
      out << ',' << (s.pose.engaged ? '1' : '0') << '\n';
    }
  });
}

ScalpelPath read_scalpel_trace(const std::string& path) {
  const std::string text = engine::read_file_bytes(path);
  return TraceParser(path).parse(text);
}

}  // namespace mtcut::sim
