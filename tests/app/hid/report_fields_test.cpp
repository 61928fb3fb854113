// Bit fields out of report bytes, and the report-level checks.

#include "app/hid/report_fields.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "app/hid/profile_file.h"

namespace mtcut::app::hid {
namespace {

TEST(HidReportFields, ExtractsLittleEndianBitFields) {
  const std::vector<std::uint8_t> b{0x01, 0xa2, 0xfe, 0x5e, 0x01, 0xf0, 0xff, 0x12, 0x34, 0x56, 0x78, 0x9a};
  EXPECT_EQ(extract_bits(b, 1, 0, 16, true), -350);
  EXPECT_EQ(extract_bits(b, 1, 0, 16, false), 0xfea2);
  EXPECT_EQ(extract_bits(b, 3, 0, 16, true), 350);
  EXPECT_EQ(extract_bits(b, 0, 0, 1, false), 1);
  EXPECT_EQ(extract_bits(b, 0, 1, 1, false), 0);
  // A 12-bit field starting at bit 4 of byte 5: 0xfff0 >> 4 = 0xfff, signed -1.
  EXPECT_EQ(extract_bits(b, 5, 4, 12, true), -1);
  EXPECT_EQ(extract_bits(b, 5, 4, 12, false), 0xfff);
  // 32 bits starting at bit 4 spans five bytes (the fifth's low nibble on top).
  EXPECT_EQ(extract_bits(b, 7, 4, 32, false), 0xa7856341);
  EXPECT_EQ(extract_bits(b, 7, 0, 32, false), 0x78563412);
  EXPECT_EQ(extract_bits(b, 7, 0, 8, true), 0x12);
  // A field past the end of the bytes is an error, not a read beyond them.
  EXPECT_THROW(extract_bits(b, 8, 4, 32, false), std::out_of_range);
  EXPECT_THROW(extract_bits(b, 12, 0, 1, false), std::out_of_range);
  EXPECT_THROW(extract_bits(b, 0, 8, 1, false), std::out_of_range);
  EXPECT_NO_THROW(extract_bits(b, 11, 7, 1, false));
}

TEST(HidReportFields, RejectsWithAReasonAndNoValues) {
  const Profile p = load_profile("spacemouse");
  ReportValues r = read_report(p, std::vector<std::uint8_t>{2, 0x5e, 0x01, 0, 0, 0xa2, 0xfe});
  EXPECT_EQ(r.reject, Reject::none);
  EXPECT_EQ(r.report, 1);
  EXPECT_EQ(r.values, (std::vector<std::int64_t>{350, 0, -350}));
  r = read_report(p, std::vector<std::uint8_t>{2, 0x5f, 0x01, 0, 0, 0xa2, 0xfe});
  EXPECT_EQ(r.reject, Reject::out_of_range);
  EXPECT_TRUE(r.values.empty());
  EXPECT_EQ(r.why, "report 2: field 'rx' = 351 outside [-350, 350]");
  r = read_report(p, std::vector<std::uint8_t>{3});
  EXPECT_EQ(r.reject, Reject::too_short);
  EXPECT_EQ(r.why, "report 3: 1 bytes, needs 2");
  r = read_report(p, std::vector<std::uint8_t>{0});
  EXPECT_EQ(r.reject, Reject::unknown_report);
  EXPECT_EQ(r.report, -1);
}

}  // namespace
}  // namespace mtcut::app::hid
