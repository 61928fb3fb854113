// mtcut: the command line. Each subcommand lives in its own file and
// registers itself here. Errors a user can cause in an input end as one line
// on stderr (with the advice their hint asks for, in this command line's
// terms) and exit code 1, as does any other fault (the line names the
// command and its inputs then); command-line usage errors exit 2.

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "app/bench_command.h"
#include "app/cut_command.h"
#include "app/hid/hid_command.h"
#include "app/mesh_command.h"
#include "app/mesh_input_options.h"
#include "app/mt_command.h"
#include "app/run_command.h"
#include "app/view/view_command.h"
#include "engine/input_error.h"

namespace {

// "mtcut SUBCOMMAND INPUT...": the command that failed and the inputs it was
// given (its positional arguments), for a fault whose message does not name them.
std::string failed_command(const CLI::App& app) {
  std::string text = "mtcut";
  for (const CLI::App* sub = &app; !sub->get_subcommands().empty();) {
    sub = sub->get_subcommands().front();
    text += " " + sub->get_name();
    for (const CLI::Option* option : sub->get_options())
      if (option->get_positional())
        for (const std::string& value : option->results()) text += " " + value;
  }
  return text;
}

}  // namespace

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
    std::cerr << "mtcut: " << mtcut::app::add_advice(e.what(), e.hint()) << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << failed_command(app) << ": out of memory\n";
    return 1;
  } catch (const std::logic_error& e) {
    std::cerr << failed_command(app) << ": internal error (please report it with the input): " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << failed_command(app) << ": " << e.what() << "\n";
    return 1;
  } catch (...) {
    std::cerr << failed_command(app) << ": an unknown fault\n";
    return 1;
  }
  return 0;
}
