#include "engine/surface_mesh.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "engine/builtin_shapes.h"
#include "engine/input_error.h"
#include "tests/temp_dir.h"
#include "tests/test_paths.h"

namespace mtcut::engine {
namespace {
namespace fs = std::filesystem;

class SurfaceFiles : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return dir_.file(name); }
  std::string write(const std::string& name, const std::string& text) const { return dir_.write(name, text); }
  mtcut::test::TempDir dir_;
};

using mtcut::test::input_error_of;

TEST_F(SurfaceFiles, ReadsTheRealSurfaces) {
  const SurfaceMesh liver = read_surface_file(mtcut::test::shared_mesh("liver.obj"));
  EXPECT_EQ(liver.positions.size(), 139u);  // the file lists 181, 42 of which no face uses
  EXPECT_EQ(liver.triangles.size(), 274u);
  EXPECT_EQ(liver.count_open_edges(), 0u);
  EXPECT_GT(std::abs(liver.enclosed_volume()), 0);

  const SurfaceMesh liver2 = read_surface_file(mtcut::test::shared_mesh("liver2.obj"));
  EXPECT_EQ(liver2.positions.size(), 1170u);
  EXPECT_EQ(liver2.count_open_edges(), 0u);

  const SurfaceMesh torus = read_surface_file(mtcut::test::shared_mesh("torus.obj"));
  EXPECT_EQ(torus.positions.size(), 800u);
  EXPECT_EQ(torus.count_open_edges(), 0u);
}

TEST_F(SurfaceFiles, PolygonFacesAreTriangulated) {
  const std::string file = write("quad.obj",
                                 "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                                 "f 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n");
  const SurfaceMesh s = read_surface_file(file);
  EXPECT_EQ(s.triangles.size(), 6u);
  EXPECT_EQ(s.count_open_edges(), 0u);
  EXPECT_NEAR(s.enclosed_volume(), 1.0 / 3.0, 1e-12);
}

TEST_F(SurfaceFiles, EveryFormatRoundTrips) {
  BuiltinShapeDef def;
  def.shape = BuiltinShape::kEllipsoid;
  def.target_tets = 500;
  const SurfaceMesh shape = make_builtin_surface(def);
  for (const std::string ext : {".obj", ".off", ".stl", ".ply"}) {
    const std::string file = path("shape" + ext);
    write_surface_file(shape, file);
    const SurfaceMesh back = read_surface_file(file);
    EXPECT_EQ(back.triangles.size(), shape.triangles.size()) << ext;
    EXPECT_EQ(back.count_open_edges(), 0u) << ext;
    // STL stores floats; the rest keep enough digits.
    EXPECT_NEAR(back.enclosed_volume(), shape.enclosed_volume(), 1e-5 * shape.enclosed_volume()) << ext;
  }
}

// Some exporters begin a binary STL's 80-byte header with "solid", the
// ascii keyword: the file's size tells it is binary.
TEST_F(SurfaceFiles, ABinaryStlWhoseHeaderSaysSolidIsReadAsBinary) {
  BuiltinShapeDef def;
  def.shape = BuiltinShape::kEllipsoid;
  def.target_tets = 500;
  const SurfaceMesh shape = make_builtin_surface(def);
  const std::string file = path("exported.stl");
  write_surface_file(shape, file);
  {
    std::fstream patch(file, std::ios::in | std::ios::out | std::ios::binary);
    const std::string header = "solid exported by a CAD tool";
    patch.write(header.data(), static_cast<std::streamsize>(header.size()));
  }
  ASSERT_EQ(format_of_content(file), MeshFormat::kStl);
  const SurfaceMesh back = read_surface_file(file);
  EXPECT_EQ(back.triangles.size(), shape.triangles.size());
  EXPECT_NEAR(back.enclosed_volume(), shape.enclosed_volume(), 1e-5 * shape.enclosed_volume());
}

TEST_F(SurfaceFiles, BadFilesGiveOneClearLine) {
  EXPECT_NE(input_error_of([&] { read_surface_file(path("missing.obj")); }).find("missing.obj: no such file"),
            std::string::npos);
  const std::string empty = write("empty.obj", "");
  EXPECT_NE(input_error_of([&] { read_surface_file(empty); }).find("empty.obj: the file is empty"), std::string::npos);
  const std::string nan = write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n");
  const std::string m = input_error_of([&] { read_surface_file(nan); });
  EXPECT_NE(m.find("nan.obj: line 2: non-finite coordinate 'nan'"), std::string::npos) << m;
  const std::string inf = write("inf.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 -inf 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  EXPECT_NE(input_error_of([&] { read_surface_file(inf); }).find("inf.off: line 5"), std::string::npos);
  const std::string nofaces = write("nofaces.obj", "v 0 0 0\nv 1 0 0\n");
  EXPECT_NE(input_error_of([&] { read_surface_file(nofaces); }).find("no faces"), std::string::npos);
}

// A damaged OBJ record is named, not skipped: the faces after a dropped
// vertex would point at the wrong vertices.
TEST_F(SurfaceFiles, DamagedObjRecordsAreNamedWithTheirLine) {
  const std::string faces = "f 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";
  const auto error_of = [&](const std::string& name, const std::string& text) {
    return input_error_of([&] { read_surface_file(write(name, text)); });
  };
  std::string m = error_of("glued.obj", "v 0 0 0\nv*-0.8 1 0 0\nv 0 1 0\nv 0 0 1\n" + faces);
  EXPECT_NE(m.find("glued.obj: line 2: 'v*-0.8' is not an OBJ record"), std::string::npos) << m;
  m = error_of("short.obj", "v 0 0 0\nv 1 0 0\nv 0 1\nv 0 0 1\n" + faces);
  EXPECT_NE(m.find("short.obj: line 3: a vertex with fewer than three coordinates"), std::string::npos) << m;
  m = error_of("word.obj", "v 0 0 0\nv 1 x 0\nv 0 1 0\nv 0 0 1\n" + faces);
  EXPECT_NE(m.find("word.obj: line 2: vertex coordinate 'x' is not a number"), std::string::npos) << m;
  m = error_of("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 0 2 3\n" + faces);
  EXPECT_NE(m.find("zero.obj: line 5: face corner '0' is not a vertex of the file"), std::string::npos) << m;
  m = error_of("back.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -1 -2 -5\n" + faces);
  EXPECT_NE(m.find("back.obj: line 5: face corner '-5'"), std::string::npos) << m;
  m = error_of("beyond.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n" + faces + "f 1 2 9/1/1\n");
  EXPECT_NE(m.find("beyond.obj: line 9: a face corner is vertex 9 of a file of 4"), std::string::npos) << m;
  // What the reader takes for floats: a coordinate beyond a float's range or
  // in hexadecimal would be dropped with its vertex.
  m = error_of("huge.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nv 0 0 1\n" + faces);
  EXPECT_NE(m.find("huge.obj: line 2: coordinate '1e39' is beyond a float's range"), std::string::npos) << m;
  m = error_of("hex.obj", "v 0 0 0\nv 0x1p0 0 0\nv 0 1 0\nv 0 0 1\n" + faces);
  EXPECT_NE(m.find("hex.obj: line 2: vertex coordinate '0x1p0' is not a number"), std::string::npos) << m;
  // A byte order mark would hide the first vertex.
  m = error_of("bom.obj", "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n" + faces);
  EXPECT_NE(m.find("bom.obj: line 1: the file starts with a byte order mark"), std::string::npos) << m;
  // What an OBJ may hold besides: colours after a vertex, texture and normal
  // records, relative and slashed corners, groups (named "inf"), comments
  // (on their own lines and after a face), empty lines, CRLF ends.
  const SurfaceMesh fine = read_surface_file(
      write("fine.obj",
            "# a tetrahedron\r\nmtllib t.mtl\r\no t\r\nv 0 0 0 1 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 0 0 1\r\n"
            "vt 0 0\r\nvn 0 0 1\r\ng inf\r\ns off\r\nf 1/1/1 3/1/1 2/1/1 # the base\r\nf 1//1 2//1 4//1\r\n"
            "# nan is not a number here\r\nf -4 -1 -2\r\n\r\nf 2 3 4\r\n"));
  EXPECT_EQ(fine.positions.size(), 4u);
  EXPECT_EQ(fine.triangles.size(), 4u);
  EXPECT_EQ(fine.count_open_edges(), 0u);
}

// Two tets' surfaces that share an edge (four faces on it, as where two
// pieces of a cut touch): every face is written, the one OpenMesh would
// refuse over copies of its vertices. A face of repeated ids is refused.
TEST_F(SurfaceFiles, EveryFaceIsWrittenEvenWhereTheSurfaceIsNotManifold) {
  SurfaceMesh s;
  s.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, -1, -1), Vec3(1, 1, -1)};
  // Tets (0 1 2 3) and (0 1 4 5), outward faces; edge 0-1 is in four.
  s.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}};
  const auto text_of = [](const std::string& file) {
    std::ifstream in(file);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  write_surface_file(s, path("bowtie.obj"));
  std::istringstream obj(text_of(path("bowtie.obj")));
  std::size_t faces = 0, vertices = 0;
  for (std::string line; std::getline(obj, line);) {
    faces += line.rfind("f ", 0) == 0;
    vertices += line.rfind("v ", 0) == 0;
  }
  EXPECT_EQ(faces, 8u);
  EXPECT_GT(vertices, 6u) << "a refused face's vertices are copied";
  EXPECT_LE(vertices, 12u) << "the faces refused share their copies";
  write_surface_file(s, path("bowtie.off"));
  std::istringstream off(text_of(path("bowtie.off")));
  std::string magic;
  std::size_t off_vertices = 0, off_faces = 0;
  off >> magic >> off_vertices >> off_faces;
  EXPECT_EQ(off_faces, 8u);
  s.triangles.push_back({2, 2, 3});
  EXPECT_THROW(write_surface_file(s, path("degenerate.obj")), std::invalid_argument);
}

// The same two tets' surfaces read back: OpenMesh's importer would put a
// face it cannot add to its halfedge mesh over copies of its corners; the
// surface read keeps every face over the file's own vertices.
TEST_F(SurfaceFiles, ANonManifoldSurfaceIsReadAsTheFileGivesIt) {
  const char* const points[6] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1", "1 -1 -1", "1 1 -1"};
  const int faces[8][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}};
  std::string obj, off = "OFF\n6 8 0\n", stl = "solid bowtie\n",
                   ply = "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 8\nproperty list uchar int vertex_indices\nend_header\n";
  for (const char* p : points) {
    obj += std::string("v ") + p + "\n";
    off += std::string(p) + "\n";
    ply += std::string(p) + "\n";
  }
  for (const auto& f : faces) {
    const std::string ids = std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]);
    obj += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1) + "\n";
    off += "3 " + ids + "\n";
    ply += "3 " + ids + "\n";
    stl += " facet normal 0 0 0\n  outer loop\n";
    for (int id : f) stl += std::string("   vertex ") + points[id] + "\n";
    stl += "  endloop\n endfacet\n";
  }
  stl += "endsolid bowtie\n";
  for (const auto& [name, text] : {std::pair{"bowtie.obj", obj}, std::pair{"bowtie.off", off},
                                   std::pair{"bowtie.ply", ply}, std::pair{"bowtie.stl", stl}}) {
    SCOPED_TRACE(name);
    const SurfaceMesh s = read_surface_file(write(name, text));
    EXPECT_EQ(s.positions.size(), 6u);
    ASSERT_EQ(s.triangles.size(), 8u);
    // Edge 0-1 is in four faces; every other edge in two.
    EXPECT_EQ(s.count_open_edges(), 1u);
    EXPECT_NEAR(s.enclosed_volume(), 1.0 / 6 + 1.0 / 3, 1e-12);
  }
  // A damaged OFF whose last face names vertices past the file's six: where
  // the importer put a refused face's copies. It is no face of the file.
  std::string damaged = off;
  damaged.replace(damaged.find("6 8 0"), 5, "6 9 0");
  damaged += "3 6 7 8\n";
  const SurfaceMesh s = read_surface_file(write("damaged.off", damaged));
  EXPECT_EQ(s.positions.size(), 6u);
  EXPECT_EQ(s.triangles.size(), 8u);
}

TEST_F(SurfaceFiles, FailedWriteLeavesNothingBehind) {
  SurfaceMesh s = make_builtin_surface(BuiltinShapeDef{BuiltinShape::kBox, Vec3(1, 1, 1), 10});
  EXPECT_THROW(write_surface_file(s, path("nodir/out.obj")), InputError);
  EXPECT_THROW(write_surface_file(s, path("out.xyz")), InputError);
  EXPECT_TRUE(fs::is_empty(dir_.path()));
}

}  // namespace
}  // namespace mtcut::engine
