#include "apps/pirouette/command.h"

namespace pirouette::cli {

// Placeholder, replaced by the eval work.
Command AddEvalCommand(CLI::App& parent) {
  CLI::App* cmd = parent.add_subcommand("eval", "Evaluate a map against a world (not yet).");
  return {cmd, [] {}};
}

}  // namespace pirouette::cli
