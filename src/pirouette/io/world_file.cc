#include "pirouette/io/world_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "pirouette/core/angle.h"
#include "pirouette/core/polygon.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/map_file.h"
#include "pirouette/io/yaml_fields.h"
#include "pirouette/sim/block_grid.h"

namespace pirouette::io {
namespace {

using io::DescribeNode;
using io::JoinFieldPath;
using io::LineOf;
using io::NumberList;
using io::ReadList;
using io::ReadMap;
using io::ReadNumber;
using io::ReadNumbers;
using io::ReadString;
using io::ScalarKind;
using io::ScalarKindOf;
using io::ThrowInputError;
using io::YamlField;
using io::YamlMap;

// ---------------------------------------------------------------------------
// The world file's values.

constexpr std::string_view kFormat = "pirouette-world/1";

std::string Item(std::size_t i, std::size_t count) {
  return fmt::format("item {} of {}: ", i + 1, count);
}

double ReadPositive(const std::string& file, const YamlField& field) {
  const double value = ReadNumber(file, field);
  if (!(value > 0.0)) ThrowInputError(file, field, fmt::format("must be > 0, got {}", value));
  return value;
}

double ReadNonNegative(const std::string& file, const YamlField& field) {
  const double value = ReadNumber(file, field);
  if (!(value >= 0.0)) ThrowInputError(file, field, fmt::format("must be >= 0, got {}", value));
  return value;
}

double ReadFraction(const std::string& file, const YamlField& field) {
  const double value = ReadNumber(file, field);
  if (!(value >= 0.0 && value <= 1.0)) {
    ThrowInputError(file, field, fmt::format("must lie in [0, 1], got {}", value));
  }
  return value;
}

// [x, y]: a point.
Eigen::Vector2d ReadPoint(const std::string& file, const YamlField& field) {
  const NumberList xy = ReadNumbers(file, field, 2);
  return {xy.values[0], xy.values[1]};
}

// [x, y]: a size, both > 0.
Eigen::Vector2d ReadSize(const std::string& file, const YamlField& field) {
  const NumberList xy = ReadNumbers(file, field, 2);
  for (std::size_t i = 0; i < 2; ++i) {
    if (!(xy.values[i] > 0.0)) {
      ThrowInputError(file, xy.items[i],
                      Item(i, 2) + fmt::format("must be > 0, got {}", xy.values[i]));
    }
  }
  return {xy.values[0], xy.values[1]};
}

// [r, g, b]: whole numbers 0..255.
core::Rgb ReadColour(const std::string& file, const YamlField& field) {
  const std::string what = "a colour [r, g, b] of whole numbers 0..255";
  const std::vector<YamlField> items = ReadList(file, field, what);
  if (items.size() != 3) {
    ThrowInputError(file, field, fmt::format("expected {}, got {} items", what, items.size()));
  }
  std::uint8_t channels[3] = {0, 0, 0};
  for (std::size_t i = 0; i < 3; ++i) {
    const double value = ReadNumber(file, items[i], Item(i, 3));
    if (value != std::floor(value) || value < 0.0 || value > 255.0) {
      ThrowInputError(file, items[i],
                      Item(i, 3) + fmt::format("expected a whole number 0..255, got {}",
                                               items[i].node.Scalar()));
    }
    channels[i] = static_cast<std::uint8_t>(value);
  }
  return {channels[0], channels[1], channels[2]};
}

YamlField Index(const YamlField& item, std::size_t i) {
  return {item.node, fmt::format("{}[{}]", item.path, i), item.line};
}

// ---------------------------------------------------------------------------
// Sections of the file.

sim::Floor ReadFloor(const std::string& file, const YamlField& field) {
  const YamlMap map = ReadMap(file, field, {"size", "colour", "texture"});
  sim::Floor floor;
  floor.size = ReadSize(file, map.Required("size"));
  floor.colour = ReadColour(file, map.Required("colour"));
  if (const auto texture = map.Optional("texture")) floor.texture = ReadFraction(file, *texture);
  return floor;
}

sim::BoundaryWalls ReadWalls(const std::string& file, const YamlField& field) {
  const YamlMap map = ReadMap(file, field, {"height", "thickness", "colour"});
  sim::BoundaryWalls walls;
  walls.height = ReadPositive(file, map.Required("height"));
  walls.thickness = ReadPositive(file, map.Required("thickness"));
  walls.colour = ReadColour(file, map.Required("colour"));
  return walls;
}

// True where the item of `obstacles` is a map whose one key is `chessboard`.
bool IsChessboardItem(const YamlField& field) {
  return field.node.IsMap() && field.node.size() == 1 && field.node.begin()->first.IsScalar() &&
         field.node.begin()->first.Scalar() == "chessboard";
}

// `- chessboard: {centre: [x, y], cols: 9, rows: 6, square: 0.025, yaw: 0}`:
// cols × rows inner corners, at least 2 × 2.
sim::Chessboard ReadChessboard(const std::string& file, const YamlField& field) {
  const YamlMap item(file, field);
  const YamlField board_field = item.Required("chessboard");
  const YamlMap map = ReadMap(file, board_field, {"centre", "cols", "rows", "square", "yaw"});
  sim::Chessboard board;
  board.centre = ReadPoint(file, map.Required("centre"));
  for (const auto& [key, value] :
       {std::pair<const char*, int*>{"cols", &board.cols}, {"rows", &board.rows}}) {
    const YamlField count_field = map.Required(key);
    *value = ReadWholeNumber(file, count_field);
    if (*value < 2 || *value > 100) {
      ThrowInputError(
          file, count_field,
          fmt::format("inner corners of a chessboard: expected 2..100, got {}", *value));
    }
  }
  board.square = ReadPositive(file, map.Required("square"));
  if (const auto yaw = map.Optional("yaw")) board.yaw_rad = core::DegToRad(ReadNumber(file, *yaw));
  return board;
}

bool IsGridItem(const YamlField& field) {
  return field.node.IsMap() && field.node.size() == 1 && field.node.begin()->first.IsScalar() &&
         field.node.begin()->first.Scalar() == "grid";
}

// `- grid: {map: house.yaml, height: 0.25, colour: [200, 200, 200], seal: true}`:
// a map_server map (relative to the world file) stood up as blocks, its
// lower-left corner at the world's (0, 0); sealed once the robot is known.
struct GridItem {
  sim::BlockGrid grid;
  double height;
  core::Rgb colour;
  bool seal;
  std::size_t item;
  int line;
};

GridItem ReadGrid(const std::string& file, const YamlField& field, std::size_t index) {
  namespace fs = std::filesystem;
  const YamlMap item(file, field);
  const YamlField grid_field = item.Required("grid");
  const YamlMap map = ReadMap(file, grid_field, {"map", "height", "colour", "seal"});
  const YamlField map_field = map.Required("map");
  const std::string name = ReadString(file, map_field);
  if (name.empty()) {
    ThrowInputError(file, map_field, "expected a map's yaml file, got an empty string");
  }
  fs::path path(name);
  if (path.is_relative()) path = fs::path(file).parent_path() / path;
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    ThrowInputError(file, map_field, fmt::format("map file '{}' not found", path.string()));
  }
  sim::BlockGrid grid = BlocksOfMap(io::ReadMapServerMap(path.string()));
  const double height = ReadPositive(file, map.Required("height"));
  const core::Rgb colour = ReadColour(file, map.Required("colour"));
  bool seal = false;
  if (const auto seal_field = map.Optional("seal")) {
    if (!seal_field->node.IsScalar() || ScalarKindOf(seal_field->node) != ScalarKind::kBool) {
      ThrowInputError(file, *seal_field,
                      "expected true or false, got " + DescribeNode(seal_field->node));
    }
    const std::string& v = seal_field->node.Scalar();
    seal = v == "true" || v == "True" || v == "TRUE";
  }
  return GridItem{std::move(grid), height, colour, seal, index, field.line};
}

// One item of `obstacles`: a map with one key, its shape.
sim::Solid ReadObstacle(const std::string& file, const YamlField& field) {
  static constexpr std::string_view kShapes[] = {"box", "cylinder", "wall", "prism"};
  const YamlMap item(file, field);
  const std::vector<YamlMap::Key> keys = item.Keys();
  if (keys.size() != 1) {
    std::string names;
    for (const auto& key : keys) names += (names.empty() ? " (" : ", ") + key.name;
    if (!names.empty()) names += ")";
    ThrowInputError(
        file, field,
        fmt::format("an obstacle has exactly one key, its shape (box, cylinder, wall, prism, "
                    "grid or chessboard); "
                    "got {}{}",
                    keys.size(), names));
  }
  const std::string& shape = keys[0].name;
  if (std::find(std::begin(kShapes), std::end(kShapes), shape) == std::end(kShapes)) {
    ThrowInputError(file, keys[0].line, JoinFieldPath(field.path, shape),
                    "unknown shape (expected box, cylinder, wall, prism, grid or chessboard)");
  }
  const YamlField shape_field = item.Required(shape);
  try {
    if (shape == "box") {
      const YamlMap map = ReadMap(file, shape_field, {"centre", "size", "yaw", "height", "colour"});
      const Eigen::Vector2d centre = ReadPoint(file, map.Required("centre"));
      const Eigen::Vector2d size = ReadSize(file, map.Required("size"));
      double yaw_deg = 0.0;
      if (const auto yaw = map.Optional("yaw")) yaw_deg = ReadNumber(file, *yaw);
      const double height = ReadPositive(file, map.Required("height"));
      const core::Rgb colour = ReadColour(file, map.Required("colour"));
      return sim::MakeBox(centre, size, core::DegToRad(yaw_deg), height, colour);
    }
    if (shape == "cylinder") {
      const YamlMap map = ReadMap(file, shape_field, {"centre", "radius", "height", "colour"});
      const Eigen::Vector2d centre = ReadPoint(file, map.Required("centre"));
      const double radius = ReadPositive(file, map.Required("radius"));
      const double height = ReadPositive(file, map.Required("height"));
      const core::Rgb colour = ReadColour(file, map.Required("colour"));
      return sim::MakeCylinder(centre, radius, height, colour);
    }
    if (shape == "wall") {
      const YamlMap map =
          ReadMap(file, shape_field, {"from", "to", "thickness", "height", "colour"});
      const Eigen::Vector2d from = ReadPoint(file, map.Required("from"));
      const YamlField to_field = map.Required("to");
      const Eigen::Vector2d to = ReadPoint(file, to_field);
      if (from == to) {
        ThrowInputError(file, to_field, "the same point as `from`: the wall has no length");
      }
      const double thickness = ReadPositive(file, map.Required("thickness"));
      const double height = ReadPositive(file, map.Required("height"));
      const core::Rgb colour = ReadColour(file, map.Required("colour"));
      return sim::MakeWall(from, to, thickness, height, colour);
    }
    // prism
    const YamlMap map = ReadMap(file, shape_field, {"points", "height", "colour"});
    const YamlField points_field = map.Required("points");
    const std::vector<YamlField> items = ReadList(file, points_field, "a list of points [x, y]");
    std::vector<Eigen::Vector2d> points;
    for (std::size_t i = 0; i < items.size(); ++i) {
      points.push_back(ReadPoint(file, Index(items[i], i)));
    }
    // A closed ring (the last point repeating the first) is the same polygon.
    if (points.size() > 3 && points.front() == points.back()) points.pop_back();
    if (points.size() < 3) {
      ThrowInputError(file, points_field,
                      fmt::format("a prism needs at least 3 points, got {}", points.size()));
    }
    // The points must make a simple polygon with an area.
    if (const auto problem = core::PolygonProblem(points)) {
      ThrowInputError(file, points_field, *problem);
    }
    const double height = ReadPositive(file, map.Required("height"));
    const core::Rgb colour = ReadColour(file, map.Required("colour"));
    return sim::MakePrism(std::move(points), height, colour);
  } catch (const std::invalid_argument& e) {
    // The builders' own checks; the ones above should leave none to fail.
    ThrowInputError(file, shape_field, e.what());
  }
}

sim::Light ReadLight(const std::string& file, const YamlField& field) {
  const YamlMap map = ReadMap(file, field, {"ambient", "direction", "intensity"});
  sim::Light light;
  if (const auto ambient = map.Optional("ambient")) light.ambient = ReadFraction(file, *ambient);
  if (const auto direction = map.Optional("direction")) {
    const NumberList xyz = ReadNumbers(file, *direction, 3);
    if (!(xyz.values[2] < 0.0)) {
      ThrowInputError(
          file, *direction,
          fmt::format("the light must travel downward (z < 0), got z = {}", xyz.values[2]));
    }
    light.direction = {xyz.values[0], xyz.values[1], xyz.values[2]};
  }
  if (const auto intensity = map.Optional("intensity")) {
    light.intensity = ReadFraction(file, *intensity);
  }
  return light;
}

// A camera file's name (relative to the world file's folder) or the camera's fields inline.
camera::CameraModel ReadCamera(const std::string& file, const YamlField& field) {
  namespace fs = std::filesystem;
  if (field.node.IsMap()) return io::ParseCameraNode(field.node, file, field.path);
  if (!field.node.IsScalar() || ScalarKindOf(field.node) != ScalarKind::kString) {
    ThrowInputError(file, field,
                    "expected a camera file's name or the camera's fields (a map), got " +
                        DescribeNode(field.node));
  }
  const std::string& name = field.node.Scalar();
  if (name.empty()) {
    ThrowInputError(file, field, "expected a camera file's name, got an empty string");
  }
  fs::path path(name);
  if (path.is_relative()) path = fs::path(file).parent_path() / path;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) {
    ThrowInputError(file, field, fmt::format("camera file '{}' not found", path.string()));
  }
  if (fs::is_directory(status)) {
    ThrowInputError(file, field, fmt::format("camera file '{}' is a folder", path.string()));
  }
  return io::LoadCameraFile(path.string());
}

core::OdometryNoise ReadOdometryNoise(const std::string& file, const YamlField& field) {
  const YamlMap map =
      ReadMap(file, field, {"translation", "rotation", "translation_bias", "rotation_bias"});
  core::OdometryNoise noise;
  if (const auto value = map.Optional("translation")) {
    noise.translation = ReadNonNegative(file, *value);
  }
  if (const auto value = map.Optional("rotation")) noise.rotation = ReadNonNegative(file, *value);
  const auto read_bias = [&](const YamlField& value) {
    const double bias = ReadNumber(file, value);
    if (!(std::abs(bias) <= 0.5)) {
      ThrowInputError(file, value, fmt::format("must lie in [-0.5, 0.5], got {}", bias));
    }
    return bias;
  };
  if (const auto value = map.Optional("translation_bias")) {
    noise.translation_bias = read_bias(*value);
  }
  if (const auto value = map.Optional("rotation_bias")) noise.rotation_bias = read_bias(*value);
  return noise;
}

std::string_view ShapeName(sim::Solid::Kind kind) {
  switch (kind) {
    case sim::Solid::Kind::kBox:
      return "box";
    case sim::Solid::Kind::kCylinder:
      return "cylinder";
    case sim::Solid::Kind::kWall:
      return "wall";
    case sim::Solid::Kind::kPrism:
      return "prism";
    case sim::Solid::Kind::kGridBlock:
      return "grid";
    case sim::Solid::Kind::kBoundaryWall:
      break;
  }
  return "wall";
}

// The world's obstacles and chessboards, with where each obstacle stands in
// the file (its index in the list and its line), for messages.
struct Obstacles {
  std::vector<sim::Solid> solids;
  std::vector<std::size_t> items;
  std::vector<int> lines;
  std::vector<sim::Chessboard> chessboards;
  std::vector<GridItem> grids;
};

// Limits that keep a world within the machine's memory: the renderer's mesh,
// the ray caster's index and the truth grow with the solids, the evaluation's
// truth with the floor. The largest world shipped or generated has a few
// thousand solids (a map_server twin merged into boxes) on a 30 m floor.
constexpr std::size_t kMaxObstacleItems = 100000;
constexpr std::size_t kMaxSolids = 200000;
constexpr double kMaxFloorSideM = 1000.0;

Obstacles ReadObstacles(const std::string& file, const YamlMap& map) {
  Obstacles out;
  if (const auto field = map.Optional("obstacles")) {
    const std::vector<YamlField> items = ReadList(file, *field, "a list of obstacles");
    if (items.size() > kMaxObstacleItems) {
      ThrowInputError(file, *field,
                      fmt::format("{} obstacles; a world may have at most {}", items.size(),
                                  kMaxObstacleItems));
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (IsChessboardItem(items[i])) {
        out.chessboards.push_back(ReadChessboard(file, Index(items[i], i)));
        continue;
      }
      if (IsGridItem(items[i])) {
        out.grids.push_back(ReadGrid(file, Index(items[i], i), i));
        continue;
      }
      out.solids.push_back(ReadObstacle(file, Index(items[i], i)));
      out.items.push_back(i);
      out.lines.push_back(items[i].line);
    }
  }
  return out;
}

// robot: start [x, y, heading°], radius, camera, odometry_noise (optional);
// with the start's field, for messages.
struct RobotField {
  sim::RobotSpec spec;
  YamlField start_field;
};

RobotField ReadRobot(const std::string& file, const YamlField& field) {
  const YamlMap robot = ReadMap(file, field, {"start", "radius", "camera", "odometry_noise"});
  const YamlField start_field = robot.Required("start");
  const NumberList start = ReadNumbers(file, start_field, 3);
  const core::Pose2 world_T_start(start.values[0], start.values[1],
                                  core::DegToRad(start.values[2]));
  const double radius = ReadPositive(file, robot.Required("radius"));
  camera::CameraModel camera = ReadCamera(file, robot.Required("camera"));
  core::OdometryNoise noise;
  if (const auto noise_field = robot.Optional("odometry_noise")) {
    noise = ReadOdometryNoise(file, *noise_field);
  }
  return {{world_T_start, radius, std::move(camera), noise}, start_field};
}

// Throws naming the start unless the robot's disc there lies on the floor and
// touches no obstacle, saying which it leaves or overlaps.
void CheckStartFits(const std::string& file, const sim::World& world, const Obstacles& obstacles,
                    const YamlField& start_field) {
  const Eigen::Vector2d& centre = world.robot().start.translation();
  const double radius = world.robot().radius;
  if (world.DiscFits(centre, radius)) return;
  const std::string disc =
      fmt::format("the robot's disc (radius {}) at ({}, {})", radius, centre.x(), centre.y());
  const Eigen::Vector2d& size = world.floor().size;
  const double to_edge =
      std::min({centre.x(), centre.y(), size.x() - centre.x(), size.y() - centre.y()});
  if (!(to_edge > radius)) {
    ThrowInputError(
        file, start_field,
        fmt::format("{} does not lie on the floor [0, {}] × [0, {}]", disc, size.x(), size.y()));
  }
  for (std::size_t i = 0; i < obstacles.solids.size(); ++i) {
    if (!(obstacles.solids[i].SignedDistance(centre) > radius)) {
      ThrowInputError(
          file, start_field,
          fmt::format("{} overlaps obstacles[{}] (the {} on line {})", disc, obstacles.items[i],
                      ShapeName(obstacles.solids[i].kind), obstacles.lines[i]));
    }
  }
  ThrowInputError(file, start_field, disc + " touches something occupied");
}

sim::World ParseWorld(const YAML::Node& node, const std::string& file) {
  const YamlField root{node, "", LineOf(node)};
  const YamlMap map(file, root);
  // The format first: a file of another kind gets that said, not a list of unknown keys.
  const YamlField format_field = map.Required("format");
  const std::string format = ReadString(file, format_field);
  if (format != kFormat) {
    ThrowInputError(file, format_field, fmt::format("expected '{}', got '{}'", kFormat, format));
  }
  map.AllowOnly({"format", "name", "floor", "walls", "obstacles", "light", "robot"});

  const YamlField name_field = map.Required("name");
  std::string name = ReadString(file, name_field);
  if (name.empty()) ThrowInputError(file, name_field, "must not be empty");
  const YamlField floor_field = map.Required("floor");
  const sim::Floor floor = ReadFloor(file, floor_field);
  if (floor.size.maxCoeff() > kMaxFloorSideM) {
    ThrowInputError(file, floor_field,
                    fmt::format("floor.size: {} x {} m; a side may be at most {} m", floor.size.x(),
                                floor.size.y(), kMaxFloorSideM));
  }
  std::optional<sim::BoundaryWalls> walls;
  if (const auto field = map.Optional("walls")) walls = ReadWalls(file, *field);
  Obstacles obstacles = ReadObstacles(file, map);
  sim::Light light;
  if (const auto field = map.Optional("light")) light = ReadLight(file, *field);
  RobotField robot = ReadRobot(file, map.Required("robot"));
  for (GridItem& grid : obstacles.grids) {
    if (grid.seal) {
      grid.grid =
          sim::SealUnreachable(grid.grid, robot.spec.radius, robot.spec.start.translation());
    }
    for (sim::Solid& solid : sim::BlockGridSolids(grid.grid, grid.height, grid.colour)) {
      obstacles.solids.push_back(std::move(solid));
      obstacles.items.push_back(grid.item);
      obstacles.lines.push_back(grid.line);
    }
    if (obstacles.solids.size() > kMaxSolids) {
      ThrowInputError(file, grid.line, fmt::format("obstacles[{}]", grid.item),
                      fmt::format("the map makes more than {} blocks with the obstacles before "
                                  "it; crop the map or coarsen its cells",
                                  kMaxSolids));
    }
  }

  std::optional<sim::World> world;
  try {
    world.emplace(std::move(name), floor, walls, obstacles.solids, light, std::move(robot.spec),
                  std::move(obstacles.chessboards));
  } catch (const std::invalid_argument& e) {
    ThrowInputError(file, 0, "", e.what());
  }
  CheckStartFits(file, *world, obstacles, robot.start_field);
  return std::move(*world);
}

}  // namespace

sim::BlockGrid BlocksOfMap(const MapServerMap& map) {
  const core::GridGeometry& g = map.geometry;
  sim::BlockGrid grid{
      core::GridGeometry(g.resolution(), Eigen::Vector2d::Zero(), g.width(), g.height()), {}};
  grid.solid.reserve(map.cells.size());
  for (const std::int8_t v : map.cells) grid.solid.push_back(v == kMapFree ? 0 : 1);
  return grid;
}

sim::World LoadWorldFile(const std::string& path) {
  return ParseWorld(io::LoadYamlFile(path), path);
}

sim::World ParseWorldText(const std::string& text, const std::string& path) {
  return ParseWorld(io::ParseYaml(text, path), path);
}

}  // namespace pirouette::io
