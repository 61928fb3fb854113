#include "engine/validation.h"

namespace mtcut::engine {

void ValidationReport::add(std::string problem) {
  if (problems.size() < kMaxListed) {
    problems.push_back(std::move(problem));
  } else {
    ++omitted;
  }
}

std::string ValidationReport::summary() const {
  if (ok()) return "ok";
  std::string out;
  for (const auto& p : problems) out += p + "\n";
  if (omitted > 0) out += "... and " + std::to_string(omitted) + " more\n";
  return out;
}

}  // namespace mtcut::engine
