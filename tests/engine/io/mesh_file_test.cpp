#include "engine/io/mesh_file.h"

#include <gtest/gtest.h>

#include <random>

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

TEST(MeshFile, TheContentTellsTheFormatWhereItCan) {
  using mtcut::test::shared_mesh;
  EXPECT_EQ(format_of_content(shared_mesh("liver.msh")), MeshFormat::kGmsh);
  EXPECT_EQ(format_of_content(shared_mesh("liver.vtk")), MeshFormat::kVtkLegacy);
  EXPECT_EQ(format_of_content(shared_mesh("Armadillo_Tetra_4406.vtu")), MeshFormat::kVtkXml);
  EXPECT_EQ(format_of_content(shared_mesh("liver2.obj")), MeshFormat::kObj);
  EXPECT_EQ(format_of_content(shared_mesh("liver.obj")), MeshFormat::kObj);
  for (const char* name : {"cube_meshio22.msh", "cube_meshio41.msh"})
    EXPECT_EQ(format_of_content(test::io_data(name)), MeshFormat::kGmsh) << name;
  for (const char* name : {"cube_meshio_ascii.vtk", "cube_meshio_binary.vtk"})
    EXPECT_EQ(format_of_content(test::io_data(name)), MeshFormat::kVtkLegacy) << name;
  for (const char* name : {"cube_meshio_binary.vtu", "cube_meshio_zlib.vtu"})
    EXPECT_EQ(format_of_content(test::io_data(name)), MeshFormat::kVtkXml) << name;
  TempDir dir;
  EXPECT_EQ(format_of_content(dir.write("a.x", "OFF\n4 4 0\n")), MeshFormat::kOff);
  EXPECT_EQ(format_of_content(dir.write("b.x", "# made by hand\nCOFF\n")), MeshFormat::kOff);
  EXPECT_EQ(format_of_content(dir.write("c.x", "ply\nformat ascii 1.0\n")), MeshFormat::kPly);
  EXPECT_EQ(format_of_content(dir.write("d.x", "solid organ\nfacet normal 0 0 1\n")), MeshFormat::kStl);
  EXPECT_EQ(format_of_content(dir.write("e.x", "\xEF\xBB\xBF# comment\n\nv 0 0 0\n")), MeshFormat::kObj);
  // A binary STL: 80 header bytes, a count of 1, one 50-byte triangle.
  std::string stl(84 + 50, '\0');
  stl[80] = 1;
  EXPECT_EQ(format_of_content(dir.write("f.x", stl)), MeshFormat::kStl);
  stl.push_back('\0');  // the size no longer matches the count
  EXPECT_EQ(format_of_content(dir.write("g.x", stl)), MeshFormat::kUnknown);
  // TetGen's numbers, an empty or a missing file tell nothing.
  EXPECT_EQ(format_of_content(dir.write("h.node", "# points\n4 3 0 0\n")), MeshFormat::kUnknown);
  EXPECT_EQ(format_of_content(dir.write("i.obj", "")), MeshFormat::kUnknown);
  EXPECT_EQ(format_of_content(dir.file("none.obj")), MeshFormat::kUnknown);
  EXPECT_EQ(format_of_file(dir.file("h.node")), MeshFormat::kTetgen);
}

TEST(MeshFile, AFileIsReadByItsContentWhenItsNameDisagrees) {
  TempDir dir;
  const std::string xml_named_vtk =
      dir.write("armadillo.vtk", test::read_bytes(mtcut::test::shared_mesh("Armadillo_Tetra_4406.vtu")));
  EXPECT_EQ(read_volume_file(xml_named_vtk, format_of_file(xml_named_vtk)).tets.size(), 4406u);
  const std::string gmsh_named_vtu = dir.write("liver.vtu", test::read_bytes(mtcut::test::shared_mesh("liver.msh")));
  EXPECT_EQ(read_volume_file(gmsh_named_vtu, format_of_file(gmsh_named_vtu)).tets.size(), 596u);
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
  for (const char* name : {"empty.msh", "empty.vtk", "empty.vtu", "empty.node"})
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

// Whatever a reader makes of a corrupted file, it either rejects it with an
// InputError of one line or returns a mesh whose ids and positions are sane;
// it never crashes, reads out of bounds (ASan) or throws anything else.
TEST(MeshFile, CorruptedFilesAreRejectedOrReadSanely) {
  TempDir dir;
  const RawMesh raw_liver = read_volume_file(mtcut::test::shared_mesh("liver.msh"));
  const TetMesh liver = make_tet_mesh(raw_liver.positions, raw_liver.tets, "liver");
  write_vtu(liver, dir.file("written.vtu"));
  write_tetgen(liver, dir.file("written"));
  const std::vector<std::string> sources = {
      mtcut::test::shared_mesh("liver.msh"), mtcut::test::shared_mesh("liver.vtk"),
      mtcut::test::shared_mesh("Armadillo_Tetra_4406.vtu"), dir.file("written.vtu"), dir.file("written.node"),
      dir.file("written.ele")};
  std::mt19937 rng(20240611);
  std::size_t rejected = 0, read = 0;
  for (const std::string& source : sources) {
    const std::string bytes = test::read_bytes(source);
    const std::string ext = std::filesystem::path(source).extension().string();
    for (int round = 0; round < 30; ++round) {
      // The pair's other file stays intact.
      if (ext == ".node") dir.write("case.ele", test::read_bytes(dir.file("written.ele")));
      if (ext == ".ele") dir.write("case.node", test::read_bytes(dir.file("written.node")));
      const std::string path = dir.write("case" + ext, test::corrupt(bytes, rng));
      try {
        const RawMesh raw = read_volume_file(path);
        const auto n = static_cast<std::int64_t>(raw.positions.size());
        for (const Vec3& p : raw.positions) ASSERT_TRUE(p.allFinite()) << source << " round " << round;
        for (const auto& t : raw.tets)
          for (std::int64_t id : t) ASSERT_TRUE(id >= 0 && id < n) << source << " round " << round;
        for (const auto& t : raw.triangles)
          for (std::int64_t id : t) ASSERT_TRUE(id >= 0 && id < n) << source << " round " << round;
        ++read;
      } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        ++rejected;
      }
    }
  }
  EXPECT_GT(rejected, read);  // most corruptions are caught
}

}  // namespace
}  // namespace mtcut::engine
