#pragma once
// `mtcut view [SCENARIO] [--frames N] [--screenshot FILE]`: the interactive
// viewer (the mouse as scalpel), or, with --screenshot, N frames played
// without input and the last one written to a PNG (for tests and docs).

#include <CLI/CLI.hpp>

namespace mtcut::app {

void register_view_command(CLI::App& app);

}  // namespace mtcut::app
