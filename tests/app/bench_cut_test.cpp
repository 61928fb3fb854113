// End-to-end tests of `mtcut bench cut`: it runs, reports every key, and its
// figures relate sanely. No time bounds.

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "tests/app/run_mtcut.h"

namespace mtcut::test {
namespace {

TEST(BenchCut, ReportsBothSchemesOnTheSameCuts) {
  const CommandResult r = run_mtcut("bench cut --runs 1 --tets 3000 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  for (const char* scheme : {"lut", "bielser17"}) {
    ASSERT_TRUE(out.contains(scheme)) << scheme;
    for (const char* key : {"split_tets", "new_tets", "new_tets_per_split_tet", "ns_per_split_tet"})
      EXPECT_TRUE(out[scheme].contains(key)) << scheme << " " << key;
    EXPECT_GT(out[scheme]["split_tets"].get<int>(), 0);
    EXPECT_GT(out[scheme]["ns_per_split_tet"].get<double>(), 0.0);
  }
  EXPECT_EQ(out["lut"]["split_tets"], out["bielser17"]["split_tets"]);
  EXPECT_GT(out["bielser17"]["new_tets"].get<int>(), out["lut"]["new_tets"].get<int>());
  EXPECT_GT(out["lut"]["new_tets"].get<int>(), out["lut"]["split_tets"].get<int>());
  EXPECT_DOUBLE_EQ(out["ratio_new_tets_bielser17_over_lut"].get<double>(),
                   out["bielser17"]["new_tets"].get<double>() / out["lut"]["new_tets"].get<double>());
  // Both meshes, complete and partial cuts; complete ones separate, partial ones do not.
  ASSERT_EQ(out["meshes"].size(), 2u);
  int complete = 0, partial = 0;
  for (const auto& cut : out["cuts"]) {
    const bool is_complete = cut["complete"].get<bool>();
    (is_complete ? complete : partial)++;
    EXPECT_GT(cut["lut"]["split_tets"].get<int>(), 0) << cut.dump();
    EXPECT_EQ(cut["lut"]["pieces"].get<int>(), is_complete ? 2 : 1) << cut.dump();
    EXPECT_EQ(cut["bielser17"]["pieces"], cut["lut"]["pieces"]) << cut.dump();
  }
  EXPECT_GT(complete, 0);
  EXPECT_GT(partial, 0);
}

TEST(BenchCut, MissingMeshGivesOneLine) {
  const CommandResult r = run_mtcut("bench cut --runs 1 --mesh /nonexistent/liver.obj");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace mtcut::test
