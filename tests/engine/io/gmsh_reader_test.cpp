// Gmsh .msh: the real liver (format 1), hand-made cubes in formats 2, 4.0
// and 4.1, and broken files of every kind.

#include <gtest/gtest.h>

#include "engine/io/mesh_file.h"
#include "engine/io/mesh_readers.h"
#include "tests/engine/io/io_test_util.h"
#include "tests/test_paths.h"

namespace mtcut::engine {
namespace {

using test::expect_all_rejected;
using test::expect_read_error;
using test::replace_once;
using test::TempDir;

// Kuhn cube corner i has node tag 10 * (i + 1), listed in reverse order so
// that ids follow the file, not the tags.
std::string cube_node_line(int i, bool with_tag = true) {
  std::string line = with_tag ? std::to_string(10 * (i + 1)) + " " : "";
  return line + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string((i >> 2) & 1) + "\n";
}

std::string tags_of(const int* corners, int n) {
  std::string s;
  for (int k = 0; k < n; ++k) s += " " + std::to_string(10 * (corners[k] + 1));
  return s;
}

// Format 2.2: a point, a line, two triangles, six tets; physical names skipped.
std::string msh2_cube() {
  std::string s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  s += "$PhysicalNames\n1\n3 1 \"tissue\"\n$EndPhysicalNames\n";
  s += "$Nodes\n8\n";
  for (int i = 7; i >= 0; --i) s += cube_node_line(i);
  s += "$EndNodes\n$Elements\n10\n";
  s += "1 15 2 0 1 10\n";
  s += "2 1 2 0 1 10 20\n";
  const int tri[2][3] = {{0, 1, 3}, {0, 3, 2}};
  for (int t = 0; t < 2; ++t) s += std::to_string(3 + t) + " 2 2 0 1" + tags_of(tri[t], 3) + "\n";
  for (int t = 0; t < 6; ++t) s += std::to_string(5 + t) + " 4 2 1 1" + tags_of(test::kKuhnTets[t], 4) + "\n";
  return s + "$EndElements\n$NodeData\n1\n\"T\"\n$EndNodeData\n";
}

// Format 4.1: entities, two node blocks (one parametric), element blocks.
std::string msh41_cube() {
  std::string s = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  s += "$Entities\n0 0 0 1\n1 0 0 0 1 1 1 0 0\n$EndEntities\n";
  s += "$Nodes\n2 8 10 80\n";
  s += "3 1 0 5\n";
  for (int i = 7; i >= 3; --i) s += std::to_string(10 * (i + 1)) + "\n";
  for (int i = 7; i >= 3; --i) s += cube_node_line(i, false);
  s += "2 1 1 3\n";
  for (int i = 2; i >= 0; --i) s += std::to_string(10 * (i + 1)) + "\n";
  for (int i = 2; i >= 0; --i) s += std::string(cube_node_line(i, false)).insert(cube_node_line(i, false).size() - 1, " 0.5 0.5");
  s += "$EndNodes\n$Elements\n3 9 1 9\n";
  s += "0 1 15 1\n1 10\n";
  s += "2 1 2 2\n2 10 20 40\n3 10 40 30\n";
  s += "3 1 4 6\n";
  for (int t = 0; t < 6; ++t) s += std::to_string(4 + t) + tags_of(test::kKuhnTets[t], 4) + "\n";
  return s + "$EndElements\n";
}

// Format 4.0: node lines hold their tag; block headers start with the entity tag.
std::string msh40_cube() {
  std::string s = "$MeshFormat\n4 0 8\n$EndMeshFormat\n";
  s += "$Nodes\n1 8\n1 3 0 8\n";
  for (int i = 7; i >= 0; --i) s += cube_node_line(i);
  s += "$EndNodes\n$Elements\n2 7\n1 2 2 1\n1 10 20 40\n1 3 4 6\n";
  for (int t = 0; t < 6; ++t) s += std::to_string(2 + t) + tags_of(test::kKuhnTets[t], 4) + "\n";
  return s + "$EndElements\n";
}

// Node i of the cube was written (7 - i)-th, so its id is 7 - i.
void expect_gmsh_cube(const RawMesh& raw, std::size_t triangles) {
  ASSERT_EQ(raw.positions.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(raw.positions[static_cast<std::size_t>(7 - i)], Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  ASSERT_EQ(raw.tets.size(), 6u);
  for (int t = 0; t < 6; ++t)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(raw.tets[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)], 7 - test::kKuhnTets[t][k]);
  EXPECT_EQ(raw.triangles.size(), triangles);
  const TetMesh mesh = test::expect_valid_tets(raw, "cube");
  EXPECT_NEAR(mesh.total_volume(), 1.0, 1e-15);
}

TEST(GmshReader, ReadsRealLiverInFormat1) {
  const RawMesh raw = read_gmsh(mtcut::test::shared_mesh("liver.msh"));
  EXPECT_EQ(raw.positions.size(), 181u);
  EXPECT_EQ(raw.tets.size(), 596u);
  EXPECT_TRUE(raw.triangles.empty());
  test::expect_valid_tets(raw, "liver.msh");
}

TEST(GmshReader, ReadsFormat2WithTagsInAnyOrder) {
  TempDir dir;
  const RawMesh raw = read_volume_file(dir.write("cube2.msh", msh2_cube()));
  expect_gmsh_cube(raw, 2);
  EXPECT_EQ(raw.triangles[0], (std::array<std::int64_t, 3>{7, 6, 4}));
}

TEST(GmshReader, ReadsFormat41WithEntityBlocks) {
  TempDir dir;
  expect_gmsh_cube(read_volume_file(dir.write("cube41.msh", msh41_cube())), 2);
}

TEST(GmshReader, ReadsFormat40) {
  TempDir dir;
  expect_gmsh_cube(read_volume_file(dir.write("cube40.msh", msh40_cube())), 1);
}

TEST(GmshReader, KeepsTheCornersOfQuadraticElements) {
  TempDir dir;
  std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n10\n";
  const double p[10][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {.5, 0, 0}, {.5, .5, 0}, {0, .5, 0}, {0, 0, .5}, {.5, 0, .5}, {0, .5, .5}};
  for (int i = 0; i < 10; ++i)
    text += std::to_string(i + 1) + " " + std::to_string(p[i][0]) + " " + std::to_string(p[i][1]) + " " + std::to_string(p[i][2]) + "\n";
  text += "$EndNodes\n$Elements\n2\n1 11 0 1 2 3 4 5 6 7 8 9 10\n2 9 0 1 2 3 5 6 7\n$EndElements\n";
  const RawMesh raw = read_volume_file(dir.write("quadratic.msh", text));
  ASSERT_EQ(raw.tets.size(), 1u);
  EXPECT_EQ(raw.tets[0], (std::array<std::int64_t, 4>{0, 1, 2, 3}));
  ASSERT_EQ(raw.triangles.size(), 1u);
  EXPECT_EQ(raw.triangles[0], (std::array<std::int64_t, 3>{0, 1, 2}));
  // A mid-edge node must exist too.
  test::expect_input_error([&] { read_volume_file(dir.write("mid.msh", replace_once(text, "9 10\n", "9 11\n"))); },
                           {"mid.msh", "line 19", "node 11"});
  test::expect_input_error([&] { read_volume_file(dir.write("short.msh", replace_once(text, "9 10\n", "9\n"))); },
                           {"short.msh", "line 19", "element 1 (a tet) has 9 nodes, expected 10"});
}

TEST(GmshReader, ReadsFilesWrittenByMeshio) {
  for (const char* name : {"cube_meshio22.msh", "cube_meshio41.msh"}) {
    SCOPED_TRACE(name);
    const RawMesh raw = read_volume_file(test::io_data(name));
    EXPECT_EQ(raw.positions, test::kuhn_cube().positions);
    EXPECT_EQ(raw.tets, test::raw_tets(test::kuhn_cube()));
  }
}

TEST(GmshReader, ReadsWindowsLineEnds) {
  TempDir dir;
  std::string text;
  for (char c : msh2_cube()) text += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expect_gmsh_cube(read_volume_file(dir.write("crlf.msh", text)), 2);
}

TEST(GmshReader, RejectsBrokenFormat2Files) {
  const std::string good = msh2_cube();
  // Lines: 1-3 format, 4-7 names, 8 $Nodes, 9 count, 10-17 nodes, 18 $EndNodes,
  // 19 $Elements, 20 count, 21-30 elements, 31 $EndElements.
  expect_all_rejected({
      {"version3.msh", replace_once(good, "2.2 0 8", "3.0 0 8"), {"line 2", "unsupported Gmsh format version 3.0"}},
      {"binary.msh", replace_once(good, "2.2 0 8", "2.2 1 8"), {"line 2", "binary"}},
      {"fewer-nodes.msh", replace_once(good, "$Nodes\n8\n", "$Nodes\n9\n"), {"line 18", "$Nodes ends early", "9 nodes declared, 8 read"}},
      {"more-nodes.msh", replace_once(good, "$Nodes\n8\n", "$Nodes\n7\n"), {"line 17", "expected $EndNodes", "counts disagree"}},
      {"fewer-elements.msh", replace_once(good, "$Elements\n10\n", "$Elements\n11\n"), {"line 31", "11 elements declared, 10 read"}},
      {"nan.msh", replace_once(good, "60 1 0 1", "60 nan 0 1"), {"line 12", "node 60 coordinate 'nan' is not finite"}},
      {"word.msh", replace_once(good, "60 1 0 1", "60 1 O 1"), {"line 12", "'O' is not a number"}},
      {"short-node.msh", replace_once(good, "60 1 0 1", "60 1 0"), {"line 12", "tag x y z"}},
      {"duplicate.msh", replace_once(good, "60 1 0 1", "70 1 0 1"), {"line 12", "node 70 is defined twice"}},
      {"unknown-tag.msh", replace_once(good, "7 4 2 1 1 10 30 70 80", "7 4 2 1 1 10 30 99 80"), {"line 27", "node 99"}},
      {"tet3.msh", replace_once(good, "7 4 2 1 1 10 30 70 80", "7 4 2 1 1 10 30 70"), {"line 27", "element 7 (a tet) has 3 nodes, expected 4"}},
      {"tags.msh", replace_once(good, "5 4 2 1 1", "5 4 9 1 1"), {"line 25", "fewer tags"}},
      {"unclosed.msh", replace_once(good, "$EndNodeData\n", ""), {"line 32", "$NodeData is never closed"}},
      {"no-format.msh", replace_once(good, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", ""), {"line 5", "$Nodes comes before $MeshFormat"}},
      {"no-nodes.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", {"no $Nodes section"}},
      {"text.msh", "hello world\n", {"line 1", "expected a section", "'hello'"}},
      {"absurd.msh", replace_once(good, "$Nodes\n8\n", "$Nodes\n99999999999\n"), {"line 9", "more than the file can hold"}},
      {"truncated.msh", good.substr(0, good.find("60 1 0 1")), {"truncated", "8 nodes declared, 2 read"}},
  });
}

TEST(GmshReader, RejectsBrokenFormat4Files) {
  const std::string g41 = msh41_cube();
  const std::string g40 = msh40_cube();
  expect_all_rejected({
      {"v41-total.msh", replace_once(g41, "$Nodes\n2 8 10 80", "$Nodes\n2 9 10 80"), {"$Nodes declares 9 nodes, its blocks hold 8"}},
      {"v41-block.msh", replace_once(g41, "3 1 0 5", "3 1 0 9"), {"line 10", "more nodes than the 8 declared"}},
      {"v41-tagline.msh", replace_once(g41, "3 1 0 5\n80\n", "3 1 0 5\n80 70\n"), {"line 11", "expected one node tag"}},
      {"v41-elements.msh", replace_once(g41, "3 9 1 9", "3 10 1 9"), {"$Elements declares 10 elements, its blocks hold 9"}},
      {"v41-tet.msh", replace_once(g41, "4 10 20 40 80", "4 10 20 40"), {"element 4 (a tet) has 3 nodes"}},
      {"v41-header.msh", replace_once(g41, "$Nodes\n2 8 10 80", "$Nodes\n2 8"), {"$Nodes header needs 4 values"}},
      {"v40-nan.msh", replace_once(g40, "20 1 0 0", "20 1 0 inf"), {"node 20 coordinate 'inf' is not finite"}},
      {"v40-range.msh", replace_once(g40, "2 10 20 40 80", "2 10 20 40 81"), {"node 81"}},
      {"v40-end.msh", replace_once(g40, "$EndElements", "$EndElement"), {"expected $EndElements"}},
  });
}

}  // namespace
}  // namespace mtcut::engine
