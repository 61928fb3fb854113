// The scalpel trace format: exact round trip, and one clear line per malformed row.

#include "sim/scalpel_trace.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <random>

#include "engine/input_error.h"
#include "tests/temp_dir.h"

namespace mtcut::sim {
namespace {

class ScalpelTrace : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return dir_.file(name); }
  std::string write(const std::string& text) const { return dir_.write("t.csv", text); }
  // The message of reading `text`, which must fail.
  std::string error_of(const std::string& text) const {
    try {
      read_scalpel_trace(write(text));
    } catch (const engine::InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "accepted:\n" << text;
    return "";
  }
  mtcut::test::TempDir dir_;
};

const std::string kHeader = std::string(kScalpelTraceHeader) + "\n";

TEST_F(ScalpelTrace, RoundTripIsBitExact) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-0.2, 0.2);
  std::vector<ScalpelSample> samples;
  double time = 0;
  for (int i = 0; i < 200; ++i) {
    time += 1.0 / 60.0;  // accumulated, as the frame loop does: not short decimals
    samples.push_back({time, {Vec3(coord(rng), coord(rng), coord(rng)), Vec3(coord(rng), 1e-300, -0.0), i % 3 == 0}});
  }
  samples.push_back({1e6, {Vec3(5e-324, 1.7976931348623157e308, 0.1), Vec3(1, 2, 3), false}});
  write_scalpel_trace(path("rt.csv"), samples);
  const ScalpelPath read = read_scalpel_trace(path("rt.csv"));
  ASSERT_EQ(read.keyframes().size(), samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const ScalpelKeyframe& a = samples[i];
    const ScalpelKeyframe& b = read.keyframes()[i];
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a.time), std::bit_cast<std::uint64_t>(b.time)) << i;
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a.pose.base[k]), std::bit_cast<std::uint64_t>(b.pose.base[k])) << i;
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a.pose.tip[k]), std::bit_cast<std::uint64_t>(b.pose.tip[k])) << i;
    }
    EXPECT_EQ(a.pose.engaged, b.pose.engaged) << i;
  }
}

TEST_F(ScalpelTrace, WritesTheDocumentedFormat) {
  const std::vector<ScalpelSample> samples = {{0.0, {Vec3(0.04, -0.06, 0.06), Vec3(0.04, -0.06, -0.045), true}},
                                              {0.5, {Vec3(0, 0, 1), Vec3(0, 0, 0), false}}};
  write_scalpel_trace(path("f.csv"), samples);
  std::ifstream in(path("f.csv"));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_EQ(text, kHeader + "0,0.04,-0.06,0.06,0.04,-0.06,-0.045,1\n0.5,0,0,1,0,0,0,0\n");
}

TEST_F(ScalpelTrace, ReadsCrLfAndAFinalLineWithoutEnd) {
  const ScalpelPath p =
      read_scalpel_trace(write(std::string(kScalpelTraceHeader) + "\r\n0,1,2,3,4,5,6,1\r\n1,1,2,3,4,5,7,0"));
  ASSERT_EQ(p.keyframes().size(), 2u);
  EXPECT_EQ(p.keyframes()[1].pose.tip.z(), 7.0);
  EXPECT_TRUE(p.keyframes()[0].pose.engaged);
  EXPECT_FALSE(p.keyframes()[1].pose.engaged);
}

TEST_F(ScalpelTrace, MalformedRowsFailWithFileAndLine) {
  const std::string file = path("t.csv");
  EXPECT_EQ(error_of(kHeader + "0,1,2,3,4,5,6,1\n1,1,2,3,4,5,6\n"),
            file + ":3: expected 8 comma-separated fields, found 7");
  EXPECT_EQ(error_of(kHeader + "0,1,2,3,4,5,6,1,9\n"), file + ":2: expected 8 comma-separated fields, found 9");
  EXPECT_EQ(error_of(kHeader + "0,1,2,x,4,5,6,1\n"), file + ":2: base_z must be a finite number, not 'x'");
  EXPECT_EQ(error_of(kHeader + "0,1,2,3,4,5,nan,1\n"), file + ":2: tip_z must be a finite number, not 'nan'");
  EXPECT_EQ(error_of(kHeader + "0,1,2,3,4,5,,1\n"), file + ":2: tip_z must be a finite number, not ''");
  EXPECT_EQ(error_of(kHeader + "0,1,2,3,4,5,6,yes\n"), file + ":2: engaged must be 0 or 1, not 'yes'");
  EXPECT_EQ(error_of(kHeader + "0,1,2,3,4,5,6,1\n0,1,2,3,4,5,6,1\n"),
            file + ":3: time 0 is not after the previous sample's");
  EXPECT_EQ(error_of("time,x\n0,1,2,3,4,5,6,1\n").rfind(file + ":1: the header must be", 0), 0u);
  EXPECT_EQ(error_of(kHeader), file + ": the trace has no samples");
  EXPECT_EQ(error_of(""), file + ": the file is empty");
  EXPECT_THROW(read_scalpel_trace(path("missing.csv")), engine::InputError);
}

TEST_F(ScalpelTrace, ReplayedSamplesArePosesAtTheirTimes) {
  std::vector<ScalpelSample> samples;
  double time = 0;
  for (int i = 0; i < 10; ++i, time += 1.0 / 60.0)
    samples.push_back({time, {Vec3(0.1 * i, -0.2 * i, 0.3), Vec3(0.01 * i, 0.5, -0.7 * i), i < 5}});
  write_scalpel_trace(path("p.csv"), samples);
  const ScalpelPath path_read = read_scalpel_trace(path("p.csv"));
  for (const ScalpelSample& s : samples) {
    const ScalpelPose pose = path_read.pose_at(s.time);
    EXPECT_EQ(pose.base, s.pose.base);
    EXPECT_EQ(pose.tip, s.pose.tip);
    EXPECT_EQ(pose.engaged, s.pose.engaged);
  }
}

}  // namespace
}  // namespace mtcut::sim
