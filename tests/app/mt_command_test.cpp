// End-to-end tests of `mtcut mt`.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <vector>

#include "tests/app/run_mtcut.h"
#include "tests/test_paths.h"

namespace mtcut::test {
namespace {

TEST(MtCommand, BuildsAValidMtOfARealMesh) {
  const CommandResult r = run_mtcut("mt " + quoted(shared_mesh("liver.msh")) + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_TRUE(report["valid"].get<bool>());
  EXPECT_EQ(report["finest_tets"].get<int>(), 596);
  EXPECT_LT(report["coarsest_tets"].get<int>(), 596);
  EXPECT_GT(report["fragments"].get<int>(), 2);
  EXPECT_GE(report["dag_depth"].get<int>(), 2);
}

TEST(MtCommand, BuiltinWithOptions) {
  const CommandResult r = run_mtcut("mt builtin:box --tets 2000 --target-coarsest 300 --no-preserve-boundary --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_TRUE(report["valid"].get<bool>());
  EXPECT_FALSE(report["preserve_boundary"].get<bool>());
  EXPECT_LE(report["coarsest_tets"].get<int>(), 330);
}

// With the boundary free, the surface moves within the bound asked for,
// which the report measures; a bound that is no positive fraction is a usage error.
TEST(MtCommand, AFreeBoundaryStaysWithinItsBound) {
  const CommandResult r =
      run_mtcut("mt builtin:ellipsoid --tets 3000 --no-preserve-boundary --max-surface-deviation 0.004 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_TRUE(report["valid"].get<bool>());
  EXPECT_DOUBLE_EQ(report["max_surface_deviation"].get<double>(), 0.004);
  EXPECT_GT(report["coarsest_surface_deviation"].get<double>(), 0.0);
  EXPECT_LE(report["coarsest_surface_deviation"].get<double>(), 0.004);
  const CommandResult kept = run_mtcut("mt builtin:ellipsoid --tets 3000 --json");
  ASSERT_EQ(kept.exit_code, 0) << kept.err;
  EXPECT_FALSE(nlohmann::json::parse(kept.out).contains("coarsest_surface_deviation"));
  for (const std::string bound : {"0", "-0.01"}) {
    const CommandResult bad = run_mtcut("mt builtin:ellipsoid --tets 3000 --no-preserve-boundary --max-surface-deviation " + bound);
    EXPECT_EQ(bad.exit_code, 2) << bound;  // a usage error, as every option's
    EXPECT_NE(bad.err.find("--max-surface-deviation"), std::string::npos) << bad.err;
  }
}

TEST(MtCommand, BadInputGivesOneLine) {
  for (const std::string& args : std::vector<std::string>{"mt --preset moon", "mt",
                                                          "mt " + quoted(shared_mesh("liver_for_test_broken.vtk"))}) {
    const CommandResult r = run_mtcut(args);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace mtcut::test
