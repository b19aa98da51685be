#pragma once

#include <thread>

#include "pirouette/robot/robot_server.h"

namespace pirouette::testing {

// Serves `server` on a thread for the life of the object; stops it and joins
// the thread at the end.
class Serving {
 public:
  explicit Serving(robot::RobotServer& server)
      : server_(server), thread_([&server] { server.Serve(); }) {}
  ~Serving() {
    server_.Stop();
    thread_.join();
  }
  Serving(const Serving&) = delete;
  Serving& operator=(const Serving&) = delete;

 private:
  robot::RobotServer& server_;
  std::thread thread_;
};

}  // namespace pirouette::testing
