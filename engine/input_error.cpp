#include "engine/input_error.h"

namespace mtcut::engine {

std::string describe_at(const std::string& source, std::size_t line, const std::string& what) {
  if (line == 0) return source + ": " + what;
  return source + ": line " + std::to_string(line) + ": " + what;
}

}  // namespace mtcut::engine
