#pragma once
// Reals in the text outputs of `mtcut run`: the shortest text that reads back
// as exactly the same double, independent of the locale.

#include <charconv>
#include <string>

namespace mtcut::app {

inline std::string format_real(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace mtcut::app
