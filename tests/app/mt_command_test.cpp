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
