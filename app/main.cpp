// mtcut: the command line. Each subcommand lives in its own file and
// registers itself here; errors a user can cause in an input end as one line
// on stderr and exit code 1; command-line usage errors exit 2.

#include <CLI/CLI.hpp>
#include <iostream>

#include "app/bench_command.h"
#include "app/cut_command.h"
#include "app/hid/hid_command.h"
#include "app/mesh_command.h"
#include "app/mt_command.h"
#include "app/run_command.h"
#include "app/view/view_command.h"
#include "engine/input_error.h"

int main(int argc, char** argv) {
  CLI::App app{
      "mtcut: progressive cutting of a multiresolution tetrahedral model in a mass-spring simulation.\n"
      "Mesh an organ, build its multiresolution model, cut it, run scripted scenarios, benchmark."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "mtcut 0.1.0");

  mtcut::app::register_mesh_command(app);
  mtcut::app::register_mt_command(app);
  mtcut::app::register_cut_command(app);
  mtcut::app::register_run_command(app);
  mtcut::app::register_bench_command(app);
  mtcut::app::hid::register_hid_command(app);
  mtcut::app::register_view_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; usage errors exit 2, like most tools.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const mtcut::engine::InputError& e) {
    std::cerr << "mtcut: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "mtcut: out of memory\n";
    return 1;
  }
  return 0;
}
