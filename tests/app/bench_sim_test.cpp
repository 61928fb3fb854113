// End-to-end tests of `mtcut bench sim`: it runs, reports every key, and each
// implicit run replays the same frames whatever --runs is. No time bounds.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/app/run_mtcut.h"

namespace mtcut::test {
namespace {

nlohmann::json bench_sim(int runs) {
  const CommandResult r = run_mtcut("bench sim --tets 3000 --json --runs " + std::to_string(runs));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(BenchSim, ReportsEveryIntegratorAndTheReference) {
  const nlohmann::json out = bench_sim(1);
  for (const char* key : {"reference_loop", "symplectic_euler", "implicit_euler", "implicit_euler_loose"}) {
    ASSERT_TRUE(out.contains(key)) << key;
    for (const char* rate : {"steps_per_s", "ns_per_spring", "spring_steps_per_s"})
      EXPECT_GT(out[key][rate].get<double>(), 0.0) << key << " " << rate;
  }
  EXPECT_GT(out["mesh"]["springs"].get<int>(), out["mesh"]["vertices"].get<int>());
  EXPECT_GT(out["model_build_ms"].get<double>(), 0.0);
  EXPECT_GT(out["model_update"]["model_update_ms"].get<double>(), 0.0);
  EXPECT_GT(out["model_update"]["removed_tets"].get<int>(), 0);
  EXPECT_EQ(out["model_update"]["added_tets"].get<int>(), 4 * out["model_update"]["removed_tets"].get<int>());
  EXPECT_GT(out["symplectic_euler"]["vs_reference"].get<double>(), 0.0);
  for (const char* key : {"implicit_euler", "implicit_euler_loose"}) {
    const auto& implicit = out[key];
    EXPECT_EQ(implicit["frames_per_run"].get<int>(), 180) << key;
    EXPECT_GT(implicit["ms_per_frame_60hz"].get<double>(), 0.0) << key;
    EXPECT_GT(implicit["first_frame_ms"].get<double>(), 0.0) << key;
    EXPECT_GT(implicit["mean_cg_iterations"].get<double>(), 0.0) << key;
  }
  // The default tolerance's frame, in parts (minima at a fixed state).
  const auto& parts = out["implicit_euler"]["frame_parts"];
  for (const char* part : {"assemble_ms", "cg_start_ms", "cg_iteration_ms"})
    EXPECT_GT(parts[part].get<double>(), 0.0) << part;
  EXPECT_EQ(parts["repeats"].get<int>(), 10);
  EXPECT_FALSE(out["implicit_euler_loose"].contains("frame_parts"));
  // The looser tolerance takes fewer iterations on the same frames.
  EXPECT_LT(out["implicit_euler_loose"]["mean_cg_iterations"].get<double>(),
            out["implicit_euler"]["mean_cg_iterations"].get<double>());
  EXPECT_EQ(out["refused_steps"].get<int>(), 0);
}

// Every implicit run starts from rest with a fresh stepper: more runs time
// the same frames (a continuing trajectory would settle and need fewer
// CG iterations per frame the more runs there were).
TEST(BenchSim, MoreRunsReplayTheSameFrames) {
  const nlohmann::json one = bench_sim(1), three = bench_sim(3);
  for (const char* key : {"implicit_euler", "implicit_euler_loose"})
    EXPECT_EQ(one[key]["mean_cg_iterations"].get<double>(), three[key]["mean_cg_iterations"].get<double>()) << key;
}

}  // namespace
}  // namespace mtcut::test
