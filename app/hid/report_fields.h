#pragma once
// Raw report bytes -> the integer value of each field the profile defines for
// that report, or the reason the report is rejected. Nothing here guesses: a
// report that is too short, carries an id the profile does not know, or holds
// a value outside a field's logical range yields no values at all.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "app/hid/profile.h"

namespace mtcut::app::hid {

enum class Reject { none, too_short, unknown_report, out_of_range };

struct ReportValues {
  int report = -1;                   // index into Profile::reports (-1 when rejected as unknown)
  std::vector<std::int64_t> values;  // (report.fields.size()) in the report's field order; empty when rejected
  Reject reject = Reject::none;
  std::string why;                   // one line for a rejected report, naming the field or id
};

// The bit field of `bits` bits starting at bit `bit` of byte `byte`, little-endian,
// sign-extended when `is_signed`. Throws std::out_of_range when the field
// does not lie within `bytes` (read_report checks the report's size first,
// which its profile sized to hold every field) or is not 1-32 bits at bit 0-7.
std::int64_t extract_bits(std::span<const std::uint8_t> bytes, int byte, int bit, int bits, bool is_signed);

ReportValues read_report(const Profile& profile, std::span<const std::uint8_t> bytes);

}  // namespace mtcut::app::hid
