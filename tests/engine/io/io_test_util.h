#pragma once
// Helpers for the mesh file tests: a temporary folder (tests/temp_dir.h)
// to write hand-made files into, a small valid tet mesh, the
// expectation that a call fails with an InputError naming given things, and
// a cap on file sizes that makes a write fail half-way.

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "engine/input_error.h"
#include "engine/io/mesh_file.h"
#include "engine/tet_mesh.h"
#include "tests/temp_dir.h"
#include "tests/test_paths.h"

namespace mtcut::engine::test {

// A small file in tests/engine/io/data: the Kuhn cube (kuhn_cube) written
// by meshio 5.3.5, an independent writer, in the formats named by the file.
inline std::string io_data(const std::string& name) { return mtcut::test::source_path("tests/engine/io/data/" + name); }

using mtcut::test::TempDir;

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Expects call() to throw an InputError whose message holds every part,
// and to be a single line.
inline void expect_input_error(const std::function<void()>& call, const std::vector<std::string>& parts) {
  try {
    call();
    ADD_FAILURE() << "no InputError thrown" << (parts.empty() ? std::string() : " (expected one mentioning " + parts.front() + ")");
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const std::string& part : parts)
      EXPECT_NE(message.find(part), std::string::npos) << "message: " << message << "\nmissing: " << part;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "message is not one line: " << message;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw something other than InputError: " << e.what();
  }
}

// Reads path and expects an InputError naming the file and every part.
inline void expect_read_error(const std::string& path, const std::vector<std::string>& parts) {
  std::vector<std::string> all = parts;
  all.push_back(std::filesystem::path(path).filename().string());
  expect_input_error([&] { read_volume_file(path); }, all);
}

// A broken file: its name, its text, and what the message must mention.
struct BadFile {
  std::string name, text;
  std::vector<std::string> parts;
};

// Writes each file into a fresh folder and expects read_volume_file to
// reject it naming the file and each part.
inline void expect_all_rejected(const std::vector<BadFile>& files) {
  TempDir dir;
  for (const BadFile& f : files) {
    SCOPED_TRACE(f.name);
    expect_read_error(dir.write(f.name, f.text), f.parts);
  }
}

// text with the first from replaced by to (which must be there).
inline std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "not in the text: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The 6 positive tets of the unit cube around its diagonal 0-7 (corner i at
// (i & 1, (i >> 1) & 1, (i >> 2) & 1)).
inline constexpr int kKuhnTets[6][4] = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};

// The unit cube made of kKuhnTets.
inline TetMesh kuhn_cube() {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  std::vector<std::array<std::int64_t, 4>> tets;
  for (const auto& t : kKuhnTets) tets.push_back({t[0], t[1], t[2], t[3]});
  return make_tet_mesh(p, tets, "cube");
}

// The six Kuhn tets of kuhn_cube as raw ids, for comparing with RawMesh.
inline std::vector<std::array<std::int64_t, 4>> raw_tets(const TetMesh& mesh) {
  std::vector<std::array<std::int64_t, 4>> out;
  for (const Tet& t : mesh.tets) out.push_back({t[0].value, t[1].value, t[2].value, t[3].value});
  return out;
}

// Expects a raw tet mesh to make a valid TetMesh of positive volume.
inline TetMesh expect_valid_tets(const RawMesh& raw, const std::string& source) {
  TetMesh mesh = make_tet_mesh(raw.positions, raw.tets, source);
  const auto report = mesh.validate();
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_GT(mesh.total_volume(), 0.0);
  return mesh;
}

// Caps the size of files this process may write, for one scope; writes past
// the cap fail (EFBIG) instead of raising SIGXFSZ.
class FileSizeCap {
 public:
  explicit FileSizeCap(rlim_t bytes) {
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    getrlimit(RLIMIT_FSIZE, &previous_);
    rlimit cap = previous_;
    cap.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &cap);
  }
  ~FileSizeCap() {
    setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  FileSizeCap(const FileSizeCap&) = delete;
  FileSizeCap& operator=(const FileSizeCap&) = delete;

 private:
  rlimit previous_{};
  void (*previous_handler_)(int) = nullptr;
};

// A corrupted copy of bytes: cut, bytes overwritten, a run deleted, or a
// troublesome token inserted.
inline std::string corrupt(const std::string& bytes, std::mt19937& rng) {
  std::string d = bytes;
  const auto at = [&] { return static_cast<std::size_t>(rng() % d.size()); };
  switch (rng() % 4) {
    case 0: d.resize(at()); break;
    case 1:
      for (unsigned k = 0, n = 1 + rng() % 4; k < n; ++k) d[at()] = static_cast<char>(rng());
      break;
    case 2: d.erase(at(), rng() % 20); break;
    default: {
      static const char* tokens[] = {"nan", " ", "\n", "-1", "999999", "<", ">", "\"", "=", "$", "0", "1e400", "_"};
      d.insert(at(), tokens[rng() % 13]);
    }
  }
  return d;
}

}  // namespace mtcut::engine::test
