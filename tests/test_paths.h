#pragma once
// Where tests find the real meshes, the sources and the built mtcut binary.

#include <string>

namespace mtcut::test {

inline std::string shared_mesh(const std::string& name) { return std::string(MTCUT_SHARED_MESHES) + "/" + name; }
inline std::string source_path(const std::string& rel) { return std::string(MTCUT_SOURCE_DIR) + "/" + rel; }
inline std::string mtcut_binary() { return MTCUT_BINARY; }

}  // namespace mtcut::test
