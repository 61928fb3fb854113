// Every mesh file the project has (../shared/meshes, the readers' test
// data, and each format written here), truncated, bit-flipped and spliced
// at random, through the whole load: read, repair, mesh, split pinches,
// validate. Each variant gives a valid mesh or one InputError line; never a
// crash (the sanitizer builds run it too), a hang or another exception.
// One test per file; at least 1,000 variants in all (as many per file), in
// the ASan + UBSan tree too (its smaller test size does not turn the corpus
// down: under AddressSanitizer is where a corrupted file's overrun shows),
// more at an MTCUT_TEST_SIZE above 1.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include "engine/input_error.h"
#include "engine/io/mesh_file.h"
#include "engine/mesh_loader.h"
#include "engine/surface_mesh.h"
#include "tests/engine/io/io_test_util.h"
#include "tests/test_paths.h"
#include "tests/test_size.h"

namespace mtcut::engine {
namespace {

constexpr int kVariants = 1000;
const char* const kWritten[] = {"written.vtu", "written.node", "written.ele", "written.obj",
                                "written.off", "written.stl",  "written.ply"};

// The corpus: the shared meshes and the readers' data by path, then the
// files written here by name.
std::vector<std::string> corpus_files() {
  std::vector<std::string> files;
  for (const std::string& folder : {mtcut::test::shared_mesh(""), mtcut::test::source_path("tests/engine/io/data")}) {
    std::vector<std::string> here;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() != ".md") here.push_back(entry.path().string());
    std::sort(here.begin(), here.end());
    files.insert(files.end(), here.begin(), here.end());
  }
  for (const char* name : kWritten) files.push_back(name);
  return files;
}

// Writes each format the project writes, of a small organ, into `dir`.
void write_formats(const mtcut::test::TempDir& dir) {
  MeshLoadDef small;
  small.builtin_tets = 300;
  small.builtin_size = Vec3(0.08, 0.05, 0.04);
  const TetMesh organ = load_mesh("builtin:ellipsoid", small).mesh;
  write_vtu(organ, dir.file("written.vtu"));
  write_tetgen(organ, dir.file("written"));
  for (const char* ext : {".obj", ".off", ".stl", ".ply"})
    write_surface_file(extract_boundary(organ), dir.file(std::string("written") + ext));
}

class MeshCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(MeshCorpus, CorruptedFilesLoadValidOrGiveOneLine) {
  mtcut::test::TempDir dir;
  std::string source = GetParam();
  if (!std::filesystem::path(source).has_parent_path()) {
    write_formats(dir);
    source = dir.file(source);
  }
  const std::size_t files = corpus_files().size();
  const auto variants =
      static_cast<int>(std::ceil(std::max(kVariants, mtcut::test::scaled(kVariants)) / static_cast<double>(files)));
  MeshLoadDef def;
  def.meshing.radius_edge_ratio = 0;  // TetGen's quality refinement is not what is tested here
  std::mt19937 rng(static_cast<unsigned>(std::hash<std::string>()(std::filesystem::path(source).filename())));
  const std::string ext = std::filesystem::path(source).extension().string();
  const std::string base = source.substr(0, source.size() - ext.size());
  int loaded = 0, refused = 0;
  for (int i = 0; i < variants; ++i) {
    // A TetGen pair: one file corrupted, the other intact.
    if (ext == ".node" || ext == ".ele") {
      dir.write("case.node", test::read_bytes(base + ".node"));
      dir.write("case.ele", test::read_bytes(base + ".ele"));
    }
    const std::string path = dir.write("case" + ext, test::corrupt(test::read_bytes(source), rng));
    try {
      const LoadedMesh mesh = load_mesh(path, def);
      EXPECT_TRUE(mesh.mesh.validate().ok()) << source << " variant " << i;
      ++loaded;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << source << " variant " << i << ": " << what;
      EXPECT_FALSE(what.empty());
      ++refused;
    }
  }
  std::printf("%s: %d variants, %d loaded, %d refused\n", source.c_str(), variants, loaded, refused);
}

std::string file_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = std::filesystem::path(info.param).filename().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Files, MeshCorpus, ::testing::ValuesIn(corpus_files()), file_name);

}  // namespace
}  // namespace mtcut::engine
