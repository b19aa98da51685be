#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/odometry_noise.h"
#include "pirouette/core/rgb.h"
#include "pirouette/sim/world.h"

namespace pirouette::sim {

// A world as its file gives it (SPEC.md, `pirouette-world/1`): each obstacle
// by its shape's own parameters, angles in degrees, where sim::World holds
// footprints. What a world file is written from (io::WorldFileText) and what
// the world generator draws.

struct BoxSpec {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d size = Eigen::Vector2d::Zero();  // along the yaw direction, across it
  double yaw_deg = 0.0;
};

struct CylinderSpec {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0;
};

struct WallSpec {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  double thickness = 0.0;
};

struct PrismSpec {
  std::vector<Eigen::Vector2d> points;  // a simple polygon, either orientation, not closed
};

struct ObstacleSpec {
  std::variant<BoxSpec, CylinderSpec, WallSpec, PrismSpec> shape;
  double height = 0.0;
  core::Rgb colour;
};

struct RobotFileSpec {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  double start_heading_deg = 0.0;
  double radius = 0.0;
  camera::CameraModel camera;
  core::OdometryNoise odometry_noise;  // all zero: none (the file leaves it out)
};

struct WorldSpec {
  std::string name;
  // Written as comment lines at the head of the file (one a line); may be empty.
  std::string comment;
  Floor floor;
  std::optional<BoundaryWalls> walls;
  std::vector<ObstacleSpec> obstacles;
  Light light;
  RobotFileSpec robot;
};

// The world the spec describes, built as io::LoadWorldFile builds the same
// world from its file (the same builders on the same numbers: a spec and its
// file give identical worlds). Throws std::invalid_argument where
// sim::World's constructor does.
World BuildWorld(const WorldSpec& spec);

}  // namespace pirouette::sim
