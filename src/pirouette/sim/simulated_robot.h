#pragma once

#include <cstdint>
#include <optional>

#include "pirouette/sim/renderer.h"
#include "pirouette/sim/sim_robot.h"
#include "pirouette/sim/world.h"

namespace pirouette::sim {

// The simulated robot of a world, built the one way every command builds it
// (explore in-process, sim-serve over TCP), so that the same world and seed
// give the same frames and motion whichever way it is driven: the renderer's
// noise and floor texture and the robot's odometry noise all seeded with
// `seed`. Holds a reference to the world; renders on the constructing thread.
class SimulatedRobot {
 public:
  // `noise`: the motion error; none: the world file's.
  SimulatedRobot(const sim::World& world, std::uint64_t seed,
                 const std::optional<core::OdometryNoise>& noise = std::nullopt);
  SimulatedRobot(const SimulatedRobot&) = delete;
  SimulatedRobot& operator=(const SimulatedRobot&) = delete;

  sim::SimRobot& robot() { return robot_; }
  // Seconds spent rendering so far.
  double render_s() const { return render_s_; }

 private:
  static sim::RenderOptions RenderOptionsFor(std::uint64_t seed);

  sim::Renderer renderer_;
  double render_s_ = 0.0;
  sim::SimRobot robot_;
};

}  // namespace pirouette::sim
