#include "app/hid/report_fields.h"

#include <stdexcept>
#include <string>

namespace mtcut::app::hid {

std::int64_t extract_bits(std::span<const std::uint8_t> bytes, int byte, int bit, int bits, bool is_signed) {
  std::uint64_t raw = 0;
  const int nbytes = (bit + bits + 7) / 8;  // at most 5 for 32 bits at bit 7
  if (byte < 0 || bit < 0 || bit > 7 || bits < 1 || bits > 32 ||
      static_cast<std::size_t>(byte + nbytes) > bytes.size())
    throw std::out_of_range("HID report field: " + std::to_string(bits) + " bits at bit " + std::to_string(bit) +
                            " of byte " + std::to_string(byte) + " in a " + std::to_string(bytes.size()) +
                            "-byte report");
  for (int k = nbytes - 1; k >= 0; --k) raw = (raw << 8) | bytes[static_cast<std::size_t>(byte + k)];
  raw = (raw >> bit) & ((std::uint64_t{1} << bits) - 1);
  if (is_signed && (raw >> (bits - 1)) & 1) return static_cast<std::int64_t>(raw) - (std::int64_t{1} << bits);
  return static_cast<std::int64_t>(raw);
}

ReportValues read_report(const Profile& profile, std::span<const std::uint8_t> bytes) {
  ReportValues out;
  if (bytes.empty()) {
    out.reject = Reject::too_short;
    out.why = "empty report";
    return out;
  }
  const int id = profile.reports.front().id == 0 ? 0 : bytes[0];
  for (std::size_t r = 0; r < profile.reports.size(); ++r)
    if (profile.reports[r].id == id) out.report = static_cast<int>(r);
  if (out.report < 0) {
    out.reject = Reject::unknown_report;
    out.why = "unknown report id " + std::to_string(id);
    return out;
  }
  const ReportDef& report = profile.reports[static_cast<std::size_t>(out.report)];
  if (bytes.size() < static_cast<std::size_t>(report.size)) {
    out.reject = Reject::too_short;
    out.why = "report " + std::to_string(id) + ": " + std::to_string(bytes.size()) + " bytes, needs " +
              std::to_string(report.size);
    return out;
  }
  out.values.reserve(report.fields.size());
  for (const int f : report.fields) {
    const FieldDef& field = profile.fields[static_cast<std::size_t>(f)];
    const std::int64_t v = extract_bits(bytes, field.byte, field.bit, field.bits, field.is_signed);
    if (v < field.logical_min || v > field.logical_max) {
      out.values.clear();
      out.reject = Reject::out_of_range;
      out.why = "report " + std::to_string(id) + ": field '" + field.name + "' = " + std::to_string(v) + " outside [" +
                std::to_string(field.logical_min) + ", " + std::to_string(field.logical_max) + "]";
      return out;
    }
    out.values.push_back(v);
  }
  return out;
}

}  // namespace mtcut::app::hid
