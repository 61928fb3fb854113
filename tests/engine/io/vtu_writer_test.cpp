// The .vtu writer: round trips through read_vtu, cell data, the file's
// layout, and atomic writes (nothing half-written, old files untouched).

#include <gtest/gtest.h>

#include "engine/io/binary_values.h"
#include "engine/io/mesh_file.h"
#include "engine/io/mesh_readers.h"
#include "engine/io/xml_scanner.h"
#include "engine/surface_mesh.h"
#include "tests/engine/io/io_test_util.h"
#include "tests/test_paths.h"

namespace mtcut::engine {
namespace {

using test::TempDir;

void expect_same_mesh(const RawMesh& back, const TetMesh& mesh) {
  ASSERT_EQ(back.positions.size(), mesh.num_vertices());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) ASSERT_EQ(back.positions[v], mesh.positions[v]) << v;
  EXPECT_EQ(back.tets, test::raw_tets(mesh));
  EXPECT_TRUE(back.triangles.empty());
}

// The Float64 values of the cell data array called name, read from the
// appended block of a file this writer made.
std::vector<double> cell_data_values(const std::string& text, const std::string& name) {
  XmlScanner xml("written.vtu", text);
  XmlTag tag;
  std::size_t offset = SIZE_MAX;
  bool big_endian = false;
  while (xml.next_tag(tag)) {
    if (tag.name == "VTKFile") big_endian = tag.attribute("byte_order") == "BigEndian";
    if (tag.name == "DataArray" && tag.attribute("Name") == name) offset = std::stoul(*tag.attribute("offset"));
    if (tag.name == "AppendedData") break;
  }
  EXPECT_NE(offset, SIZE_MAX) << name;
  if (offset == SIZE_MAX) return {};
  const std::size_t start = text.find('_', tag.end) + 1 + offset;
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data() + start);
  std::int64_t n = 0;
  EXPECT_TRUE(decode_int(bytes, ScalarType{8, false, false}, big_endian, n));
  std::vector<double> values;
  for (std::int64_t i = 0; i < n / 8; ++i)
    values.push_back(decode_real(bytes + 8 + 8 * i, ScalarType{8, true, true}, big_endian));
  return values;
}

TEST(VtuWriter, KuhnCubeRoundTrips) {
  TempDir dir;
  const TetMesh cube = test::kuhn_cube();
  write_vtu(cube, dir.file("cube.vtu"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"cube.vtu"});
  expect_same_mesh(read_volume_file(dir.file("cube.vtu")), cube);
}

TEST(VtuWriter, RealMeshesRoundTripExactly) {
  TempDir dir;
  for (const char* name : {"liver.msh", "Armadillo_Tetra_4406.vtu"}) {
    SCOPED_TRACE(name);
    const TetMesh mesh = test::expect_valid_tets(read_volume_file(mtcut::test::shared_mesh(name)), name);
    write_vtu(mesh, dir.file("out.vtu"));
    const RawMesh back = read_vtu(dir.file("out.vtu"));
    expect_same_mesh(back, mesh);
    EXPECT_TRUE(test::expect_valid_tets(back, "out.vtu").validate().ok());
  }
}

TEST(VtuWriter, ASurfaceRoundTripsAsTriangleCellsWithItsCellData) {
  TempDir dir;
  SurfaceMesh surface;  // a tetrahedron's four faces
  surface.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  surface.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  write_vtu(surface, dir.file("surface.vtu"), {{"piece", {0, 1, 2, 3}}});
  const RawMesh back = read_vtu(dir.file("surface.vtu"));
  EXPECT_EQ(back.positions, surface.positions);
  EXPECT_EQ(back.triangles, (std::vector<std::array<std::int64_t, 3>>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}));
  EXPECT_TRUE(back.tets.empty());
  EXPECT_EQ(cell_data_values(test::read_bytes(dir.file("surface.vtu")), "piece"), (std::vector<double>{0, 1, 2, 3}));
  EXPECT_THROW(write_vtu(surface, dir.file("bad.vtu"), {{"piece", {0, 1}}}), InputError);
}

TEST(VtuWriter, EmptyMeshRoundTrips) {
  TempDir dir;
  write_vtu(TetMesh{}, dir.file("empty.vtu"));
  const RawMesh back = read_vtu(dir.file("empty.vtu"));
  EXPECT_TRUE(back.positions.empty());
  EXPECT_TRUE(back.tets.empty());
}

TEST(VtuWriter, WritesTheLayoutParaViewExpects) {
  TempDir dir;
  write_vtu(test::kuhn_cube(), dir.file("cube.vtu"));
  const std::string text = test::read_bytes(dir.file("cube.vtu"));
  EXPECT_EQ(text.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\"", 0), 0u);
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
  for (const char* array : {"type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"",
                            "type=\"Int64\" Name=\"connectivity\"", "type=\"Int64\" Name=\"offsets\"",
                            "type=\"UInt8\" Name=\"types\"", "<AppendedData encoding=\"raw\">"})
    EXPECT_NE(text.find(array), std::string::npos) << array;
  EXPECT_TRUE(text.ends_with("</AppendedData>\n</VTKFile>\n"));
}

TEST(VtuWriter, WritesCellDataWithEscapedNames) {
  TempDir dir;
  const TetMesh cube = test::kuhn_cube();
  const std::vector<CellField> fields = {{"error", {1, 2, 3, 4, 5, 6.5}}, {"a<b & \"c\"", {-1, 0, 1e300, 1e-300, 0.1, 7}}};
  write_vtu(cube, dir.file("fields.vtu"), fields);
  const std::string text = test::read_bytes(dir.file("fields.vtu"));
  EXPECT_NE(text.find("<CellData>"), std::string::npos);
  EXPECT_NE(text.find("Name=\"a&lt;b &amp; &quot;c&quot;\""), std::string::npos);
  EXPECT_EQ(cell_data_values(text, "error"), fields[0].values);
  EXPECT_EQ(cell_data_values(text, "a<b & \"c\""), fields[1].values);
  expect_same_mesh(read_vtu(dir.file("fields.vtu")), cube);
}

TEST(VtuWriter, FieldOfWrongSizeThrowsAndWritesNothing) {
  TempDir dir;
  test::expect_input_error([&] { write_vtu(test::kuhn_cube(), dir.file("bad.vtu"), {{"short", {1, 2}}}); },
                           {"bad.vtu", "cell field 'short' has 2 values for 6 tets"});
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VtuWriter, WriteIntoMissingFolderThrowsAndLeavesNothing) {
  TempDir dir;
  test::expect_input_error([&] { write_vtu(test::kuhn_cube(), dir.file("missing/cube.vtu")); }, {"missing/cube.vtu"});
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VtuWriter, FailedWriteLeavesTheOldFileUntouched) {
  TempDir dir;
  const TetMesh mesh = test::expect_valid_tets(
      read_volume_file(mtcut::test::shared_mesh("Armadillo_Tetra_4406.vtu")), "armadillo");
  const std::string old = dir.write("out.vtu", "old content\n");
  {
    test::FileSizeCap cap(16 * 1024);  // the mesh needs ~200 KB: the write fails half-way
    EXPECT_THROW(write_vtu(mesh, old), InputError);
  }
  EXPECT_EQ(test::read_bytes(old), "old content\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.vtu"});  // no temporary left
}

}  // namespace
}  // namespace mtcut::engine
