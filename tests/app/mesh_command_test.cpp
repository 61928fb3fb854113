// End-to-end tests of `mtcut mesh`: real inputs, every kind of bad input,
// and the promise that a failed run leaves no output file behind.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/app/run_mtcut.h"
#include "tests/temp_dir.h"
#include "tests/test_paths.h"

namespace mtcut::test {
namespace {
namespace fs = std::filesystem;

class MeshCommand : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return dir_.file(name); }
  std::string write(const std::string& name, const std::string& text) const { return dir_.write(name, text); }
  // Expects a one-line error naming `what` and exit code 1, and no output file.
  void expect_rejected(const std::string& input, const std::string& what, const std::string& options = "") const {
    const std::string out = path("out.vtu");
    const CommandResult r = run_mtcut("mesh " + quoted(input) + " -o " + quoted(out) + options);
    EXPECT_EQ(r.exit_code, 1) << input << "\n" << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(out)) << input;
    for (const auto& entry : fs::directory_iterator(dir_.path()))
      EXPECT_EQ(entry.path().filename().string().rfind(".tmp-", 0), std::string::npos) << "left " << entry.path();
  }
  TempDir dir_;
};

TEST_F(MeshCommand, Liver2JsonHasTheStatistics) {
  const CommandResult r = run_mtcut("mesh " + quoted(shared_mesh("liver2.obj")) + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  for (const char* key : {"vertices", "tets", "boundary_faces", "volume", "min_dihedral_deg", "seconds"})
    EXPECT_TRUE(report.contains(key)) << key;
  EXPECT_GT(report["tets"].get<int>(), 5000);
  EXPECT_GT(report["volume"].get<double>(), 0);
  EXPECT_EQ(r.err, "");
}

// --units and --scale read a file's coordinates in that unit; a size that
// looks like millimetres read as metres gets one line saying so.
TEST_F(MeshCommand, UnitsScaleAFileToMetres) {
  const std::string box = path("box_mm.obj");
  ASSERT_EQ(run_mtcut("mesh builtin:box --tets 500 --size 100,200,50 -o " + quoted(box)).exit_code, 0);
  for (const std::string option : {"--units mm", "--scale 0.001"}) {
    const CommandResult r = run_mtcut("mesh " + quoted(box) + " " + option + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NEAR(nlohmann::json::parse(r.out)["volume"].get<double>(), 1e-3, 1e-12) << option;
    EXPECT_EQ(r.err, "") << option;
  }
  const CommandResult unsaid = run_mtcut("mesh " + quoted(box) + " --json");
  ASSERT_EQ(unsaid.exit_code, 0) << unsaid.err;
  EXPECT_NEAR(nlohmann::json::parse(unsaid.out)["volume"].get<double>(), 1e6, 1e-3);
  EXPECT_NE(unsaid.err.find("--units mm"), std::string::npos) << unsaid.err;
  EXPECT_EQ(std::count(unsaid.err.begin(), unsaid.err.end(), '\n'), 1) << unsaid.err;

  const CommandResult unknown = run_mtcut("mesh " + quoted(box) + " --units furlong");
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_NE(unknown.err.find("unknown unit"), std::string::npos) << unknown.err;
  EXPECT_EQ(std::count(unknown.err.begin(), unknown.err.end(), '\n'), 1) << unknown.err;
  EXPECT_EQ(run_mtcut("mesh " + quoted(box) + " --units mm --scale 0.001").exit_code, 2);
}

TEST_F(MeshCommand, WritesEveryOutputFormat) {
  for (const std::string name : {"box.vtu", "box.node", "box.obj", "box.stl"}) {
    const CommandResult r = run_mtcut("mesh builtin:box --tets 500 --size 1,2,3 -o " + quoted(path(name)));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(path(name))) << name;
  }
  EXPECT_TRUE(fs::exists(path("box.ele")));
  // The written tet meshes read back to the same volume.
  for (const std::string name : {"box.vtu", "box.node"}) {
    const CommandResult r = run_mtcut("mesh " + quoted(path(name)) + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NEAR(nlohmann::json::parse(r.out)["volume"].get<double>(), 6.0, 1e-9) << name;
  }
}

TEST_F(MeshCommand, HelpIsUsefulToANewcomer) {
  const CommandResult top = run_mtcut("--help");
  EXPECT_EQ(top.exit_code, 0);
  EXPECT_NE(top.out.find("mesh"), std::string::npos);
  const CommandResult sub = run_mtcut("mesh --help");
  EXPECT_EQ(sub.exit_code, 0);
  EXPECT_NE(sub.out.find("builtin:ellipsoid"), std::string::npos);
  EXPECT_NE(sub.out.find("--max-volume"), std::string::npos);
}

TEST_F(MeshCommand, BrokenSharedMeshesAreRejected) {
  expect_rejected(shared_mesh("Armadillo_Tetra_4406_for_test_broken.vtu"), "Armadillo_Tetra_4406_for_test_broken.vtu");
  expect_rejected(shared_mesh("liver_for_test_broken.vtk"), "liver_for_test_broken.vtk");
}

TEST_F(MeshCommand, BadFilesAreRejected) {
  expect_rejected(path("missing.obj"), "no such file");
  expect_rejected(write("empty.off", ""), "empty");
  // A pyramid with one side missing: refused when strict (repaired otherwise, below).
  expect_rejected(write("hole.obj",
                        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                        "f 1 3 2\nf 1 4 3\nf 1 2 5\nf 2 3 5\nf 3 4 5\n"),
                  "hole.obj: the surface is not closed", " --strict");
  expect_rejected(write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n"),
                  "non-finite");
  expect_rejected(write("cut.node", "4 3 0 0\n0 0 0 0\n1 1 0 0\n"), "cut.node");
  expect_rejected(write("organ.xyz", "1 2 3\n"), "unknown mesh format");
  expect_rejected("builtin:spleen", "unknown built-in shape");
}

// Without --strict a surface with a hole is repaired, and one line says how.
TEST_F(MeshCommand, ASurfaceWithAHoleIsRepairedAndSaysSo) {
  const std::string hole = write("hole.obj",
                                 "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                                 "f 1 3 2\nf 1 4 3\nf 1 2 5\nf 2 3 5\nf 3 4 5\n");
  const CommandResult r = run_mtcut("mesh " + quoted(hole) + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["volume"].get<double>(), 1.0 / 3.0, 1e-12);
  EXPECT_NE(r.err.find("hole.obj: repaired (holes closed): 5 faces in, 6 out, 1 holes closed"), std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(MeshCommand, FailedRunKeepsAnExistingOutput) {
  const std::string out = write("keep.obj", "precious");
  const CommandResult r = run_mtcut("mesh " + quoted(path("missing.obj")) + " -o " + quoted(out));
  EXPECT_EQ(r.exit_code, 1);
  std::ifstream in(out);
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "precious");
}

TEST_F(MeshCommand, BadOptionsAreRejected) {
  EXPECT_NE(run_mtcut("mesh builtin:box --tets -5").exit_code, 0);
  EXPECT_NE(run_mtcut("mesh builtin:box --size 1,2").exit_code, 0);
  EXPECT_NE(run_mtcut("mesh").exit_code, 0);
}

}  // namespace
}  // namespace mtcut::test
