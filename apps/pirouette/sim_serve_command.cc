#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "apps/pirouette/command.h"
#include "apps/pirouette/interrupt.h"
#include "pirouette/app/simulated_robot.h"
#include "pirouette/robot/robot_error.h"
#include "pirouette/robot/robot_server.h"
#include "pirouette/sim/world_file.h"

namespace pirouette::cli {
namespace {

struct SimServeRequest {
  std::string world_path;
  std::string host = "127.0.0.1";
  int port = 5555;
  std::uint64_t seed = 1;
  std::string port_file;
};

// Writes the port and a newline to `path` atomically (a temporary name, then
// a rename), so that a script polling for the file never reads half of it.
void WritePortFile(const std::string& path, int port) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << port << '\n';
    if (!out.flush()) throw std::runtime_error("cannot write the port file " + temporary);
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    throw std::runtime_error("cannot write the port file " + path + ": " + error.message());
  }
}

// The simulated robot exactly as the in-process explorer builds it
// (app::SimulatedRobot), so that a run through sim-serve sees the same frames
// and the same motion as one in-process with the same world and seed.
void Serve(const SimServeRequest& request) {
  const sim::World world = sim::LoadWorldFile(request.world_path);
  app::SimulatedRobot simulated(world, request.seed);
  robot::Robot& robot = simulated.robot();

  robot::RobotServerOptions options;
  options.host = request.host;
  options.port = request.port;
  options.stop_requested = StopOnInterrupt();
  options.log = [](const std::string& message) {
    std::fprintf(stderr, "sim-serve: %s\n", message.c_str());
  };
  robot::RobotServer server(robot, options);
  if (!request.port_file.empty()) WritePortFile(request.port_file, server.port());
  std::fprintf(stderr, "sim-serve: listening on %s (world %s, seed %llu); Ctrl-C stops\n",
               server.address().c_str(), request.world_path.c_str(),
               static_cast<unsigned long long>(request.seed));
  server.Serve();
  std::fprintf(stderr, "sim-serve: stopped\n");
}

}  // namespace

Command AddSimServeCommand(CLI::App& parent) {
  auto request = std::make_shared<SimServeRequest>();
  CLI::App* cmd = parent.add_subcommand(
      "sim-serve",
      "Serve the simulated robot of a world over TCP with pirouette's robot line protocol "
      "(docs/robot-protocol.md), one client at a time, until Ctrl-C: what `explore --robot "
      "tcp://HOST:PORT` drives, and what a real robot's adapter imitates.\n"
      "  example: pirouette sim-serve --world worlds/soccer_field.yaml --port 5555");
  cmd->add_option("--world", request->world_path, "world file (pirouette-world/1)")->required();
  cmd->add_option("--port", request->port, "TCP port to listen on; 0: any free port")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  cmd->add_option("--host", request->host,
                  "address to listen on (0.0.0.0: every interface; the protocol has no "
                  "authentication)")
      ->capture_default_str();
  cmd->add_option("--seed", request->seed, "seed of the simulator's noise (camera and odometry)")
      ->capture_default_str();
  cmd->add_option("--port-file", request->port_file,
                  "once listening, write the port to this file (atomically), for scripts");
  return {cmd, [request] {
            try {
              Serve(*request);
            } catch (const robot::RobotError& e) {
              throw std::runtime_error(std::string("sim-serve: ") + e.what());
            }
          }};
}

}  // namespace pirouette::cli
