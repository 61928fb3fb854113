#pragma once
// How much of a heavy property test to run: the environment's
// MTCUT_TEST_SIZE, a share of the full size, else the build's
// (CMake's MTCUT_TEST_SIZE: 1, and 0.25 in sanitizer builds, which run 3
// to 10 times slower). A test turned down still runs: scaled() keeps at
// least one of anything.

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mtcut::test {

// A value that is no positive number (unset, empty, 0, text) leaves the
// build's size.
inline double test_size() {
  const char* env = std::getenv("MTCUT_TEST_SIZE");
  const double size = env ? std::atof(env) : 0.0;
  return size > 0 ? size : MTCUT_TEST_SIZE_DEFAULT;
}

// n at the test's size, at least 1.
inline int scaled(int n) { return std::max(1, static_cast<int>(std::lround(n * test_size()))); }

}  // namespace mtcut::test
