#include "pirouette/tools/world_from_map.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "pirouette/core/input_error.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/world_file.h"
#include "pirouette/io/world_writer.h"
#include "pirouette/sim/block_grid.h"
#include "pirouette/sim/world_generator.h"

namespace pirouette::tools {
namespace {

namespace fs = std::filesystem;

// The apartment's look (worlds/apartment.yaml): a blue-grey carpet and white
// walls, which the light shades to a grey close to a grey floor.
constexpr core::Rgb kFloorColour{95, 110, 135};
constexpr core::Rgb kBlockColour{235, 230, 220};
constexpr double kFloorTexture = 0.05;

// The map's path as the world file names it: relative to the world file's
// folder where both are on one tree, else absolute.
std::string MapPathFromWorld(const std::string& map_path, const std::string& out_path) {
  std::error_code error;
  const fs::path map = fs::absolute(map_path, error);
  if (error) return map_path;
  fs::path folder = fs::absolute(out_path, error).parent_path();
  if (error) return map.string();
  const fs::path relative = map.lexically_relative(folder.lexically_normal());
  if (relative.empty()) return map.lexically_normal().string();
  return relative.string();
}

}  // namespace

WorldFromMapResult RunWorldFromMap(const WorldFromMapRequest& request) {
  if (!(request.radius_m > 0.0)) {
    throw core::InputError("--radius", 0, "", fmt::format("must be > 0, got {}", request.radius_m));
  }
  if (!(request.height_m > 0.0)) {
    throw core::InputError("--height", 0, "", fmt::format("must be > 0, got {}", request.height_m));
  }
  WorldFromMapResult result{"", io::ReadMapServerMap(request.map_path)};
  const core::GridGeometry& g = result.map.geometry;
  const sim::BlockGrid grid = io::BlocksOfMap(result.map);
  result.free_cells = grid.solid.size() - grid.SolidCount();

  double heading_deg = 0.0;
  if (request.start) {
    result.start_map = request.start->head<2>();
    result.start_world = result.start_map - g.origin();
    heading_deg = request.start->z();
  } else {
    const std::optional<Eigen::Vector2d> chosen = sim::ChooseGridStart(grid, request.radius_m);
    if (!chosen) {
      throw core::InputError(request.map_path, 0, "",
                             fmt::format("the robot's disc (radius {} m) fits nowhere among the "
                                         "map's {} free cells",
                                         request.radius_m, result.free_cells));
    }
    result.start_world = *chosen;
    result.start_map = *chosen + g.origin();
  }
  const sim::BlockGrid sealed =
      request.seal ? sim::SealUnreachable(grid, request.radius_m, result.start_world) : grid;
  result.sealed_cells = sealed.SolidCount() - grid.SolidCount();
  std::vector<sim::Solid> solids = sim::BlockGridSolids(sealed, request.height_m, kBlockColour);
  result.boxes = solids.size();

  const camera::CameraModel camera =
      request.camera_path ? io::LoadCameraFile(*request.camera_path) : sim::Webcam640Camera();
  std::string name = fs::path(request.map_path).stem().string();
  if (name.empty()) name = "from-map";
  sim::WorldSpec spec{
      .name = name,
      .comment = fmt::format(
          "Made by `pirouette world from-map --map {}` from a {} x {} map at {} m a cell.\n"
          "The map's frame moved so that its origin ({}, {}) is this world's (0, 0):\n"
          "a point (x, y) of the map is (x - {}, y - {}) here. Every cell map_server\n"
          "does not serve as free (0) is a block{}.",
          request.map_path, g.width(), g.height(), g.resolution(), g.origin().x(), g.origin().y(),
          g.origin().x(), g.origin().y(),
          request.seal ? "; gaps narrower than the robot are sealed (seal: true)" : ""),
      .floor = {Eigen::Vector2d(g.width() * g.resolution(), g.height() * g.resolution()),
                kFloorColour, kFloorTexture},
      .walls = std::nullopt,
      .obstacles = {},
      .light = sim::Light{},
      .robot = {.start = result.start_world,
                .start_heading_deg = heading_deg,
                .radius = request.radius_m,
                .camera = camera,
                .odometry_noise = {}}};

  // The world LoadWorldFile will build, to check the start before writing.
  const sim::World world(
      spec.name, spec.floor, std::nullopt, solids, spec.light,
      sim::RobotSpec{core::Pose2(result.start_world.x(), result.start_world.y(), 0.0),
                     request.radius_m,
                     camera,
                     {}});
  if (!world.DiscFits(result.start_world, request.radius_m)) {
    throw core::InputError(
        request.start ? "--start" : request.map_path, 0, "",
        fmt::format("the robot's disc (radius {} m) at ({}, {}) in the map's frame {}",
                    request.radius_m, result.start_map.x(), result.start_map.y(),
                    world.OnFloor(result.start_world) ? "touches a block (an occupied or "
                                                        "unknown cell, or one sealed)"
                                                      : "lies off the map"));
  }
  result.text = io::WorldFileText(
      spec, {io::GridFileSpec{MapPathFromWorld(request.map_path, request.out_path),
                              request.height_m, kBlockColour, request.seal}});
  io::WriteFileAtomically(request.out_path, result.text);
  return result;
}

}  // namespace pirouette::tools
