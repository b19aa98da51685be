#pragma once

#include <atomic>

namespace pirouette::cli {

// Installs the handlers of SIGINT and SIGTERM for a long command: the first
// signal sets the returned flag (the command finishes the step it is on,
// writes what it has and returns); a second one ends the program at once.
const std::atomic<bool>* StopOnInterrupt();

}  // namespace pirouette::cli
