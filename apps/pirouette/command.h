#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <string>

namespace pirouette::cli {

// Exit codes (SPEC.md): 0 done, 1 the run failed, 2 bad usage or bad input.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;

// One subcommand: its options are added to the app by its Add function, which
// returns the action to run when the subcommand was given. The action throws
// core::InputError for bad input (exit 2) and anything else for a failed run
// (exit 1); main turns both into a message on standard error.
struct Command {
  CLI::App* app = nullptr;
  std::function<void()> run;
};

Command AddRenderCommand(CLI::App& parent);
Command AddIpmReportCommand(CLI::App& parent);
Command AddRopCommand(CLI::App& parent);
Command AddPerceptionEvalCommand(CLI::App& parent);
Command AddSegmentCommand(CLI::App& parent);
Command AddSegmentEvalCommand(CLI::App& parent);
Command AddEvalCommand(CLI::App& parent);
Command AddExploreCommand(CLI::App& parent);
Command AddExploreEvalCommand(CLI::App& parent);
Command AddMapCommand(CLI::App& parent);
Command AddCalibrateCommand(CLI::App& parent);
Command AddCaptureCommand(CLI::App& parent);
Command AddSimServeCommand(CLI::App& parent);
Command AddPlacesCommand(CLI::App& parent);
Command AddLocateCommand(CLI::App& parent);
// `world` and its own subcommands (world_command.cc): generate.
Command AddWorldCommand(CLI::App& parent);

}  // namespace pirouette::cli
