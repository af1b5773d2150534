// SPDX-License-Identifier: GPL-3.0-or-later
// elastica: fair triangle meshes with the discrete elastica flow (Yoshizawa & Belyaev 2002).
// Exit codes: 0 success, 1 the work failed (message on stderr), 2 bad command line. On SIGINT
// (Ctrl-C), SIGTERM or SIGHUP the file being written is deleted and the process dies of the
// signal (a shell reports 128 + its number: 130 for Ctrl-C); existing files are never touched.
#include "commands.h"
#include "help_format.h"

#include <elastica/errors.h>
#include <elastica/io/atomic_file.h>

#include <iostream>

int main(int argc, char** argv) {
  elastica::io::installInterruptHandlers("elastica");
  CLI::App app{"elastica: fair triangle meshes with the discrete elastica flow\n"
               "(Yoshizawa & Belyaev, Fair Triangle Mesh Generation with Discrete Elastica, GMP 2002)"};
  app.formatter(std::make_shared<elastica::cli::HelpFormatter>());  // subcommands inherit it
  app.require_subcommand(1);
  app.set_version_flag("--version", "elastica 0.1.0");
  elastica::cli::addBatchCommand(app);
  elastica::cli::addCurvatureCommand(app);
  elastica::cli::addFairCommand(app);
  elastica::cli::addFillCommand(app);
  elastica::cli::addGenerateCommand(app);
  elastica::cli::addRunCommand(app);
  elastica::cli::addSubdivideCommand(app);

  try {
    app.parse(argc, argv);  // runs the chosen subcommand's callback
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    std::vector<std::string> extras = app.remaining();
    for (const CLI::App* sub : app.get_subcommands())
      for (const std::string& r : sub->remaining()) extras.push_back(r);
    std::cerr << "elastica: " << e.what() << elastica::cli::optionSuggestion(app, extras)
              << "\n(run 'elastica --help' or 'elastica COMMAND --help')\n";
    return 2;
  } catch (const CLI::ParseError& e) {
    std::cerr << "elastica: " << elastica::cli::readableParseError(e.what()) << "\n(run 'elastica --help' or 'elastica COMMAND --help')\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "elastica: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "elastica: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
