// Legacy VTK: the real liver surface (binary POLYDATA) and its broken twin,
// hand-made ascii and binary unstructured grids in the classic and the 5.1
// cell layouts, polygons and strips, and broken files of every kind.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <limits>
#include <cstring>

#include "engine/io/mesh_file.h"
#include "engine/io/mesh_readers.h"
#include "tests/engine/io/io_test_util.h"
#include "tests/test_paths.h"

namespace mtcut::engine {
namespace {

using test::BadFile;
using test::expect_all_rejected;
using test::expect_read_error;
using test::replace_once;
using test::TempDir;

// Appends value in big-endian byte order.
template <class T>
void put_be(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::little) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

// An ascii unstructured grid: the Kuhn cube, plus a triangle, a line and a
// vertex (skipped), a FIELD before the points and point data after.
std::string ascii_grid() {
  std::string s = "# vtk DataFile Version 3.0\ncube\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  s += "FIELD FieldData 1\nTIME 1 1 double\n0.5\n";
  s += "POINTS 8 double\n";
  for (int i = 0; i < 8; ++i) s += std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string((i >> 2) & 1) + "\n";
  s += "CELLS 9 39\n";
  for (const auto& t : test::kKuhnTets) s += "4 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + " " + std::to_string(t[3]) + "\n";
  s += "3 0 1 3\n2 0 1\n1 7\n";
  s += "CELL_TYPES 9\n10\n10\n10\n10\n10\n10\n5\n3\n1\n";
  s += "POINT_DATA 8\nSCALARS t float 1\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 7\n";
  return s;
}

// The same grid, binary, with float or double points.
std::string binary_grid(bool doubles) {
  std::string s = "# vtk DataFile Version 3.0\ncube\nBINARY\nDATASET UNSTRUCTURED_GRID\n";
  s += "FIELD FieldData 1\nTIME 1 1 double\n";
  put_be(s, 0.5);
  s += std::string("\nPOINTS 8 ") + (doubles ? "double" : "float") + "\n";
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) {
      const int c = (i >> k) & 1;
      if (doubles) put_be(s, static_cast<double>(c));
      else put_be(s, static_cast<float>(c));
    }
  s += "\nCELLS 7 34\n";
  for (const auto& t : test::kKuhnTets) {
    put_be<std::int32_t>(s, 4);
    for (int k = 0; k < 4; ++k) put_be<std::int32_t>(s, t[k]);
  }
  put_be<std::int32_t>(s, 3);
  for (int v : {0, 1, 3}) put_be<std::int32_t>(s, v);
  s += "\nCELL_TYPES 7\n";
  for (int c = 0; c < 6; ++c) put_be<std::int32_t>(s, 10);
  put_be<std::int32_t>(s, 5);
  s += "\nCELL_DATA 7\nSCALARS id int 1\nLOOKUP_TABLE default\n";
  for (int c = 0; c < 7; ++c) put_be<std::int32_t>(s, c);
  return s + "\n";
}

// Version 5.1 layout: CELLS n_offsets n_ids, then OFFSETS and CONNECTIVITY.
std::string grid51(bool binary) {
  std::string s = std::string("# vtk DataFile Version 5.1\ncube\n") + (binary ? "BINARY" : "ASCII") +
                  "\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 float\n";
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) {
      if (binary) put_be(s, static_cast<float>((i >> k) & 1));
      else s += std::to_string((i >> k) & 1) + (k == 2 ? "\n" : " ");
    }
  s += std::string(binary ? "\n" : "") + "METADATA\nINFORMATION 0\n\n";
  s += "CELLS 7 24\nOFFSETS vtktypeint64\n";
  for (int c = 0; c <= 6; ++c) {
    if (binary) put_be<std::int64_t>(s, 4 * c);
    else s += std::to_string(4 * c) + " ";
  }
  s += "\nCONNECTIVITY vtktypeint64\n";
  for (const auto& t : test::kKuhnTets)
    for (int k = 0; k < 4; ++k) {
      if (binary) put_be<std::int64_t>(s, t[k]);
      else s += std::to_string(t[k]) + " ";
    }
  s += "\nCELL_TYPES 6\n";
  for (int c = 0; c < 6; ++c) {
    if (binary) put_be<std::int32_t>(s, 10);
    else s += "10\n";
  }
  return s + "\n";
}

void expect_vtk_cube(const RawMesh& raw, std::size_t triangles) {
  ASSERT_EQ(raw.positions.size(), 8u);
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(raw.positions[static_cast<std::size_t>(i)], Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  EXPECT_EQ(raw.tets, test::raw_tets(test::kuhn_cube()));
  EXPECT_EQ(raw.triangles.size(), triangles);
  const TetMesh mesh = test::expect_valid_tets(raw, "cube");
  EXPECT_NEAR(mesh.total_volume(), 1.0, 1e-15);
}

TEST(VtkLegacyReader, ReadsRealLiverSurfaceBinaryPolydata) {
  const RawMesh raw = read_vtk_legacy(mtcut::test::shared_mesh("liver.vtk"));
  EXPECT_EQ(raw.positions.size(), 5008u);
  EXPECT_EQ(raw.triangles.size(), 10000u);
  EXPECT_TRUE(raw.tets.empty());
  for (const auto& t : raw.triangles)
    for (std::int64_t id : t) ASSERT_TRUE(id >= 0 && id < 5008);
}

TEST(VtkLegacyReader, RejectsRealBrokenLiver) {
  // POINTS declares 508, the data is for 5008: the next keyword is not there.
  expect_read_error(mtcut::test::shared_mesh("liver_for_test_broken.vtk"),
                    {"the 508 points that POINTS declares", "counts disagree"});
}

TEST(VtkLegacyReader, ReadsAsciiUnstructuredGridSkippingOtherCellsAndData) {
  TempDir dir;
  expect_vtk_cube(read_volume_file(dir.write("cube.vtk", ascii_grid())), 1);
}

TEST(VtkLegacyReader, ReadsBinaryUnstructuredGridWithFloatAndDoublePoints) {
  TempDir dir;
  expect_vtk_cube(read_volume_file(dir.write("f.vtk", binary_grid(false))), 1);
  expect_vtk_cube(read_volume_file(dir.write("d.vtk", binary_grid(true))), 1);
}

TEST(VtkLegacyReader, ReadsVersion51OffsetsAndConnectivity) {
  TempDir dir;
  expect_vtk_cube(read_volume_file(dir.write("a51.vtk", grid51(false))), 0);
  expect_vtk_cube(read_volume_file(dir.write("b51.vtk", grid51(true))), 0);
}

TEST(VtkLegacyReader, ReadsVersion51FilesWrittenByMeshio) {
  for (const char* name : {"cube_meshio_ascii.vtk", "cube_meshio_binary.vtk"}) {
    SCOPED_TRACE(name);
    expect_vtk_cube(read_volume_file(test::io_data(name)), 0);
  }
}

TEST(VtkLegacyReader, KeepsTheCornersOfQuadraticCells) {
  TempDir dir;
  const std::string text =
      "# vtk DataFile Version 4.2\nq\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 10 float\n"
      "0 0 0 1 0 0 0 1 0 0 0 1 .5 0 0 .5 .5 0 0 .5 0 0 0 .5 .5 0 .5 0 .5 .5\n"
      "CELLS 3 21\n10 0 1 2 3 4 5 6 7 8 9\n6 0 1 2 4 5 6\n2 0 1\nCELL_TYPES 3\n24 22 3\n";
  const RawMesh raw = read_volume_file(dir.write("quadratic.vtk", text));
  ASSERT_EQ(raw.tets.size(), 1u);
  EXPECT_EQ(raw.tets[0], (std::array<std::int64_t, 4>{0, 1, 2, 3}));
  ASSERT_EQ(raw.triangles.size(), 1u);
  test::expect_input_error(
      [&] { read_volume_file(dir.write("q4.vtk", replace_once(text, "24 22 3", "10 22 3"))); },
      {"q4.vtk", "cell 0 has type 10 but 10 points (expected 4)"});
}

TEST(VtkLegacyReader, FansPolygonsAndSplitsStrips) {
  TempDir dir;
  const std::string text =
      "# vtk DataFile Version 2.0\nsquare\nascii\ndataset polydata\npoints 5 float\n"
      "0 0 0 1 0 0 1 1 0 0 1 0 0.5 0.5 1\n"
      "VERTICES 1 2\n1 4\nLINES 1 3\n2 0 1\n"
      "POLYGONS 2 9\n4 0 1 2 3\n3 0 1 4\n"
      "TRIANGLE_STRIPS 1 5\n4 0 1 3 2\n";
  const RawMesh raw = read_volume_file(dir.write("square.vtk", text));
  const std::vector<std::array<std::int64_t, 3>> expected = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {0, 1, 3}, {3, 1, 2}};
  EXPECT_EQ(raw.triangles, expected);
  EXPECT_TRUE(raw.tets.empty());
}

TEST(VtkLegacyReader, RejectsBrokenAsciiFiles) {
  const std::string good = ascii_grid();
  // Lines: 1 header, 2 title, 3 ASCII, 4 DATASET, 5-7 FIELD, 8 POINTS,
  // 9-16 points, 17 CELLS, 18-26 cells, 27 CELL_TYPES, 28-36 types.
  expect_all_rejected({
      {"version.vtk", replace_once(good, "Version 3.0", "Version 6.0"), {"line 1", "unsupported VTK file version '6.0'"}},
      {"nover.vtk", replace_once(good, " Version 3.0", " Version"), {"line 1", "version is missing"}},
      {"header.vtk", replace_once(good, "# vtk DataFile", "# VTX DataFile"), {"line 1", "not a legacy VTK file"}},
      {"format.vtk", replace_once(good, "ASCII", "TEXT"), {"line 3", "expected ASCII or BINARY"}},
      {"dataset.vtk", replace_once(good, "UNSTRUCTURED_GRID", "STRUCTURED_POINTS"), {"line 4", "STRUCTURED_POINTS is not supported"}},
      {"fewer-points.vtk", replace_once(good, "POINTS 8", "POINTS 9"), {"line 17", "'CELLS' is not a number"}},
      {"truncated.vtk", good.substr(0, good.find("0 1 1\n")), {"truncated", "POINTS declares 8 points, only 6"}},
      {"nan.vtk", replace_once(good, "0 1 0\n", "0 nan 0\n"), {"line 11", "point 2 has a non-finite coordinate 'nan'"}},
      {"word.vtk", replace_once(good, "0 1 0\n", "0 one 0\n"), {"line 11", "point 2: coordinate 'one' is not a number"}},
      {"range.vtk", replace_once(good, "4 0 6 4 7", "4 0 6 8 7"), {"cell 3 refers to point 8, but there are 8 points"}},
      {"negative.vtk", replace_once(good, "4 0 6 4 7", "4 0 6 -1 7"), {"cell 3 refers to point -1"}},
      {"size.vtk", replace_once(good, "CELLS 9 39", "CELLS 9 40"), {"line 27", "'CELL_TYPES' is not an integer"}},
      {"size-less.vtk", replace_once(good, "CELLS 9 39", "CELLS 9 38"), {"cell 8 has a bad corner count"}},
      {"ncells.vtk", replace_once(good, "CELLS 9 39", "CELLS 8 39"), {"size 39 but its 8 cells use 37"}},
      {"types.vtk", replace_once(good, "CELL_TYPES 9\n10\n", "CELL_TYPES 8\n"), {"CELL_TYPES has 8 values but CELLS has 9"}},
      {"tet3.vtk", replace_once(good, "CELL_TYPES 9\n10\n10\n10\n10\n10\n10\n5", "CELL_TYPES 9\n10\n10\n10\n10\n10\n10\n10"),
       {"cell 6 has type 10 but 3 points (expected 4)"}},
      {"keyword.vtk", replace_once(good, "CELL_TYPES 9", "CELL_TYPE 9"), {"line 27", "expected a keyword after the 9 cells of CELLS", "'CELL_TYPE'"}},
      {"absurd.vtk", replace_once(good, "POINTS 8", "POINTS 80000000000"), {"line 8", "more than the file can hold"}},
      {"points-type.vtk", replace_once(good, "POINTS 8 double", "POINTS 8 quad"), {"line 8", "unsupported data type 'quad'"}},
      {"no-points.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n", {"no POINTS section"}},
      {"no-types.vtk", good.substr(0, good.find("CELL_TYPES")), {"CELLS without CELL_TYPES"}},
      {"polygon2.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 3\n2 0 1\n",
       {"polygon 0 has 2 corners"}},
  });
}

TEST(VtkLegacyReader, RejectsBrokenBinaryFiles) {
  const std::string good = binary_grid(false);
  std::string nan_point = good;
  const std::size_t at = nan_point.find("POINTS 8 float\n") + std::string("POINTS 8 float\n").size() + 4 * 3 * 5;
  float nan = std::numeric_limits<float>::quiet_NaN();
  std::string be;
  put_be(be, nan);
  nan_point.replace(at, 4, be);
  std::string big_id = good;
  const std::size_t cells = big_id.find("CELLS 7 34\n") + std::string("CELLS 7 34\n").size();
  std::string bad;
  put_be<std::int32_t>(bad, 1000);
  big_id.replace(cells + 4 * 3, 4, bad);  // first tet, third corner
  expect_all_rejected({
      {"bin-nan.vtk", nan_point, {"point 5 has a non-finite coordinate"}},
      {"bin-range.vtk", big_id, {"cell 0 refers to point 1000, but there are 8 points"}},
      {"bin-truncated.vtk", good.substr(0, good.find("CELLS") + 111), {"byte", "truncated", "CELLS needs 136 bytes, only 100"}},
      {"bin-fewer.vtk", replace_once(good, "POINTS 8", "POINTS 7"), {"expected a keyword after the 7 points that POINTS declares"}},
      {"bin-more.vtk", replace_once(good, "POINTS 8", "POINTS 9"), {"byte", "expected a keyword"}},
      {"bin-int-points.vtk", replace_once(good, "CELL_TYPES 7", "CELL_TYPES 70"), {"truncated"}},
  });
}

}  // namespace
}  // namespace mtcut::engine
