#pragma once
// What validate() returns: every fault found, as text, so that a failing test
// says what is wrong and where, not just "false".

#include <string>
#include <vector>

namespace mtcut::engine {

struct ValidationReport {
  std::vector<std::string> problems;  // one line each, most important first
  std::size_t omitted = 0;            // faults found beyond kMaxListed

  static constexpr std::size_t kMaxListed = 20;

  bool ok() const { return problems.empty(); }
  void add(std::string problem);
  // All problems on separate lines ("ok" when there are none).
  std::string summary() const;
};

}  // namespace mtcut::engine
