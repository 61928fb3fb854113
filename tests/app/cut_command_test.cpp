// End-to-end tests of `mtcut cut`.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/app/run_mtcut.h"
#include "tests/test_paths.h"

namespace mtcut::test {
namespace {

// The builtin box is 0.16 x 0.10 x 0.07 m around the origin; small enough to mesh fast.
const std::string kBox = "cut builtin:box --tets 2000 ";
// A slightly tilted plane near x = 0, far larger than the box: a complete cut.
const std::string kComplete = "0.001,-1,-1;0.003,1,-1;0.003,1,1;0.001,-1,1";
// The plane y ~ 0 reaching from x = -1 to x = 0.02 only: a partial cut (a slit
// from the box's -x end past its middle).
const std::string kPartial = "-1,0.001,-1;0.02,0.003,-1;0.02,0.003,1;-1,0.001,1";

nlohmann::json cut_json(const std::string& polygon, const std::string& extra = "") {
  const CommandResult r = run_mtcut(kBox + "--polygon " + quoted(polygon) + " --json " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

TEST(CutCommand, CompleteCutMakesTwoPieces) {
  const auto out = cut_json(kComplete);
  ASSERT_FALSE(out.empty());
  for (const char* key : {"split_tets", "new_tets", "new_tets_per_split_tet", "cases", "pieces", "min_dihedral_deg",
                          "seconds", "tets", "tets_before"})
    EXPECT_TRUE(out.contains(key)) << key;
  for (const char* c : {"A", "B", "C", "D", "E", "O", "vertex"}) EXPECT_TRUE(out["cases"].contains(c)) << c;
  const auto split = out["split_tets"].get<std::size_t>(), made = out["new_tets"].get<std::size_t>();
  EXPECT_GT(split, 0u);
  EXPECT_GT(made, split);
  EXPECT_DOUBLE_EQ(out["new_tets_per_split_tet"].get<double>(), static_cast<double>(made) / split);
  std::size_t by_case = 0;
  for (const auto& [name, count] : out["cases"].items()) by_case += count.get<std::size_t>();
  EXPECT_EQ(by_case, split);
  EXPECT_EQ(out["tets"].get<std::size_t>(), out["tets_before"].get<std::size_t>() - split + made);
  EXPECT_EQ(out["pieces"].get<int>(), 2);
  EXPECT_GT(out["min_dihedral_deg"].get<double>(), 0.0);
}

TEST(CutCommand, PartialCutKeepsOnePiece) {
  const auto out = cut_json(kPartial);
  ASSERT_FALSE(out.empty());
  EXPECT_GT(out["split_tets"].get<int>(), 0);
  EXPECT_EQ(out["pieces"].get<int>(), 1);
}

TEST(CutCommand, Bielser17MakesMoreTetsThanLutOnTheSameCut) {
  for (const std::string& polygon : {kComplete, kPartial}) {
    const auto lut = cut_json(polygon, "--scheme lut");
    const auto b17 = cut_json(polygon, "--scheme bielser17");
    ASSERT_FALSE(lut.empty() || b17.empty());
    EXPECT_EQ(lut["scheme"], "lut");
    EXPECT_EQ(b17["scheme"], "bielser17");
    EXPECT_EQ(b17["split_tets"], lut["split_tets"]) << polygon;
    EXPECT_EQ(b17["pieces"], lut["pieces"]) << polygon;
    EXPECT_GT(b17["new_tets"].get<int>(), lut["new_tets"].get<int>()) << polygon;
  }
}

TEST(CutCommand, WritesTheCutMesh) {
  const auto path = std::filesystem::temp_directory_path() / ("mtcut-cut-" + std::to_string(::getpid()) + ".vtu");
  const auto out = cut_json(kComplete, "-o " + quoted(path.string()));
  ASSERT_FALSE(out.empty());
  ASSERT_TRUE(std::filesystem::exists(path));
  const CommandResult back = run_mtcut("mesh " + quoted(path.string()) + " --json");
  std::filesystem::remove(path);
  ASSERT_EQ(back.exit_code, 0) << back.err;
  EXPECT_EQ(nlohmann::json::parse(back.out)["tets"], out["tets"]);
}

TEST(CutCommand, BadPolygonGivesOneLine) {
  const std::vector<std::string> bad = {
      "0,0,0;1,0,0",                      // fewer than 3 corners
      "0,0,0;1,1,1;2,2,2",                // collinear
      "0,0,0;1,0,0;1,1,0;0,1,0.5",        // not planar
      "nan,0,0;1,0,0;0,1,0",              // NaN
      "0,0,0;1,zero,0;0,1,0",             // unparsable
      "0,0,0;1,0;0,1,0",                  // a corner with two coordinates
  };
  for (const std::string& polygon : bad) {
    const CommandResult r = run_mtcut(kBox + "--polygon " + quoted(polygon));
    EXPECT_EQ(r.exit_code, 1) << polygon << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << polygon << "\n" << r.err;
    EXPECT_NE(r.err.find("--polygon"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

TEST(CutCommand, BadSchemeOrMeshGivesOneLine) {
  for (const std::string& args :
       {kBox + "--polygon " + quoted(kComplete) + " --scheme 1:4",
        "cut " + quoted(shared_mesh("liver_for_test_broken.vtk")) + " --polygon " + quoted(kComplete)}) {
    const CommandResult r = run_mtcut(args);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace mtcut::test
