#include "engine/io/mesh_file.h"

#include <gtest/gtest.h>

#include "engine/input_error.h"
#include "tests/engine/io/io_test_util.h"
#include "tests/test_paths.h"

namespace mtcut::engine {
namespace {

using test::expect_read_error;
using test::TempDir;

TEST(MeshFile, KnowsVolumeExtensionsInAnyCase) {
  for (const char* path : {"a.node", "a.ele", "a.msh", "a.vtk", "a.vtu", "dir/B.VTU", "x.Msh", "y.NODE"})
    EXPECT_TRUE(is_volume_file(path)) << path;
  for (const char* path : {"a.obj", "a.stl", "a", "a.vtp", "a.node.bak", "msh", ".vtk.txt"})
    EXPECT_FALSE(is_volume_file(path)) << path;
}

TEST(MeshFile, DispatchesEachRealMeshByExtension) {
  const RawMesh msh = read_volume_file(mtcut::test::shared_mesh("liver.msh"));
  EXPECT_EQ(msh.tets.size(), 596u);
  const RawMesh vtk = read_volume_file(mtcut::test::shared_mesh("liver.vtk"));
  EXPECT_EQ(vtk.triangles.size(), 10000u);
  const RawMesh vtu = read_volume_file(mtcut::test::shared_mesh("Armadillo_Tetra_4406.vtu"));
  EXPECT_EQ(vtu.tets.size(), 4406u);
}

TEST(MeshFile, UpperCaseExtensionIsReadLikeLowerCase) {
  TempDir dir;
  const std::string path = dir.write("LIVER.MSH", test::read_bytes(mtcut::test::shared_mesh("liver.msh")));
  EXPECT_EQ(read_volume_file(path).tets.size(), 596u);
}

TEST(MeshFile, MissingFileIsNamed) {
  TempDir dir;
  for (const char* name : {"none.msh", "none.vtk", "none.vtu", "none.node"})
    expect_read_error(dir.file(name), {"no such file"});
  // A .ele path reads the pair, .node first: the message names that one.
  test::expect_input_error([&] { read_volume_file(dir.file("none.ele")); }, {"none.node", "no such file"});
}

TEST(MeshFile, EmptyFileIsNamed) {
  TempDir dir;
  for (const char* name : {"empty.msh", "empty.vtk", "empty.vtu"})
    expect_read_error(dir.write(name, ""), {"the file is empty"});
}

TEST(MeshFile, DirectoryIsNotAMesh) {
  TempDir dir;
  std::filesystem::create_directories(dir.file("folder.vtu"));
  expect_read_error(dir.file("folder.vtu"), {"is a directory"});
}

TEST(MeshFile, UnknownExtensionIsRejected) {
  TempDir dir;
  expect_read_error(dir.write("mesh.xyz", "1 2 3\n"), {"unknown tet-mesh format", ".xyz"});
}

TEST(MeshFile, BinaryGarbageIsRejectedByEveryReader) {
  TempDir dir;
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage += static_cast<char>((i * 7919 + 13) & 0xff);
  for (const char* name : {"junk.msh", "junk.vtk", "junk.vtu", "junk.node"})
    EXPECT_THROW(read_volume_file(dir.write(name, garbage)), InputError) << name;
}

}  // namespace
}  // namespace mtcut::engine
