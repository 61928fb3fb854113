#pragma once
// Runs the built mtcut binary as a user would, capturing stdout, stderr and
// the exit code, for end-to-end tests of the command line.

#include <string>

namespace mtcut::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs `mtcut ARGS` through the shell (ARGS is shell-quoted by the caller).
CommandResult run_mtcut(const std::string& args);

// Single-quotes a path or argument for the shell.
std::string quoted(const std::string& s);

}  // namespace mtcut::test
