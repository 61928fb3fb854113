#pragma once
// The error a user can cause (a bad file, a broken surface, a bad option).
// Its message is one line naming the input and the fault, ready to print.

#include <stdexcept>
#include <string>

namespace mtcut::engine {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// Builds "source: line N: what" (line omitted when 0).
std::string describe_at(const std::string& source, std::size_t line, const std::string& what);

}  // namespace mtcut::engine
