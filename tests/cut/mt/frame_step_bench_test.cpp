#include "cut/mt/frame_step_bench.h"

#include <gtest/gtest.h>

#include "cut/mt/mt_pieces.h"
#include "tests/cut/mt/mt_cut_test_util.h"

namespace mtcut::test {
namespace {

// The shape of the experiment the bench runs (its default stroke, not its
// timings), on the MT it runs on (the paper preset) and on the real liver:
// every step is a small cut (a tenth of the MT at most), most steps cut
// something, and the MT the dashed stroke leaves is valid, grown, and in one
// piece. (Not on the 1,500-tet builtin ellipsoid: its tets are many times
// wider than a frame's quad, and most of its steps cut nothing.)
TEST(FrameStepBench, DashedStrokeMakesSmallCutsAndLeavesAValidMt) {
  for (const std::string name : {"paper", "liver"}) {
    const Mt& mt = cut_test_mt(name);
    cut::FrameStepDef def;
    def.runs = 1;
    Mt after;
    const cut::FrameStepResult r = cut::run_frame_steps(mt, def, &after);
    EXPECT_EQ(r.steps, static_cast<std::size_t>(def.steps)) << name;
    EXPECT_GT(r.split_tets_median, 0u) << name;
    EXPECT_LT(r.split_tets_max, mt.num_live_tets() / 10) << name;
    EXPECT_GT(r.new_tets_median, r.split_tets_median) << name;
    const auto report = after.validate();
    EXPECT_TRUE(report.ok()) << name << ": " << report.summary();
    EXPECT_EQ(cut::find_pieces(after).count, 1u) << name;
    EXPECT_GT(after.num_live_tets(), mt.num_live_tets()) << name;
  }
}

TEST(FrameStepBench, RejectsStepsThatTouch) {
  cut::FrameStepDef def;
  def.stride = def.sweep_width;
  EXPECT_THROW(cut::run_frame_steps(cut_test_mt("ellipsoid"), def), std::invalid_argument);
}

}  // namespace
}  // namespace mtcut::test
