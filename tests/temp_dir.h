#pragma once
// Test helpers for files: a fresh temporary folder that removes itself, and
// the message of a call expected to fail with an InputError.

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <system_error>
#include <vector>

#include "engine/input_error.h"

namespace mtcut::test {

// A fresh folder under the system temp folder, removed with its contents.
// Named by process and a counter: tests of one binary, and the processes
// ctest runs side by side, never share one.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("mtcut-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // The path of name inside the folder.
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  // Writes bytes to name inside the folder; returns its path.
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string p = file(name);
    std::ofstream out(p, std::ios::binary);
    out << bytes;
    return p;
  }
  // Every entry in the folder, by name.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path path_;
};

// The message of the InputError call() throws, or "no error" when it
// returns (any other exception propagates and fails the test).
inline std::string input_error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const engine::InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace mtcut::test
