// TetGen .node/.ele: reading hand-made pairs, writing and reading back, and
// every kind of broken pair.

#include <gtest/gtest.h>

#include "engine/io/mesh_file.h"
#include "engine/io/mesh_readers.h"
#include "tests/engine/io/io_test_util.h"
#include "tests/test_paths.h"

namespace mtcut::engine {
namespace {

using test::expect_read_error;
using test::replace_once;
using test::TempDir;

// The Kuhn cube, numbered from 1, with comments, one attribute and markers.
const char* kCubeNode =
    "# a unit cube\n"
    "8 3 1 1  # points, dimension, attributes, markers\n"
    "1 0 0 0 0.5 1\n"
    "2 1 0 0 0.5 1\n"
    "3 0 1 0 0.5 1\n"
    "\n"
    "4 1 1 0 0.5 1\n"
    "5 0 0 1 0.5 1\n"
    "6 1 0 1 0.5 1\n"
    "7 0 1 1 0.5 1\n"
    "8 1.0e0 +1 1 0.5 1   # last point\n";

const char* kCubeEle =
    "6 4 1\n"
    "1 1 2 4 8 7\n"
    "2 1 4 3 8 7\n"
    "3 1 3 7 8 7\n"
    "4 1 7 5 8 7\n"
    "5 1 5 6 8 7\n"
    "6 1 6 2 8 7\n";

// Writes the pair under base (with the given texts) and returns the .node path.
std::string write_pair(const TempDir& dir, const std::string& base, const std::string& node, const std::string& ele) {
  dir.write(base + ".ele", ele);
  return dir.write(base + ".node", node);
}

TEST(TetGenFiles, ReadsOneBasedPairWithCommentsAttributesAndMarkers) {
  TempDir dir;
  const std::string node = write_pair(dir, "cube", kCubeNode, kCubeEle);
  const RawMesh raw = read_volume_file(node);
  ASSERT_EQ(raw.positions.size(), 8u);
  ASSERT_EQ(raw.tets.size(), 6u);
  EXPECT_TRUE(raw.triangles.empty());
  EXPECT_EQ(raw.positions[7], Vec3(1, 1, 1));
  EXPECT_EQ(raw.tets[0], (std::array<std::int64_t, 4>{0, 1, 3, 7}));
  EXPECT_EQ(raw.tets, test::raw_tets(test::kuhn_cube()));
  const TetMesh mesh = test::expect_valid_tets(raw, node);
  EXPECT_NEAR(mesh.total_volume(), 1.0, 1e-15);
}

TEST(TetGenFiles, ElePathAndBaseNameNameTheSamePair) {
  TempDir dir;
  write_pair(dir, "cube", kCubeNode, kCubeEle);
  EXPECT_EQ(read_volume_file(dir.file("cube.ele")).tets.size(), 6u);
  EXPECT_EQ(tetgen_pair(dir.file("cube")).first, dir.file("cube.node"));
  EXPECT_EQ(tetgen_pair(dir.file("cube.ELE")).second, dir.file("cube.ele"));
}

TEST(TetGenFiles, ReadsZeroBasedTenNodeTets) {
  TempDir dir;
  std::string node = "5 3\n";
  for (int i = 0; i < 5; ++i) node += std::to_string(i) + " " + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string(i == 4 ? 1 : 0) + "\n";
  // One 10-node tet: 4 corners then 6 edge nodes (ids only checked for range).
  const std::string path = write_pair(dir, "quad", node, "1 10 0\n0 0 1 2 4 0 1 2 3 4 4\n");
  const RawMesh raw = read_volume_file(path);
  ASSERT_EQ(raw.tets.size(), 1u);
  EXPECT_EQ(raw.tets[0], (std::array<std::int64_t, 4>{0, 1, 2, 4}));
}

TEST(TetGenFiles, WriteThenReadGivesTheSameMesh) {
  TempDir dir;
  const TetMesh cube = test::kuhn_cube();
  write_tetgen(cube, dir.file("out"));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.ele", "out.node"}));
  const RawMesh back = read_volume_file(dir.file("out.node"));
  EXPECT_EQ(back.positions, cube.positions);
  EXPECT_EQ(back.tets, test::raw_tets(cube));
}

TEST(TetGenFiles, RealMeshRoundTripsExactly) {
  TempDir dir;
  const RawMesh raw = read_volume_file(mtcut::test::shared_mesh("liver.msh"));
  const TetMesh mesh = test::expect_valid_tets(raw, "liver.msh");
  write_tetgen(mesh, dir.file("liver.ele"));  // either extension names the pair
  const RawMesh back = read_volume_file(dir.file("liver.node"));
  ASSERT_EQ(back.positions.size(), mesh.num_vertices());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) EXPECT_EQ(back.positions[v], mesh.positions[v]) << v;
  EXPECT_EQ(back.tets, test::raw_tets(mesh));
}

TEST(TetGenFiles, WriteIntoMissingFolderThrowsAndLeavesNothing) {
  TempDir dir;
  EXPECT_THROW(write_tetgen(test::kuhn_cube(), dir.file("no/such/folder/out")), InputError);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(TetGenFiles, FailedWriteLeavesTheOldFilesUntouched) {
  TempDir dir;
  const TetMesh mesh = test::expect_valid_tets(
      read_volume_file(mtcut::test::shared_mesh("Armadillo_Tetra_4406.vtu")), "armadillo");
  dir.write("out.node", "old node\n");
  dir.write("out.ele", "old ele\n");
  {
    test::FileSizeCap cap(16 * 1024);
    EXPECT_THROW(write_tetgen(mesh, dir.file("out")), InputError);
  }
  EXPECT_EQ(test::read_bytes(dir.file("out.node")), "old node\n");
  EXPECT_EQ(test::read_bytes(dir.file("out.ele")), "old ele\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.ele", "out.node"}));
}

TEST(TetGenFiles, MissingEleIsNamed) {
  TempDir dir;
  dir.write("lonely.node", kCubeNode);
  test::expect_input_error([&] { read_volume_file(dir.file("lonely.node")); }, {"lonely.ele", "no such file"});
}

TEST(TetGenFiles, BrokenNodeFilesAreRejectedWithTheLine) {
  TempDir dir;
  struct Case {
    std::string name, node;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {"empty", "# only a comment\n", {"cube-empty.node", "no data"}},
      {"truncated", replace_once(kCubeNode, "8 1.0e0 +1 1 0.5 1   # last point\n", ""),
       {"line 11", "truncated", "8 points declared, only 7"}},
      {"extra", std::string(kCubeNode) + "9 2 2 2 0.5 1\n", {"line 12", "more points than the 8 declared"}},
      {"nan", replace_once(kCubeNode, "3 0 1 0", "3 0 nan 0"), {"line 5", "point 3 coordinate 'nan' is not finite"}},
      {"inf", replace_once(kCubeNode, "3 0 1 0", "3 0 -inf 0"), {"line 5", "not finite"}},
      {"word", replace_once(kCubeNode, "6 1 0 1", "6 1 zero 1"), {"line 9", "'zero' is not a number"}},
      {"huge", replace_once(kCubeNode, "6 1 0 1", "6 1 1e999 1"), {"line 9", "'1e999' is not a number"}},
      {"short", replace_once(kCubeNode, "5 0 0 1 0.5 1", "5 0 0 1"), {"line 8", "has 4 values, expected 6"}},
      {"gap", replace_once(kCubeNode, "5 0 0 1", "15 0 0 1"), {"line 8", "consecutive", "expected 5, found 15"}},
      {"dim2", replace_once(kCubeNode, "8 3 1 1", "8 2 1 1"), {"line 2", "dimension is 2"}},
      {"count", replace_once(kCubeNode, "8 3 1 1", "eight 3 1 1"), {"line 2", "'eight' is not an integer"}},
      {"negative", replace_once(kCubeNode, "8 3 1 1", "-8 3 1 1"), {"line 2", "negative"}},
      {"absurd", replace_once(kCubeNode, "8 3 1 1", "800000000000 3 1 1"), {"line 2", "more than the file can hold"}},
      {"zero", replace_once(kCubeNode, "8 3 1 1", "0 3 1 1"), {"declares no points"}},
      {"markers", replace_once(kCubeNode, "8 3 1 1", "8 3 1 2"), {"marker flag is 2"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = write_pair(dir, "cube-" + c.name, c.node, kCubeEle);
    try {
      read_volume_file(path);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("cube-" + c.name + ".node"), std::string::npos) << message;
      for (const auto& part : c.parts) EXPECT_NE(message.find(part), std::string::npos) << message << " / " << part;
    }
  }
}

TEST(TetGenFiles, BrokenEleFilesAreRejectedWithTheLine) {
  TempDir dir;
  struct Case {
    std::string name, ele;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {"empty", "\n\n", {"no data"}},
      {"truncated", replace_once(kCubeEle, "6 1 6 2 8 7\n", ""), {"line 7", "6 tets declared, only 5"}},
      {"extra", std::string(kCubeEle) + "7 1 2 3 4 0\n", {"line 8", "more tets than the 6 declared"}},
      {"range", replace_once(kCubeEle, "3 1 3 7 8", "3 1 3 9 8"), {"line 4", "tet 3 refers to point 9", "numbered 1..8"}},
      {"zero", replace_once(kCubeEle, "3 1 3 7 8", "3 1 3 0 8"), {"line 4", "refers to point 0"}},
      {"word", replace_once(kCubeEle, "2 1 4 3 8", "2 1 four 3 8"), {"line 3", "'four' is not an integer"}},
      {"real", replace_once(kCubeEle, "2 1 4 3 8", "2 1 4.5 3 8"), {"line 3", "'4.5' is not an integer"}},
      {"short", replace_once(kCubeEle, "4 1 7 5 8 7", "4 1 7 5 8"), {"line 5", "has 5 values, expected 6"}},
      {"corners", replace_once(kCubeEle, "6 4 1", "6 5 1"), {"line 1", "5 nodes, expected 4 or 10"}},
      {"gap", replace_once(kCubeEle, "5 1 5 6", "9 1 5 6"), {"line 6", "consecutive"}},
      {"region", replace_once(kCubeEle, "1 1 2 4 8 7", "1 1 2 4 8 nan"), {"line 2", "not finite"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    write_pair(dir, "cube-" + c.name, kCubeNode, c.ele);
    try {
      read_volume_file(dir.file("cube-" + c.name + ".ele"));
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("cube-" + c.name + ".ele"), std::string::npos) << message;
      for (const auto& part : c.parts) EXPECT_NE(message.find(part), std::string::npos) << message << " / " << part;
    }
  }
}

}  // namespace
}  // namespace mtcut::engine
