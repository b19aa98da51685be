#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/pirouette/command.h"
#include "apps/pirouette/interrupt.h"
#include "apps/pirouette/options.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/world_file.h"
#include "pirouette/robot/robot_error.h"
#include "pirouette/robot/robot_server.h"
#include "pirouette/robot/ros2/dds_participant.h"
#include "pirouette/sim/faulty_robot.h"
#include "pirouette/sim/robot_fault.h"
#include "pirouette/sim/simulated_robot.h"
#include "pirouette/tools/ros2_sim_server.h"
#include "pirouette/tools/sim_view.h"

namespace pirouette::cli {
namespace {

struct SimServeRequest {
  std::string world_path;
  std::string host = "127.0.0.1";
  int port = 5555;
  std::uint64_t seed = 1;
  std::string port_file;
  std::vector<double> odometry_noise;  // {} or {translation, rotation}
  std::vector<double> odometry_bias;   // {} or {translation, rotation}
  bool ros2 = false;                   // serve as a ROS 2 robot over DDS instead
  Ros2Choices ros2_choices;
  ViewChoices view;
  std::string fault;  // --fault KIND[@N], for testing
};

// The live view of --view, if asked for: it listens before the robot does.
std::unique_ptr<tools::SimView> MakeSimView(const SimServeRequest& request,
                                            const sim::World& world) {
  const std::optional<run::LiveViewOptions> options =
      LiveViewOf(request.view, request.ros2_choices.ros_namespace);
  if (!options) return nullptr;
  auto view = std::make_unique<tools::SimView>(world, *options);
  AnnounceView("sim-serve", false)(view->endpoint());
  return view;
}

// The simulator as a ROS 2 robot over DDS (tools::Ros2SimServer).
void ServeRos2(const SimServeRequest& request, const sim::World& world,
               const core::OdometryNoise& noise, const sim::RobotFault& fault) {
  Ros2Choices choices = request.ros2_choices;
  choices.publish = true;
  const run::Ros2PublishOptions dds = *Ros2PublishOf(choices);
  tools::Ros2SimServerOptions options;
  options.domain_id = dds.domain_id;
  options.network = dds.network;
  options.ros_namespace = dds.ros_namespace;
  options.stop_requested = StopOnInterrupt();
  options.fault = fault;
  std::unique_ptr<tools::SimView> view = MakeSimView(request, world);
  if (view) {
    options.on_render = [&view](const core::ImageRgb8& image, const core::Pose2& pose) {
      view->OnFrame(image, pose);
    };
  }
  try {
    tools::Ros2SimServer server(world, request.seed, noise, options);
    std::fprintf(stderr, "sim-serve: a ROS 2 robot on %s (world %s, seed %llu); Ctrl-C stops\n",
                 server.Describe().c_str(), request.world_path.c_str(),
                 static_cast<unsigned long long>(request.seed));
    server.Serve();
    std::fprintf(stderr, "sim-serve: %.1f s of simulated time, %ld steps, %d frames published\n",
                 server.robot().time_s(), server.steps(), server.frames_published());
  } catch (const robot::ros2::DdsError& e) {
    throw std::runtime_error(std::string("sim-serve: DDS: ") + e.what());
  }
  std::fprintf(stderr, "sim-serve: stopped\n");
}

// The simulated robot exactly as the in-process explorer builds it
// (sim::SimulatedRobot), so that a run through sim-serve sees the same frames
// and the same motion as one in-process with the same world and seed.
void Serve(const SimServeRequest& request) {
  const sim::World world = io::LoadWorldFile(request.world_path);
  const auto pair = [](const std::vector<double>& v) {
    return v.size() == 2 ? std::optional<std::array<double, 2>>({v[0], v[1]}) : std::nullopt;
  };
  const core::OdometryNoise noise = core::OdometryNoiseWith(
      world.robot().odometry_noise, pair(request.odometry_noise), pair(request.odometry_bias));
  core::CheckOdometryNoise(noise);
  const sim::RobotFault fault =
      request.fault.empty() ? sim::RobotFault{} : sim::ParseRobotFault(request.fault);
  if (request.ros2) {
    if (fault.kind == sim::RobotFault::Kind::kHalfFrame) {
      throw core::InputError("--fault", 0, "", "half-frame is a fault of TCP only, not --ros2");
    }
    ServeRos2(request, world, noise, fault);
    return;
  }
  sim::SimulatedRobot simulated(world, request.seed, noise);
  std::unique_ptr<tools::SimView> view = MakeSimView(request, world);
  tools::WatchedRobot watched(simulated.robot(), [&](const robot::Frame& frame) {
    if (view) view->OnFrame(frame.image, simulated.robot().TruePose());
  });
  sim::FaultyRobot faulty(watched, fault);
  robot::Robot& robot = faulty;

  robot::RobotServerOptions options;
  options.host = request.host;
  options.port = request.port;
  options.stop_requested = StopOnInterrupt();
  options.log = [](const std::string& message) {
    std::fprintf(stderr, "sim-serve: %s\n", message.c_str());
  };
  if (fault.kind == sim::RobotFault::Kind::kHalfFrame) options.half_frame_from = fault.from;
  robot::RobotServer server(robot, options);
  if (!request.port_file.empty()) {
    io::WriteFileAtomically(request.port_file, std::to_string(server.port()) + "\n");
  }
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
      "tcp://HOST:PORT` drives, and what a real robot's adapter imitates; or with --ros2 as "
      "a ROS 2 robot over DDS, for `explore --robot ros2` and ROS 2's own tools.\n"
      "  example: pirouette sim-serve --world worlds/soccer_field.yaml --port 5555\n"
      "  example: pirouette sim-serve --world worlds/soccer_field.yaml --ros2");
  AddWorldOption(cmd, request->world_path)->required();
  cmd->add_option("--port", request->port, "TCP port to listen on; 0: any free port")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  cmd->add_option("--host", request->host,
                  "address to listen on (0.0.0.0: every interface; the protocol has no "
                  "authentication)")
      ->capture_default_str();
  AddSeedOption(cmd, request->seed, "the simulator's noise (camera and odometry)");
  AddOdometryOptions(cmd, request->odometry_noise, request->odometry_bias);
  cmd->add_option("--port-file", request->port_file,
                  "once listening, write the port to this file (atomically), for scripts");
  cmd->add_flag("--ros2", request->ros2,
                "serve a ROS 2 robot over DDS instead, in the domain ROS_DOMAIN_ID names: obeys "
                "cmd_vel in simulated time, publishes odom, tf (odom->base_link), clock, and "
                "image_raw with camera_info while at rest; what `explore --robot ros2` drives "
                "(docs/ros2.md). Loopback only unless --ros-network");
  cmd->add_option("--ros-namespace", request->ros2_choices.ros_namespace,
                  "with --ros2: the namespace of the topics, e.g. robot1 (default: none)");
  cmd->add_option("--ros-network", request->ros2_choices.network,
                  "with --ros2: let DDS leave this machine (an interface such as eth0 or its "
                  "IPv4 address, or auto); default loopback only");
  AddViewOptions(cmd, request->view, false);
  cmd->add_option("--fault", request->fault,
                  "for testing pirouette, not for use: the robot misbehaves from its Nth "
                  "request on (TCP; 1: the first TURN, MOVE or CAPTURE) or N simulated seconds "
                  "after the first cmd_vel on (--ros2), default 1; KIND one of " +
                      sim::RobotFaultKinds() +
                      " (half-frame: TCP only); what explore does with each: "
                      "docs/robot-protocol.md and docs/ros2.md")
      ->type_name("KIND[@N]");
  return {cmd, [request] {
            if (!request->ros2 && (!request->ros2_choices.ros_namespace.empty() ||
                                   !request->ros2_choices.network.empty())) {
              throw core::InputError("--ros-namespace", 0, "", "needs --ros2");
            }
            try {
              Serve(*request);
            } catch (const robot::RobotError& e) {
              throw std::runtime_error(std::string("sim-serve: ") + e.what());
            }
          }};
}

}  // namespace pirouette::cli
