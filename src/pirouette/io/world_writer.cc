#include "pirouette/io/world_writer.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <variant>

#include <fmt/format.h>

#include "pirouette/io/camera_file.h"

namespace pirouette::io {
namespace {

// The shortest decimal that reads back as `value` (+0 for -0).
std::string Number(double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("WorldFileText: {} is not a finite number", value));
  }
  return fmt::format("{}", value + 0.0);
}

std::string Point(const Eigen::Vector2d& p) {
  return fmt::format("[{}, {}]", Number(p.x()), Number(p.y()));
}

std::string Colour(const core::Rgb& c) { return fmt::format("[{}, {}, {}]", c.r, c.g, c.b); }

// A YAML scalar that reads back as `text`, whatever it holds.
std::string Quoted(const std::string& text) {
  YAML::Emitter out;
  out << YAML::DoubleQuoted << text;
  return out.c_str();
}

// `- shape: {...}`, one line.
std::string ObstacleLine(const sim::ObstacleSpec& o) {
  const std::string tail =
      fmt::format("height: {}, colour: {}}}", Number(o.height), Colour(o.colour));
  if (const auto* box = std::get_if<sim::BoxSpec>(&o.shape)) {
    const std::string yaw =
        box->yaw_deg == 0.0 ? "" : fmt::format("yaw: {}, ", Number(box->yaw_deg));
    return fmt::format("  - box: {{centre: {}, size: {}, {}{}", Point(box->centre),
                       Point(box->size), yaw, tail);
  }
  if (const auto* cylinder = std::get_if<sim::CylinderSpec>(&o.shape)) {
    return fmt::format("  - cylinder: {{centre: {}, radius: {}, {}", Point(cylinder->centre),
                       Number(cylinder->radius), tail);
  }
  if (const auto* wall = std::get_if<sim::WallSpec>(&o.shape)) {
    return fmt::format("  - wall: {{from: {}, to: {}, thickness: {}, {}", Point(wall->from),
                       Point(wall->to), Number(wall->thickness), tail);
  }
  std::string points;
  for (const Eigen::Vector2d& p : std::get<sim::PrismSpec>(o.shape).points) {
    points += (points.empty() ? "" : ", ") + Point(p);
  }
  return fmt::format("  - prism: {{points: [{}], {}", points, tail);
}

// The camera's own file text, indented under `robot.camera`.
std::string InlineCamera(const camera::CameraModel& camera) {
  std::istringstream lines(CameraFileText(camera));
  std::string out;
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty()) out += "    " + line + "\n";
  }
  return out;
}

std::string RobotText(const sim::RobotFileSpec& robot) {
  std::string out = "robot:\n";
  out += fmt::format("  start: [{}, {}, {}]\n", Number(robot.start.x()), Number(robot.start.y()),
                     Number(robot.start_heading_deg));
  out += fmt::format("  radius: {}\n", Number(robot.radius));
  out += "  camera:\n" + InlineCamera(robot.camera);
  const core::OdometryNoise& n = robot.odometry_noise;
  if (n.translation != 0.0 || n.rotation != 0.0 || n.translation_bias != 0.0 ||
      n.rotation_bias != 0.0) {
    out += "  odometry_noise:\n";
    out += fmt::format("    translation: {}\n", Number(n.translation));
    out += fmt::format("    rotation: {}\n", Number(n.rotation));
    out += fmt::format("    translation_bias: {}\n", Number(n.translation_bias));
    out += fmt::format("    rotation_bias: {}\n", Number(n.rotation_bias));
  }
  return out;
}

}  // namespace

std::string WorldFileText(const sim::WorldSpec& spec) { return WorldFileText(spec, {}); }

std::string WorldFileText(const sim::WorldSpec& spec, const std::vector<GridFileSpec>& grids) {
  std::string out;
  std::istringstream comment(spec.comment);
  for (std::string line; std::getline(comment, line);) {
    out += line.empty() ? "#\n" : "# " + line + "\n";
  }
  out += "format: pirouette-world/1\n";
  out += "name: " + Quoted(spec.name) + "\n";
  out += "floor:\n";
  out += "  size: " + Point(spec.floor.size) + "\n";
  out += "  colour: " + Colour(spec.floor.colour) + "\n";
  out += "  texture: " + Number(spec.floor.texture) + "\n";
  if (spec.walls) {
    out += "walls:\n";
    out += "  height: " + Number(spec.walls->height) + "\n";
    out += "  thickness: " + Number(spec.walls->thickness) + "\n";
    out += "  colour: " + Colour(spec.walls->colour) + "\n";
  }
  if (!spec.obstacles.empty() || !grids.empty()) {
    out += "obstacles:\n";
    for (const GridFileSpec& g : grids) {
      out += fmt::format("  - grid: {{map: {}, height: {}, colour: {}{}}}\n", Quoted(g.map),
                         Number(g.height), Colour(g.colour), g.seal ? ", seal: true" : "");
    }
    for (const sim::ObstacleSpec& o : spec.obstacles) out += ObstacleLine(o) + "\n";
  }
  const sim::Light& light = spec.light;
  out += "light:\n";
  out += "  ambient: " + Number(light.ambient) + "\n";
  out += fmt::format("  direction: [{}, {}, {}]\n", Number(light.direction.x()),
                     Number(light.direction.y()), Number(light.direction.z()));
  out += "  intensity: " + Number(light.intensity) + "\n";
  return out + RobotText(spec.robot);
}

}  // namespace pirouette::io
