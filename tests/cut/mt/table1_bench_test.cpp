#include "cut/mt/table1_bench.h"

#include <gtest/gtest.h>

#include "tests/cut/mt/mt_cut_test_util.h"

namespace mtcut::test {
namespace {

// The shape of the experiment (not its timings): growing cuts in the
// paper's order, the last one separating the object into two pieces, the
// LUT making fewer tets than the 1:17 reference.
TEST(Table1Bench, RowsHaveThePapersShape) {
  cut::Table1Def def;
  def.runs = 1;
  const auto result = cut::run_table1(cut_test_mt("ellipsoid"), def);
  ASSERT_EQ(result.rows.size(), 5u);
  EXPECT_LT(result.rows[1].split_tets, result.rows[2].split_tets);
  EXPECT_LT(result.rows[2].split_tets, result.rows[0].split_tets);
  EXPECT_LT(result.rows[0].split_tets, result.rows[3].split_tets);
  EXPECT_LT(result.rows[3].split_tets, result.rows[4].split_tets);
  for (const auto& row : result.rows) {
    EXPECT_GT(row.split_tets, 0u);
    EXPECT_LT(row.new_tets_lut, row.new_tets_bielser17);
  }
  EXPECT_EQ(result.rows[4].pieces, 2u);
  EXPECT_EQ(result.rows[0].pieces, 1u);
}

}  // namespace
}  // namespace mtcut::test
