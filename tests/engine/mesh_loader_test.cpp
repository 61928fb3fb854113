// load_mesh: a file's unit scales it to metres, a size that looks like other
// units leaves a note naming them, and what is loaded is valid or refused.

#include "engine/mesh_loader.h"

#include <gtest/gtest.h>

#include "engine/io/mesh_file.h"
#include "engine/mesh_stats.h"
#include "engine/surface_mesh.h"
#include "tests/engine/io/io_test_util.h"
#include "tests/temp_dir.h"

namespace mtcut::engine {
namespace {

// A box of `size` (file units) written as a tet mesh and as its surface.
struct BoxFiles {
  std::string vtu, obj;
};

BoxFiles write_box(const mtcut::test::TempDir& dir, const Vec3& size) {
  MeshLoadDef def;
  def.builtin_size = size;
  def.builtin_tets = 300;
  const TetMesh box = load_mesh("builtin:box", def).mesh;
  BoxFiles files{dir.file("box.vtu"), dir.file("box.obj")};
  write_vtu(box, files.vtu);
  write_surface_file(extract_boundary(box), files.obj);
  return files;
}

TEST(MeshUnits, NamedUnitsAreMetresDecimetresCentimetresMillimetres) {
  EXPECT_EQ(metres_per_unit("m"), 1.0);
  EXPECT_EQ(metres_per_unit("dm"), 0.1);
  EXPECT_EQ(metres_per_unit("cm"), 0.01);
  EXPECT_EQ(metres_per_unit("mm"), 0.001);
  EXPECT_FALSE(metres_per_unit("km"));
  EXPECT_FALSE(metres_per_unit("MM"));
  EXPECT_FALSE(metres_per_unit(""));
}

TEST(LoadMesh, AUnitScalesTetMeshesAndSurfacesToMetres) {
  mtcut::test::TempDir dir;
  const BoxFiles files = write_box(dir, Vec3(100, 200, 50));  // millimetres
  for (const std::string& path : {files.vtu, files.obj}) {
    MeshLoadDef def;
    def.metres_per_unit = 0.001;
    def.unit_stated = true;
    const LoadedMesh loaded = load_mesh(path, def);
    EXPECT_NEAR(compute_stats(loaded.mesh).volume, 0.1 * 0.2 * 0.05, 1e-12) << path;
    EXPECT_TRUE(loaded.notes.empty()) << path << ": " << loaded.notes.front().text;
  }
}

TEST(LoadMesh, AMeshInMillimetresReadAsMetresIsToldToSayMillimetres) {
  mtcut::test::TempDir dir;
  const BoxFiles files = write_box(dir, Vec3(180, 120, 90));
  for (const std::string& path : {files.vtu, files.obj}) {
    const LoadedMesh loaded = load_mesh(path, {});
    ASSERT_EQ(loaded.notes.size(), 1u) << path;
    const InputNote& note = loaded.notes[0];
    EXPECT_NE(note.text.find(path), std::string::npos) << note.text;
    EXPECT_NE(note.text.find("they may be millimetres"), std::string::npos) << note.text;
    EXPECT_EQ(note.text.find('\n'), std::string::npos);
    EXPECT_EQ(note.hint.kind, InputHint::Kind::kUnits);
    EXPECT_EQ(note.hint.unit, "mm");
    // The advice in a command line's terms is the app's: the note names no flag.
    EXPECT_EQ(note.text.find("--"), std::string::npos) << note.text;
  }
}

// The unit suggested is named in the note and given by its symbol in the
// hint; a size no unit makes organ-sized still hints at the unit, naming none.
TEST(LoadMesh, SizesSuggestTheUnitThatMakesThemOrganSized) {
  struct Case {
    double extent;
    std::string unit, says;
  };
  const std::vector<Case> cases = {
      {25.0, "cm", "; they may be centimetres"}, {2500.0, "mm", "; they may be millimetres"}, {0.0002, "", ""}};
  for (const auto& [extent, unit, says] : cases) {
    const std::vector<Vec3> box = {Vec3::Zero(), Vec3(extent, 0.6 * extent, 0.5 * extent)};
    const auto note = implausible_size_note(box, {}, "organ.obj");
    ASSERT_TRUE(note) << extent;
    EXPECT_EQ(note->hint.kind, InputHint::Kind::kUnits) << extent;
    EXPECT_EQ(note->hint.unit, unit) << extent;
    const std::string fact = ", which is not an organ's size" + says;
    ASSERT_GE(note->text.size(), fact.size()) << note->text;
    EXPECT_EQ(note->text.substr(note->text.size() - fact.size()), fact) << note->text;
  }
  const std::vector<Vec3> organ = {Vec3::Zero(), Vec3(0.2, 0.1, 0.1)};
  EXPECT_FALSE(implausible_size_note(organ, {}, "organ.obj"));
  // A stated unit is taken as given, whatever the size.
  MeshLoadDef stated;
  stated.unit_stated = true;
  const std::vector<Vec3> huge = {Vec3::Zero(), Vec3(300, 200, 100)};
  EXPECT_FALSE(implausible_size_note(huge, stated, "organ.obj"));
}

// A file whose name says one format and whose content another is read by
// its content, with a note saying so.
TEST(LoadMesh, AFileIsReadAsItsContentSaysWithANote) {
  mtcut::test::TempDir dir;
  const BoxFiles files = write_box(dir, Vec3(0.1, 0.08, 0.06));
  const std::string obj_named_stl = dir.write("box.stl", test::read_bytes(files.obj));
  const std::string vtu_named_vtk = dir.write("box.vtk", test::read_bytes(files.vtu));
  const std::string vtu_named_txt = dir.write("box.txt", test::read_bytes(files.vtu));
  for (const auto& [path, says] : std::vector<std::pair<std::string, std::string>>{
           {obj_named_stl, "read as OBJ, which its content is, not STL"},
           {vtu_named_vtk, "read as VTK XML, which its content is, not legacy VTK"},
           {vtu_named_txt, "read as VTK XML, which its content is"}}) {
    const LoadedMesh loaded = load_mesh(path, {});
    EXPECT_NEAR(compute_stats(loaded.mesh).volume, 0.1 * 0.08 * 0.06, 1e-9) << path;  // OBJ keeps floats
    ASSERT_EQ(loaded.notes.size(), 1u) << path;
    EXPECT_EQ(loaded.notes[0].text, path + ": " + says);
    EXPECT_EQ(loaded.notes[0].hint.kind, InputHint::Kind::kNone);
  }
  EXPECT_TRUE(load_mesh(files.obj, {}).notes.empty());
}

TEST(LoadMesh, ABuiltinShapeTakesNoUnit) {
  MeshLoadDef def;
  def.metres_per_unit = 0.001;
  EXPECT_NE(mtcut::test::input_error_of([&] { load_mesh("builtin:box", def); }).find("sized in metres"), std::string::npos);
  def.metres_per_unit = 0;
  EXPECT_NE(mtcut::test::input_error_of([&] { load_mesh("builtin:box", def); }).find("positive"), std::string::npos);
}

TEST(LoadMesh, OverlappingTetsAreRefusedNamingTheFile) {
  mtcut::test::TempDir dir;
  // Two tets on the same side of their shared face.
  const std::string path =
      dir.write("overlap.node", "5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 0.1 0.1 1\n");
  dir.write("overlap.ele", "2 4 0\n0 0 1 2 3\n1 0 1 2 4\n");
  const std::string error = mtcut::test::input_error_of([&] { load_mesh(path, {}); });
  EXPECT_NE(error.find("overlap.node"), std::string::npos) << error;
  EXPECT_NE(error.find("invalid tet mesh"), std::string::npos) << error;
}

}  // namespace
}  // namespace mtcut::engine
