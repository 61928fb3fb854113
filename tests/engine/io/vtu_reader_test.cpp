// VTK XML .vtu: the real Armadillo (ascii) and its broken twin, and the
// Kuhn cube written here in every encoding (ascii, inline binary, appended
// raw and base64), both byte orders, both header types, and broken files.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <sstream>

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

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

// How the hand-made file stores its arrays.
struct VtuStyle {
  std::string format = "ascii";  // ascii, binary, appended
  std::string encoding = "raw";  // appended: raw or base64
  bool big_endian = false;
  bool header64 = false;          // header_type UInt64
  bool float32 = false;           // points as Float32 (else Float64)
  bool int64 = false;             // connectivity and offsets as Int64 (else Int32)
  bool split_base64 = false;      // header and data encoded separately
  bool information_key = false;   // an <InformationKey> inside the points array
  std::size_t header_extra = 0;   // bytes the connectivity header claims beyond the data
};

template <class T>
std::string bytes_of(const std::vector<T>& values, bool big_endian) {
  std::string out;
  for (T v : values) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (big_endian != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(T));
    out.append(b, sizeof(T));
  }
  return out;
}

class VtuMaker {
 public:
  explicit VtuMaker(VtuStyle style) : s_(std::move(style)) {}

  std::string make(const TetMesh& mesh) {
    std::vector<double> points;
    for (const Vec3& p : mesh.positions) points.insert(points.end(), {p.x(), p.y(), p.z()});
    std::vector<std::int64_t> connectivity, offsets;
    for (const Tet& t : mesh.tets) {
      for (VertId v : t) connectivity.push_back(v.value);
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    }
    const std::vector<std::uint8_t> types(mesh.num_tets(), 10);

    std::ostringstream x;
    x << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
      << (s_.big_endian ? "BigEndian" : "LittleEndian") << "\" header_type=\"" << (s_.header64 ? "UInt64" : "UInt32")
      << "\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << mesh.num_vertices() << "\" NumberOfCells=\""
      << mesh.num_tets() << "\">\n<Points>\n";
    if (s_.float32) {
      std::vector<float> f(points.begin(), points.end());
      array(x, "Float32", "Points\" NumberOfComponents=\"3", f, 3, 0, s_.information_key);
    } else {
      array(x, "Float64", "Points\" NumberOfComponents=\"3", points, 3, 0, s_.information_key);
    }
    x << "</Points>\n<Cells>\n";
    if (s_.int64) {
      array(x, "Int64", "connectivity", connectivity, 4, s_.header_extra);
      array(x, "Int64", "offsets", offsets, 1);
    } else {
      array(x, "Int32", "connectivity", std::vector<std::int32_t>(connectivity.begin(), connectivity.end()), 4,
            s_.header_extra);
      array(x, "Int32", "offsets", std::vector<std::int32_t>(offsets.begin(), offsets.end()), 1);
    }
    array(x, "UInt8", "types", types, 1);
    x << "</Cells>\n</Piece>\n</UnstructuredGrid>\n";
    if (s_.format == "appended") x << "<AppendedData encoding=\"" << s_.encoding << "\">\n_" << appended_ << "\n</AppendedData>\n";
    x << "</VTKFile>\n";
    return x.str();
  }

 private:
  std::string header(std::size_t n) const {
    return s_.header64 ? bytes_of(std::vector<std::uint64_t>{n}, s_.big_endian)
                       : bytes_of(std::vector<std::uint32_t>{static_cast<std::uint32_t>(n)}, s_.big_endian);
  }

  template <class T>
  void array(std::ostringstream& x, const char* type, const std::string& name, const std::vector<T>& values,
             std::size_t per_line, std::size_t header_extra = 0, bool information_key = false) {
    x << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"" << s_.format << "\"";
    if (s_.format == "appended") x << " offset=\"" << appended_.size() << "\"";
    x << ">\n";
    if (information_key)
      x << "<InformationKey name=\"L2_NORM_RANGE\" location=\"vtkDataArray\" length=\"2\">\n"
        << "<Value index=\"0\">\n0\n</Value>\n<Value index=\"1\">\n1.7\n</Value>\n</InformationKey>\n";
    const std::string data = bytes_of(values, s_.big_endian);
    const std::string head = header(data.size() + header_extra);
    const std::string encoded = s_.split_base64 ? base64(head) + base64(data) : base64(head + data);
    if (s_.format == "ascii") {
      for (std::size_t i = 0; i < values.size(); ++i)
        x << +values[i] << (i % per_line == per_line - 1 ? "\n" : " ");
    } else if (s_.format == "binary") {
      x << encoded << "\n";
    } else {
      appended_ += s_.encoding == "raw" ? head + data : encoded;
    }
    x << "</DataArray>\n";
  }

  VtuStyle s_;
  std::string appended_;
};

std::string cube_vtu(const VtuStyle& style) { return VtuMaker(style).make(test::kuhn_cube()); }

void expect_cube(const RawMesh& raw) {
  const TetMesh cube = test::kuhn_cube();
  EXPECT_EQ(raw.positions, cube.positions);
  EXPECT_EQ(raw.tets, test::raw_tets(cube));
  EXPECT_TRUE(raw.triangles.empty());
}

TEST(VtuReader, ReadsRealArmadilloAscii) {
  const RawMesh raw = read_vtu(mtcut::test::shared_mesh("Armadillo_Tetra_4406.vtu"));
  EXPECT_EQ(raw.positions.size(), 1446u);
  EXPECT_EQ(raw.tets.size(), 4406u);
  test::expect_valid_tets(raw, "armadillo");
}

TEST(VtuReader, RejectsRealBrokenArmadillo) {
  // The header says 1445 points and 4407 cells; the data holds 1446 and 4406.
  expect_read_error(mtcut::test::shared_mesh("Armadillo_Tetra_4406_for_test_broken.vtu"),
                    {"line 5", "4338 values", "NumberOfPoints=\"1445\"", "counts disagree"});
}

TEST(VtuReader, ReadsEveryEncodingByteOrderAndHeaderType) {
  TempDir dir;
  int n = 0;
  for (const char* format : {"ascii", "binary", "appended-raw", "appended-base64"})
    for (bool big : {false, true})
      for (bool header64 : {false, true})
        for (bool wide : {false, true}) {
          VtuStyle style;
          style.format = std::string(format).substr(0, std::string(format).find('-'));
          if (style.format == "appended") style.encoding = std::string(format).substr(9);
          style.big_endian = big;
          style.header64 = header64;
          style.int64 = wide;
          style.float32 = !wide;
          SCOPED_TRACE(std::string(format) + (big ? " big" : " little") + (header64 ? " h64" : " h32") + (wide ? " wide" : ""));
          expect_cube(read_volume_file(dir.write("cube" + std::to_string(n++) + ".vtu", cube_vtu(style))));
        }
}

TEST(VtuReader, ReadsFilesWrittenByMeshioAndRejectsCompressedOnes) {
  expect_cube(read_volume_file(test::io_data("cube_meshio_binary.vtu")));
  expect_read_error(test::io_data("cube_meshio_zlib.vtu"),
                    {"line 2", "compressed data (vtkZLibDataCompressor) is not supported"});
}

TEST(VtuReader, ReadsBase64WithSeparatelyEncodedHeaders) {
  TempDir dir;
  VtuStyle inline_style;
  inline_style.format = "binary";
  inline_style.split_base64 = true;
  expect_cube(read_volume_file(dir.write("split.vtu", cube_vtu(inline_style))));
  VtuStyle appended = inline_style;
  appended.format = "appended";
  appended.encoding = "base64";
  expect_cube(read_volume_file(dir.write("split-appended.vtu", cube_vtu(appended))));
}

TEST(VtuReader, SkipsInformationKeysInsideDataArrays) {
  TempDir dir;
  for (const char* format : {"ascii", "binary"}) {
    VtuStyle style;
    style.format = format;
    style.information_key = true;
    expect_cube(read_volume_file(dir.write(std::string("info-") + format + ".vtu", cube_vtu(style))));
  }
}

TEST(VtuReader, ConcatenatesPieces) {
  TempDir dir;
  const std::string one = cube_vtu({});
  const std::size_t begin = one.find("<Piece"), end = one.find("</Piece>") + 8;
  std::string two = one;
  two.insert(end, "\n" + one.substr(begin, end - begin));
  const RawMesh raw = read_volume_file(dir.write("two.vtu", two));
  ASSERT_EQ(raw.positions.size(), 16u);
  ASSERT_EQ(raw.tets.size(), 12u);
  EXPECT_EQ(raw.tets[6], (std::array<std::int64_t, 4>{8, 9, 11, 15}));
}

TEST(VtuReader, RejectsBrokenHeadersAndStructure) {
  const std::string good = cube_vtu({});
  VtuStyle appended;
  appended.format = "appended";
  const std::string raw = cube_vtu(appended);
  expect_all_rejected({
      {"compressed.vtu", replace_once(good, "header_type", "compressor=\"vtkZLibDataCompressor\" header_type"),
       {"line 2", "compressed data (vtkZLibDataCompressor) is not supported"}},
      {"version.vtu", replace_once(good, "version=\"1.0\" byte", "version=\"3.0\" byte"), {"line 2", "unsupported VTK XML version '3.0'"}},
      {"polydata.vtu", replace_once(good, "\"UnstructuredGrid\"", "\"PolyData\""), {"line 2", "'PolyData' is not supported"}},
      {"order.vtu", replace_once(good, "LittleEndian", "MiddleEndian"), {"line 2", "unknown byte_order 'MiddleEndian'"}},
      {"header.vtu", replace_once(good, "UInt32", "UInt16"), {"line 2", "unsupported header_type 'UInt16'"}},
      {"text.vtu", "hello\n", {"not a VTK XML file (no tags)"}},
      {"html.vtu", "<html><body/></html>\n", {"line 1", "first tag is <html>"}},
      {"unterminated.vtu", good.substr(0, good.find("NumberOfCells")), {"line 4", "ends inside the tag <Piece>"}},
      {"unquoted.vtu", replace_once(good, "NumberOfCells=\"6\"", "NumberOfCells=6"), {"line 4", "is not quoted"}},
      {"no-count.vtu", replace_once(good, "NumberOfCells=\"6\"", ""), {"line 4", "<Piece> has no NumberOfCells"}},
      {"bad-count.vtu", replace_once(good, "NumberOfCells=\"6\"", "NumberOfCells=\"-6\""), {"line 4", "'-6' is not a count"}},
      {"no-piece.vtu", good.substr(0, good.find("<Piece")) + "</UnstructuredGrid></VTKFile>", {"no <Piece>"}},
      {"no-points.vtu", replace_once(good, "<Points>", "<PointData>"), {"line 4", "no Points DataArray"}},
      {"no-cells.vtu", replace_once(good, "Name=\"types\"", "Name=\"kinds\""), {"no connectivity, offsets and types"}},
      {"type.vtu", replace_once(good, "Float64", "Float16"), {"line 6", "unsupported DataArray type 'Float16'"}},
      {"format.vtu", replace_once(good, "format=\"ascii\"", "format=\"hex\""), {"line 6", "unknown DataArray format 'hex'"}},
      {"components.vtu", replace_once(good, "NumberOfComponents=\"3\"", "NumberOfComponents=\"2\""), {"line 6", "NumberOfComponents is 2, expected 3"}},
      {"real-ids.vtu", replace_once(good, "\"Int32\" Name=\"connectivity\"", "\"Float32\" Name=\"connectivity\""),
       {"connectivity: the DataArray type is Float32, expected an integer type"}},
      {"unclosed.vtu", good.substr(0, good.find("</DataArray>")), {"line 6", "<DataArray> is never closed"}},
      {"no-appended.vtu", raw.substr(0, raw.find("<AppendedData")) + "</VTKFile>\n", {"line 6", "no <AppendedData>"}},
      {"encoding.vtu", replace_once(raw, "encoding=\"raw\"", "encoding=\"hex\""), {"unknown AppendedData encoding 'hex'"}},
      {"underscore.vtu", replace_once(raw, "\n_", "\n"), {"does not start with '_'"}},
  });
}

TEST(VtuReader, RejectsDataThatDisagreesWithTheHeader) {
  const std::string good = cube_vtu({});
  // Lines: 6 points DataArray, 7-14 points, 15 </DataArray>, 18 connectivity,
  // 19-24 tets, 25 </DataArray>, 26 offsets, 27-32, 33 </DataArray>, 34 types.
  expect_all_rejected({
      {"points.vtu", replace_once(good, "NumberOfPoints=\"8\"", "NumberOfPoints=\"9\""),
       {"line 6", "Points: the DataArray holds 24 values, but NumberOfPoints=\"9\" x 3 needs 27"}},
      {"cells.vtu", replace_once(good, "NumberOfCells=\"6\"", "NumberOfCells=\"7\""),
       {"line 26", "offsets: the DataArray holds 6 values, but NumberOfCells=\"7\" needs 7"}},
      {"nan.vtu", replace_once(good, "0 1 0\n", "0 nan 0\n"), {"line 9", "point 2 has a non-finite coordinate"}},
      {"word.vtu", replace_once(good, "0 1 0\n", "0 one 0\n"), {"line 9", "point 2: coordinate 'one' is not a number"}},
      {"id.vtu", replace_once(good, "0 3 2 7\n", "0 3 8 7\n"), {"line 18", "cell 1 refers to point 8, but the piece has 8 points"}},
      {"id-word.vtu", replace_once(good, "0 3 2 7\n", "0 3 x 7\n"), {"line 20", "connectivity: value 6 'x' is not an integer"}},
      {"offsets.vtu", replace_once(good, "4\n8\n12\n", "4\n8\n2\n"), {"line 26", "offsets: cell 2 ends at 2, outside 8..24"}},
      {"offsets-end.vtu",
       replace_once(replace_once(good, "\n24\n", "\n20\n"), "10\n10\n10\n10\n10\n10\n", "10\n10\n10\n10\n10\n7\n"), {"line 18", "connectivity holds 24 ids, but the 6 cells use 20"}},
      {"tet5.vtu", replace_once(good, "4\n8\n12\n", "5\n8\n12\n"), {"cell 0 has type 10 but 5 points (expected 4)"}},
  });
}

TEST(VtuReader, RejectsTruncatedAndCorruptBinaryData) {
  VtuStyle binary;
  binary.format = "binary";
  const std::string inline_good = cube_vtu(binary);
  VtuStyle lying = binary;
  lying.header_extra = 8;
  VtuStyle appended;
  appended.format = "appended";
  const std::string raw = cube_vtu(appended);
  VtuStyle appended_lying = appended;
  appended_lying.header_extra = 1000;
  VtuStyle b64 = appended;
  b64.encoding = "base64";
  const std::string encoded = cube_vtu(b64);
  const std::size_t underscore = raw.find("\n_") + 2;
  expect_all_rejected({
      {"inline-short.vtu", cube_vtu(lying), {"connectivity: the binary data is truncated: the header says 104 bytes, only 96"}},
      {"inline-char.vtu", replace_once(inline_good, "AAAA", "AA*A"), {"outside the base64 alphabet"}},
      {"appended-cut.vtu", raw.substr(0, underscore + 300), {"truncated"}},
      {"appended-lie.vtu", cube_vtu(appended_lying), {"connectivity: the appended data is truncated: the header says 1096 bytes"}},
      {"appended-offset.vtu", replace_once(raw, "offset=\"0\"", "offset=\"" + std::to_string(raw.size() - 1) + "\""),
       {"line 6", "offset " + std::to_string(raw.size() - 1) + " is past the end"}},
      {"appended-huge.vtu", replace_once(raw, "offset=\"0\"", "offset=\"99999\""),
       {"line 6", "offset='99999' is more than the file can hold"}},
      {"appended-odd.vtu", replace_once(raw, "offset=\"0\"", "offset=\"1\""), {"line 6", "Points:"}},
      {"base64-cut.vtu", encoded.substr(0, encoded.find("\n_") + 200), {"truncated"}},
  });
}

}  // namespace
}  // namespace mtcut::engine
