// End-to-end tests of `mtcut bench stroke`: it runs, reports every stroke
// and step count, and straight strokes cut progressively make exactly the
// tets of their one-polygon cut. No time bounds.

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "tests/app/run_mtcut.h"

namespace mtcut::test {
namespace {

TEST(BenchStroke, ProgressiveStrokesAgainstTheirOnePolygonCut) {
  const CommandResult r = run_mtcut("bench stroke --runs 1 --tets 1500 --steps 60 --mesh builtin:box --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  ASSERT_EQ(out["organs"].size(), 2u);
  for (const auto& organ : out["organs"]) {
    ASSERT_EQ(organ["strokes"].size(), 4u) << organ["mesh"];
    for (const auto& stroke : organ["strokes"]) {
      const std::string name = stroke["stroke"].get<std::string>();
      const int one = stroke["one_polygon"]["new_tets"].get<int>();
      EXPECT_GT(one, 0) << name;
      ASSERT_EQ(stroke["progressive"].size(), 1u) << name;
      for (const auto& p : stroke["progressive"]) {
        EXPECT_GT(p["steps_cut"].get<int>(), 0) << name;
        const double p50 = p["step_ms_p50"].get<double>(), p90 = p["step_ms_p90"].get<double>();
        const double p99 = p["step_ms_p99"].get<double>(), most = p["step_ms_max"].get<double>();
        const double mean = p["step_ms_mean"].get<double>();
        EXPECT_TRUE(0 < p50 && p50 <= p90 && p90 <= p99 && p99 <= most) << name << " " << p.dump();
        EXPECT_TRUE(0 < mean && mean <= most) << name << " " << p.dump();
        // The MT's storage: retracted cuts leave slots behind during the
        // stroke (more than the one-polygon cut's), reclaimed once it ends:
        // then at most as many dead tets as live ones, or kReclaimMin.
        EXPECT_GT(p["mt_tet_slots_peak"].get<int>(), stroke["one_polygon"]["mt_tet_slots_peak"].get<int>()) << name;
        EXPECT_GE(p["mt_vertices_peak"].get<int>(), p["mt_vertices"].get<int>()) << name;
        const int live = organ["mt_live_tets"].get<int>() + p["new_tets"].get<int>();
        EXPECT_LE(p["mt_tet_slots"].get<int>(), std::max(2 * live, live + 4096)) << name;
        EXPECT_DOUBLE_EQ(p["tets_ratio_vs_one_polygon"].get<double>(), p["new_tets"].get<double>() / one) << name;
        // The bound on element growth, at 60 steps (at 6 or 12, turning strokes exceed it).
        EXPECT_LE(p["tets_ratio_vs_one_polygon"].get<double>(), 1.3) << name << " " << p.dump();
        if (name == "straight" || name == "tip_inside") {
          EXPECT_EQ(p["new_tets"].get<int>(), one) << name;  // one part: each tet split once
          EXPECT_EQ(p["pieces"], stroke["one_polygon"]["pieces"]) << name;
        }
      }
      if (name == "straight") {
        EXPECT_EQ(stroke["one_polygon"]["pieces"].get<int>(), 2) << organ["mesh"];
      }
    }
  }
}

TEST(BenchStroke, MissingMeshGivesOneLine) {
  const CommandResult r = run_mtcut("bench stroke --runs 1 --steps 6 --mesh /nonexistent/liver.obj");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace mtcut::test
