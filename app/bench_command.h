#pragma once
// `mtcut bench ...`: performance figures as JSON (medians of timed batches
// after a warm-up). Never run from tests with a time bound.

#include <CLI/CLI.hpp>

namespace mtcut::app {

void register_bench_command(CLI::App& app);

}  // namespace mtcut::app
