#include "pirouette/sim/world_spec.h"

#include <utility>

#include "pirouette/core/angle.h"
#include "pirouette/core/pose2.h"

namespace pirouette::sim {
namespace {

// The solid of one obstacle, by the builder the world file's reader uses for its shape.
Solid BuildSolid(const ObstacleSpec& obstacle) {
  const double h = obstacle.height;
  const core::Rgb c = obstacle.colour;
  if (const auto* box = std::get_if<BoxSpec>(&obstacle.shape)) {
    return MakeBox(box->centre, box->size, core::DegToRad(box->yaw_deg), h, c);
  }
  if (const auto* cylinder = std::get_if<CylinderSpec>(&obstacle.shape)) {
    return MakeCylinder(cylinder->centre, cylinder->radius, h, c);
  }
  if (const auto* wall = std::get_if<WallSpec>(&obstacle.shape)) {
    return MakeWall(wall->from, wall->to, wall->thickness, h, c);
  }
  return MakePrism(std::get<PrismSpec>(obstacle.shape).points, h, c);
}

}  // namespace

World BuildWorld(const WorldSpec& spec) {
  std::vector<Solid> solids;
  solids.reserve(spec.obstacles.size());
  for (const ObstacleSpec& obstacle : spec.obstacles) solids.push_back(BuildSolid(obstacle));
  const RobotFileSpec& robot = spec.robot;
  RobotSpec robot_spec{
      core::Pose2(robot.start.x(), robot.start.y(), core::DegToRad(robot.start_heading_deg)),
      robot.radius, robot.camera, robot.odometry_noise};
  return {spec.name, spec.floor, spec.walls, std::move(solids), spec.light, std::move(robot_spec)};
}

}  // namespace pirouette::sim
