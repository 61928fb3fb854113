#include "app/cli_checks.h"

#include <cmath>
#include <string>

namespace mtcut::app {
namespace {

CLI::Validator number_at_least(bool zero_allowed) {
  return CLI::Validator(
      [zero_allowed](std::string& input) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(input, value) || !std::isfinite(value)) return "'" + input + "' is not a number";
        if (zero_allowed ? value < 0 : value <= 0)
          return "'" + input + "' must be " + (zero_allowed ? "0 or more" : "greater than 0");
        return {};
      },
      zero_allowed ? "NONNEGATIVE" : "POSITIVE");
}

}  // namespace

const CLI::Validator& positive_number() {
  static const CLI::Validator check = number_at_least(false);
  return check;
}

const CLI::Validator& non_negative_number() {
  static const CLI::Validator check = number_at_least(true);
  return check;
}

}  // namespace mtcut::app
