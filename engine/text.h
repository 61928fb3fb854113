#pragma once
// ASCII text helpers of the file readers and the commands: white space and
// case as files and file names spell them, never the locale's.

#include <filesystem>
#include <string>
#include <string_view>

namespace mtcut::engine {

// The C locale's white space (XML's is narrower: xml_scanner.cpp).
inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

inline std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

// The path's extension in lower case, with its dot: "organ.STL" -> ".stl".
inline std::string lower_extension(const std::string& path) {
  return lower(std::filesystem::path(path).extension().string());
}

}  // namespace mtcut::engine
