#pragma once
// Seconds on the steady clock: every timing the commands, the cutters and the
// viewer report is one of these.

#include <chrono>

namespace mtcut::engine {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace mtcut::engine
