// texsynth: example-based texture synthesis from the command line.
// Parses flags, runs one subcommand, and turns every error into one clear line and an exit code:
// 1 for bad input or failed output, 2 for bad usage or parameters.
#include <cstdio>
#include <vector>

#include "cli_common.h"
#include "parse_errors.h"
#include "texsynth/core/error.h"
#include "texsynth/core/output_batch.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/temporary_files.h"

using namespace texsynth;

int main(int argc, char** argv) {
  CLI::App app{
      "texsynth: example-based texture synthesis for images, solids and surfaces.\n"
      "Run 'texsynth demo' for a tour on built-in defaults, or 'texsynth SUBCOMMAND --help'."};
  app.set_help_all_flag("--help-all", "Help for every subcommand");
  app.footer("Cache: exemplar analyses and candidate triples are kept in " + cli::defaultCacheDirectory() +
             "\n($TEXSYNTH_CACHE, else $XDG_CACHE_HOME/texsynth, else ~/.cache/texsynth); deleting it is safe.");
  app.require_subcommand(1);
  cli::GlobalOptions globals;
  cli::addGlobalOptions(app, globals);

  std::vector<cli::Command> commands = {
      cli::registerDemoCommand(app, globals),    cli::registerEvalCommand(app, globals),
      cli::registerRenderCommand(app, globals),  cli::registerInfoCommand(app, globals),
      cli::registerImageCommand(app, globals),   cli::registerSolidCommand(app, globals),
      cli::registerFieldCommand(app, globals),   cli::registerVectorizeCommand(app, globals),
      cli::registerEditCommand(app, globals),    cli::registerSurfaceCommand(app, globals),
      cli::registerAnimateCommand(app, globals), cli::registerStudioCommand(app, globals),
  };
  // Global flags may also follow the subcommand name.
  for (auto& command : commands) {
    command.parser->fallthrough();
    command.parser->footer("Global flags (before or after the subcommand): --seed N, --threads N, --quiet, --json");
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    std::fprintf(stderr, "texsynth: %s\n", cli::describeParseError(e, app, arguments).c_str());
    return 2;
  }

  try {
    ThreadLimit limit(globals.threads);
    removeTemporariesOnSignals();
    for (auto& command : commands)
      if (command.parser->parsed()) {
        cli::checkFileArguments(*command.parser);  // every destination, before any work
        OutputBatch outputs;                       // all of the run's outputs, or none
        cli::runCommand(command);                  // errors name the user's flags and files
        SignalsHeld held;  // a signal now waits: the outputs go into place and are reported, or neither
        outputs.commit();
        cli::sayCommitted();
      }
    return 0;
  } catch (const ParameterError& e) {
    std::fprintf(stderr, "texsynth: bad parameter %s\n", e.what());
    return 2;
  } catch (const Cancelled&) {
    std::fprintf(stderr, "texsynth: cancelled\n");
    return 130;
  } catch (const InternalError& e) {
    std::fprintf(stderr, "texsynth: %s (this is a bug in texsynth)\n", e.what());
    return 1;
  } catch (const Error& e) {
    std::fprintf(stderr, "texsynth: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "texsynth: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "texsynth: unexpected error: %s\n", e.what());
    return 1;
  }
}
