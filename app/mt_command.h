#pragma once
// `mtcut mt IN | --preset NAME [--json]`: builds the Multi-Tessellation of a
// mesh, validates it, and prints its figures.

#include <CLI/CLI.hpp>

namespace mtcut::app {

void register_mt_command(CLI::App& app);

}  // namespace mtcut::app
