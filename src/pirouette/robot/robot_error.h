#pragma once

#include <stdexcept>

namespace pirouette::robot {

// A robot failed: it could not be reached, stopped answering, dropped the
// connection, answered something that is not the protocol, or refused a
// command. The message says which robot (HOST:PORT), which command and what
// happened, so that it can be shown to the user as it is. A run that gets one
// has lost its robot: it stops and keeps what it has mapped.
class RobotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace pirouette::robot
