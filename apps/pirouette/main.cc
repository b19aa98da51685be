// The command line of pirouette: parsing, messages and exit codes (SPEC.md).
// Each subcommand lives in its own <name>_command.cc; the work is in app/.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <vector>

#include "apps/pirouette/command.h"
#include "pirouette/core/input_error.h"

int main(int argc, char** argv) {
  using namespace pirouette::cli;  // NOLINT(google-build-using-namespace)
  CLI::App app{
      "pirouette: a robot with one cheap camera maps an unknown floor by itself.\n"
      "It spins on the spot, finds where the floor ends in each picture, turns that\n"
      "edge into ranges, and builds an occupancy grid (Taylor, Geva & Boles, 2005).\n"
      "Exit codes: 0 done, 1 the run failed, 2 bad usage or bad input.\n"};
  app.require_subcommand(1);
  app.failure_message(CLI::FailureMessage::help);

  const std::vector<Command> commands = {
      AddRenderCommand(app),      AddIpmReportCommand(app),
      AddRopCommand(app),         AddPerceptionEvalCommand(app),
      AddSegmentCommand(app),     AddSegmentEvalCommand(app),
      AddEvalCommand(app),        AddExploreCommand(app),
      AddExploreEvalCommand(app), AddMapCommand(app),
      AddCalibrateCommand(app),   AddCaptureCommand(app),
      AddSimServeCommand(app),    AddPlacesCommand(app),
      AddLocateCommand(app),      AddWorldCommand(app),
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitBadInput;
  }

  try {
    for (const Command& command : commands) {
      if (command.app->parsed()) command.run();
    }
    return kExitOk;
  } catch (const pirouette::core::InputError& e) {
    std::fprintf(stderr, "pirouette: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pirouette: %s\n", e.what());
    return kExitFailed;
  }
}
