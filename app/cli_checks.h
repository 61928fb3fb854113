#pragma once
// The checks of the commands' numeric options, saying what the value must
// be (CLI11's PositiveNumber and NonNegativeNumber print their range, up to
// the largest double written out in full).

#include <CLI/CLI.hpp>

namespace mtcut::app {

// A finite number greater than 0 (its type name in --help: POSITIVE).
const CLI::Validator& positive_number();
// A finite number of 0 or more (NONNEGATIVE).
const CLI::Validator& non_negative_number();

}  // namespace mtcut::app
