#include "engine/atomic_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "engine/input_error.h"

namespace mtcut::engine {
namespace fs = std::filesystem;

void write_atomically(const std::string& path, const std::function<bool(const std::string& temp_path)>& write) {
  const fs::path target(path);
  // Keep the extension last: some writers (OpenMesh) pick the format from it.
  const fs::path temp = target.parent_path() /
                        (".tmp-" + std::to_string(::getpid()) + "-" + target.filename().string());
  bool ok = false;
  try {
    ok = write(temp.string());
  } catch (...) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw;
  }
  std::error_code ec;
  if (!ok || !fs::exists(temp, ec)) {
    fs::remove(temp, ec);
    throw InputError(path + ": cannot write the file");
  }
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw InputError(path + ": cannot write the file (" + ec.message() + ")");
  }
}

void write_stream_atomically(const std::string& path, const std::function<void(std::ostream& out)>& write) {
  write_atomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    write(out);
    out.flush();
    return static_cast<bool>(out);
  });
}

}  // namespace mtcut::engine
