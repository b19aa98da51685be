#include "pirouette/sim/world_generator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "pirouette/core/angle.h"
#include "pirouette/sim/maze_plan.h"
#include "pirouette/sim/obstacle_placer.h"
#include "pirouette/sim/room_plan.h"
#include "pirouette/sim/seeded_random.h"
#include "pirouette/sim/world_style.h"

namespace pirouette::sim {
namespace {

// The narrowest gap left open anywhere (between furniture, in a doorway, a
// corridor), in robot radii: the diameter and one radius to spare, the
// least the coarse planning grid keeps open whatever its alignment
// (explore/coarse_grid.h). Narrower gaps would test the planner's grid, not
// the map.
constexpr double kPassRadii = 3.0;
// Doors "just wider than the robot": kPassRadii to kDoorMaxRadii wide, or
// up to kWideDoorMaxRadii for kWideDoorChance of them.
constexpr double kDoorMaxRadii = 4.0;
constexpr double kWideDoorMaxRadii = 6.0;
constexpr double kWideDoorChance = 0.25;
// Corridors one and a half to three diameters wide.
constexpr double kCorridorMaxRadii = 6.0;
// The start: at least this many radii from anything, where such a place is found.
constexpr double kStartClearanceRadii = 2.0;
constexpr int kStartTries = 2000;
// Tries at placing one piece of furniture before it is left out.
constexpr int kPlacementTries = 30;
// Furniture: a quarter boxes against a wall (kCornerChance of them pushed
// into a corner), the rest free-standing boxes, cylinders, prisms and short
// walls in these shares.
constexpr double kAgainstWallChance = 0.25;
constexpr double kCornerChance = 0.35;
constexpr double kBoxShare = 0.35;
constexpr double kCylinderShare = 0.30;
constexpr double kPrismShare = 0.25;  // (the rest: short walls)

// The sizes of the furniture of a kind, millimetres.
struct FurnitureScale {
  Mm against_length_min = 0;  // a box against a wall: along the wall
  Mm against_length_max = 0;
  Mm against_depth_min = 0;
  Mm against_depth_max = 0;
  Mm box_min = 0;  // each side of a free-standing box
  Mm box_max = 0;
  Mm cylinder_min = 0;  // radius
  Mm cylinder_max = 0;
  Mm prism_min = 0;  // the radius of the ellipse its corners lie on
  Mm prism_max = 0;
  Mm wall_min = 0;  // a free-standing wall's length
  Mm wall_max = 0;
  Mm wall_thickness_min = 0;
  Mm wall_thickness_max = 0;
};

// The robot a kind is drawn for and the sizes around it.
struct KindScale {
  double radius_m = 0.0;
  camera::CameraModel camera;
  StyleScale style;
  FurnitureScale furniture;
  Mm min_room = 0;  // the shortest side of a room
  // How many rooms the floor is split into (as many as fit): one for each
  // room_area_min..max m² of floor, within rooms_min..rooms_max.
  double room_area_min_m2 = 0.0;
  double room_area_max_m2 = 0.0;
  int rooms_min = 0;
  int rooms_max = 0;
  int furniture_min = 0;  // a room's pieces
  int furniture_max = 0;
};

// The paper's robot for rooms, maze and clutter (walls 1-3 cm thick, things
// 3-20 cm high, rooms from 0.55 m); the apartment robot for the apartment
// (walls 8-16 cm, furniture 0.3-1.2 m high, rooms from 2.5 m).
KindScale ScaleOf(WorldKind kind) {
  if (kind == WorldKind::kApartment) {
    return {.radius_m = 0.15,
            .camera = Webcam640Camera(),
            .style = {.camera_height_m = 0.30,
                      .tall_wall_min_m = 0.5,
                      .tall_wall_max_m = 2.5,
                      .wall_thickness_min_mm = 80,
                      .wall_thickness_max_mm = 160,
                      .obstacle_height_min_m = 0.3,
                      .obstacle_height_max_m = 1.2},
            .furniture = {.against_length_min = 500,
                          .against_length_max = 2200,
                          .against_depth_min = 350,
                          .against_depth_max = 1000,
                          .box_min = 300,
                          .box_max = 1400,
                          .cylinder_min = 150,
                          .cylinder_max = 600,
                          .prism_min = 250,
                          .prism_max = 800,
                          .wall_min = 800,
                          .wall_max = 2000,
                          .wall_thickness_min = 80,
                          .wall_thickness_max = 120},
            .min_room = 2500,
            .room_area_min_m2 = 10.0,
            .room_area_max_m2 = 18.0,
            .rooms_min = 3,
            .rooms_max = 16,
            .furniture_min = 1,
            .furniture_max = 5};
  }
  return {.radius_m = 0.04,
          .camera = YujinCamera(),
          .style = {.camera_height_m = 0.11,
                    .tall_wall_min_m = 0.13,
                    .tall_wall_max_m = 0.25,
                    .wall_thickness_min_mm = 10,
                    .wall_thickness_max_mm = 30,
                    .obstacle_height_min_m = 0.03,
                    .obstacle_height_max_m = 0.2},
          .furniture = {.against_length_min = 60,
                        .against_length_max = 350,
                        .against_depth_min = 40,
                        .against_depth_max = 150,
                        .box_min = 30,
                        .box_max = 200,
                        .cylinder_min = 20,
                        .cylinder_max = 90,
                        .prism_min = 40,
                        .prism_max = 130,
                        .wall_min = 100,
                        .wall_max = 400,
                        .wall_thickness_min = 10,
                        .wall_thickness_max = 30},
          .min_room = 550,
          .room_area_min_m2 = 0.8,
          .room_area_max_m2 = 2.0,
          .rooms_min = 2,
          .rooms_max = 24,
          .furniture_min = 0,
          .furniture_max = 3};
}

double Metres(Mm mm) { return static_cast<double>(mm) / 1000.0; }
Eigen::Vector2d Metres(Mm x, Mm y) { return {Metres(x), Metres(y)}; }
Mm RadiiMm(const KindScale& s, double radii) { return std::llround(s.radius_m * radii * 1000.0); }
// An even number of millimetres in [lo, hi] (so that its half is whole).
Mm EvenBetween(SeededRandom& random, Mm lo, Mm hi) { return 2 * random.Between(lo / 2, hi / 2); }

// An obstacle of `shape`, its height and colour still to be drawn.
ObstacleSpec Shaped(decltype(ObstacleSpec::shape) shape) { return {std::move(shape), 0.0, {}}; }

ObstacleSpec WallOf(const MmSegment& s, Mm thickness, const WorldStyle& style) {
  return {WallSpec{Metres(s.x0, s.y0), Metres(s.x1, s.y1), Metres(thickness)}, style.walls.height,
          style.inner_wall_colour};
}

// A convex prism: 3 to 6 corners at distinct multiples of 30° on an ellipse
// of radii `radius` and up to half that, turned by a multiple of 15°, at
// tenths of a millimetre. Nullopt where rounding left it not strictly convex.
std::optional<PrismSpec> DrawPrism(SeededRandom& random, Mm cx, Mm cy, Mm radius) {
  std::vector<int> steps = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  const int n = static_cast<int>(random.Between(3, 6));
  for (int i = 0; i < n; ++i) std::swap(steps[i], steps[i + random.Below(12 - i)]);
  steps.resize(n);
  std::sort(steps.begin(), steps.end());
  for (int i = 0; i < n; ++i) {  // every turn between corners under 180°
    if ((steps[(i + 1) % n] - steps[i] + 12) % 12 >= 6) return std::nullopt;
  }
  const auto rx = static_cast<double>(radius);
  const double ry = rx * random.Uniform(0.5, 1.0);
  const Eigen::Vector2d turn = YawDirection(static_cast<int>(random.Below(24)));
  PrismSpec prism;
  for (const int step : steps) {
    const Eigen::Vector2d on = YawDirection(2 * step);
    const Eigen::Vector2d p(rx * on.x(), ry * on.y());  // millimetres from the centre
    const Eigen::Vector2d q(turn.x() * p.x() - turn.y() * p.y(),
                            turn.y() * p.x() + turn.x() * p.y());
    prism.points.emplace_back(static_cast<double>(cx * 10 + std::llround(q.x() * 10.0)) / 10000.0,
                              static_cast<double>(cy * 10 + std::llround(q.y() * 10.0)) / 10000.0);
  }
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = prism.points[i];
    const Eigen::Vector2d& b = prism.points[(i + 1) % n];
    const Eigen::Vector2d& c = prism.points[(i + 2) % n];
    if (!((b - a).x() * (c - b).y() - (b - a).y() * (c - b).x() > 1e-8)) return std::nullopt;
  }
  return prism;
}

// A free-standing piece in the room `r`: a box, cylinder, prism or short wall.
std::optional<ObstacleSpec> DrawFreeStanding(SeededRandom& random, const MmRect& r,
                                             const FurnitureScale& f) {
  const Mm cx = random.Between(r.x0, r.x1);
  const Mm cy = random.Between(r.y0, r.y1);
  const double pick = random.Unit();
  if (pick < kBoxShare) {
    const Mm sx = random.Between(f.box_min, f.box_max);
    const Mm sy = random.Between(f.box_min, f.box_max);
    return Shaped(BoxSpec{Metres(cx, cy), Metres(sx, sy), 15.0 * random.Between(0, 23)});
  }
  if (pick < kBoxShare + kCylinderShare) {
    return Shaped(
        CylinderSpec{Metres(cx, cy), Metres(random.Between(f.cylinder_min, f.cylinder_max))});
  }
  if (pick < kBoxShare + kCylinderShare + kPrismShare) {
    auto prism = DrawPrism(random, cx, cy, random.Between(f.prism_min, f.prism_max));
    if (!prism) return std::nullopt;
    return Shaped(std::move(*prism));
  }
  const Eigen::Vector2d along = YawDirection(static_cast<int>(random.Below(12)));
  const double half = static_cast<double>(random.Between(f.wall_min, f.wall_max)) / 2.0;
  const auto end = [&](double sign) {
    return Metres(cx + std::llround(sign * half * along.x()),
                  cy + std::llround(sign * half * along.y()));
  };
  return Shaped(WallSpec{end(-1.0), end(1.0),
                         Metres(EvenBetween(random, f.wall_thickness_min, f.wall_thickness_max))});
}

// A box standing flush against one side of the room `r` (or in a corner).
std::optional<ObstacleSpec> DrawAgainstWall(SeededRandom& random, const MmRect& r,
                                            const FurnitureScale& f) {
  const int side = static_cast<int>(random.Below(4));  // bottom, top, left, right
  const Mm length = EvenBetween(random, f.against_length_min, f.against_length_max);
  const Mm depth = EvenBetween(random, f.against_depth_min, f.against_depth_max);
  const bool along_x = side < 2;
  const Mm lo = along_x ? r.x0 : r.y0;
  const Mm hi = along_x ? r.x1 : r.y1;
  if (length > hi - lo || depth > (along_x ? r.y1 - r.y0 : r.x1 - r.x0)) return std::nullopt;
  Mm at = random.Between(lo + length / 2, hi - length / 2);
  if (random.Chance(kCornerChance)) at = random.Chance(0.5) ? lo + length / 2 : hi - length / 2;
  const Mm across = side == 0   ? r.y0 + depth / 2
                    : side == 1 ? r.y1 - depth / 2
                    : side == 2 ? r.x0 + depth / 2
                                : r.x1 - depth / 2;
  const Eigen::Vector2d centre = along_x ? Metres(at, across) : Metres(across, at);
  const Eigen::Vector2d size = along_x ? Metres(length, depth) : Metres(depth, length);
  return Shaped(BoxSpec{centre, size, 0.0});
}

// Adds `count` pieces of furniture to the room `r`; returns how many found a place.
int Furnish(SeededRandom& random, const MmRect& r, int count, double gap, const KindScale& scale,
            const WorldStyle& style, ObstaclePlacer& placer) {
  int added = 0;
  for (int piece = 0; piece < count; ++piece) {
    const bool against_wall = random.Chance(kAgainstWallChance);
    for (int attempt = 0; attempt < kPlacementTries; ++attempt) {
      std::optional<ObstacleSpec> obstacle = against_wall
                                                 ? DrawAgainstWall(random, r, scale.furniture)
                                                 : DrawFreeStanding(random, r, scale.furniture);
      if (!obstacle) continue;
      obstacle->height = DrawObstacleHeight(random, scale.style);
      obstacle->colour = DrawObstacleColour(random, style);
      if (placer.TryAdd(*obstacle, gap, against_wall)) {
        ++added;
        break;
      }
    }
  }
  return added;
}

// Where the robot starts: a place at least kStartClearanceRadii from anything
// (the most open of kStartTries places drawn, where none is).
Eigen::Vector2d DrawStart(SeededRandom& random, Mm width, Mm height, const ObstaclePlacer& placer,
                          const KindScale& scale) {
  Eigen::Vector2d start = Metres(width / 2, height / 2);
  double best = -1.0;
  for (int attempt = 0; attempt < kStartTries; ++attempt) {
    const Mm x = random.Between(0, width);
    const Mm y = random.Between(0, height);
    const Eigen::Vector2d p = Metres(x, y);
    const double clearance = placer.Clearance(p);
    if (clearance > best) {
      best = clearance;
      start = p;
    }
    if (best >= kStartClearanceRadii * scale.radius_m) break;
  }
  return start;
}

// The floor's size in millimetres: `size` rounded, or drawn (to the
// centimetre for the small kinds, the decimetre for the apartment).
std::pair<Mm, Mm> FloorSize(SeededRandom& random, WorldKind kind,
                            const std::optional<Eigen::Vector2d>& size) {
  const WorldSizeLimits limits = SizeLimitsOf(kind);
  const Mm step = kind == WorldKind::kApartment ? 100 : 10;
  const auto draw = [&] {
    return step * random.Between(std::llround(limits.default_min * 1000.0) / step,
                                 std::llround(limits.default_max * 1000.0) / step);
  };
  const Mm x = draw();
  const Mm y = draw();
  if (!size) return {x, y};
  for (const double side : {size->x(), size->y()}) {
    if (!(side >= limits.min && side <= limits.max)) {
      throw std::invalid_argument(fmt::format("a {} world's sides must lie in [{}, {}] m, got {}",
                                              WorldKindName(kind), limits.min, limits.max, side));
    }
  }
  return {std::llround(size->x() * 1000.0), std::llround(size->y() * 1000.0)};
}

// What every kind ends with: the spec around the placed obstacles, the start
// (`start`, or drawn) heading a multiple of 15°.
WorldSpec Assemble(SeededRandom& random, WorldKind kind, Mm width, Mm height,
                   const KindScale& scale, const WorldStyle& style, const ObstaclePlacer& placer,
                   const std::string& layout_words,
                   const std::optional<Eigen::Vector2d>& start = std::nullopt) {
  RobotFileSpec robot{start ? *start : DrawStart(random, width, height, placer, scale),
                      0.0,
                      scale.radius_m,
                      scale.camera,
                      {}};
  robot.start_heading_deg = 15.0 * static_cast<double>(random.Between(0, 23));
  return {std::string(WorldKindName(kind)),
          layout_words + "\n" + style.description,
          Floor{Metres(width, height), style.floor.colour, style.floor.texture},
          style.walls,
          placer.obstacles(),
          style.light,
          std::move(robot)};
}

// "0.12-0.24" metres, or one length where all are the same.
std::string RangeText(const std::vector<Mm>& lengths) {
  const auto [lo, hi] = std::minmax_element(lengths.begin(), lengths.end());
  if (lo == lengths.end()) return "none";
  return *lo == *hi ? fmt::format("{}", Metres(*lo))
                    : fmt::format("{}-{}", Metres(*lo), Metres(*hi));
}

// "1 door", "3 doors".
std::string Count(std::size_t n, std::string_view one, std::string_view many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

// rooms and apartment: a room plan, furnished.
WorldSpec GenerateRooms(SeededRandom& random, WorldKind kind, Mm width, Mm height,
                        const KindScale& scale, const WorldStyle& style) {
  const Mm t = std::llround(style.walls.thickness * 1000.0);
  const double area_m2 = Metres(width) * Metres(height);
  const double area_per_room = random.Uniform(scale.room_area_min_m2, scale.room_area_max_m2);
  const int rooms =
      std::clamp(static_cast<int>(area_m2 / area_per_room), scale.rooms_min, scale.rooms_max);
  const Mm pass = RadiiMm(scale, kPassRadii);
  const RoomPlanOptions options{width,
                                height,
                                t,
                                scale.min_room,
                                rooms,
                                pass,
                                RadiiMm(scale, kDoorMaxRadii),
                                RadiiMm(scale, kWideDoorMaxRadii),
                                kWideDoorChance,
                                t + RadiiMm(scale, 1.0),
                                RadiiMm(scale, 1.0),
                                pass};
  const RoomPlan plan = DrawRoomPlan(random, options);
  ObstaclePlacer placer(Metres(width, height));
  for (const MmSegment& wall : plan.walls) placer.AddWall(WallOf(wall, t, style));
  for (const MmRect& d : plan.doorways) placer.AddKeepOut(Metres(d.x0, d.y0), Metres(d.x1, d.y1));
  int furniture = 0;
  for (const MmRect& room : plan.rooms) {
    const int count = static_cast<int>(random.Between(scale.furniture_min, scale.furniture_max));
    furniture += Furnish(random, room, count, Metres(pass), scale, style, placer);
  }
  const std::string doors =
      plan.door_widths.empty()
          ? "no doors"
          : fmt::format("{} {} m wide", Count(plan.door_widths.size(), "door", "doors"),
                        RangeText(plan.door_widths));
  return Assemble(
      random, kind, width, height, scale, style, placer,
      fmt::format("{}: {}, {}, walls {} m thick; {} at least {} m apart", WorldKindName(kind),
                  Count(plan.rooms.size(), "room", "rooms"), doors, Metres(t),
                  Count(furniture, "piece of furniture", "pieces of furniture"), Metres(pass)));
}

WorldSpec GenerateMaze(SeededRandom& random, Mm width, Mm height, const KindScale& scale,
                       const WorldStyle& style) {
  const Mm t = std::llround(style.walls.thickness * 1000.0);
  const MazePlan plan = DrawMazePlan(
      random, {width, height, t, RadiiMm(scale, kPassRadii), RadiiMm(scale, kCorridorMaxRadii)});
  ObstaclePlacer placer(Metres(width, height));
  for (const MmSegment& wall : plan.walls) placer.AddWall(WallOf(wall, t, style));
  std::vector<Mm> widths = plan.columns;
  widths.insert(widths.end(), plan.rows.begin(), plan.rows.end());
  // The start: a cell's centre (to the millimetre), the middle of a corridor.
  const MmRect& cell = plan.cells[random.Below(plan.cells.size())];
  return Assemble(random, WorldKind::kMaze, width, height, scale, style, placer,
                  fmt::format("maze: {} × {} cells, corridors {} m wide, walls {} m thick",
                              plan.columns.size(), plan.rows.size(), RangeText(widths), Metres(t)),
                  Metres((cell.x0 + cell.x1) / 2, (cell.y0 + cell.y1) / 2));
}

WorldSpec GenerateClutter(SeededRandom& random, Mm width, Mm height, const KindScale& scale,
                          const WorldStyle& style) {
  // A crowd: 4 to 8 things a square metre (as many as find a place), as tight as the robot
  // passes or a little wider.
  const double area_m2 = Metres(width) * Metres(height);
  const int count = std::clamp(static_cast<int>(area_m2 * random.Uniform(4.0, 8.0)), 6, 50);
  const Mm gap = random.Between(RadiiMm(scale, kPassRadii), RadiiMm(scale, 1.5 * kPassRadii));
  ObstaclePlacer placer(Metres(width, height));
  const int added =
      Furnish(random, {0, 0, width, height}, count, Metres(gap), scale, style, placer);
  return Assemble(random, WorldKind::kClutter, width, height, scale, style, placer,
                  fmt::format("clutter: {} at least {} m apart",
                              Count(added, "obstacle", "obstacles"), Metres(gap)));
}

}  // namespace

std::string_view WorldKindName(WorldKind kind) {
  switch (kind) {
    case WorldKind::kRooms:
      return "rooms";
    case WorldKind::kMaze:
      return "maze";
    case WorldKind::kClutter:
      return "clutter";
    case WorldKind::kApartment:
      break;
  }
  return "apartment";
}

std::optional<WorldKind> ParseWorldKind(std::string_view name) {
  for (const WorldKind kind : kWorldKinds) {
    if (WorldKindName(kind) == name) return kind;
  }
  return std::nullopt;
}

WorldSizeLimits SizeLimitsOf(WorldKind kind) {
  switch (kind) {
    case WorldKind::kRooms:
      return {1.5, 3.0, 1.0, 8.0};
    case WorldKind::kMaze:
      return {1.5, 3.0, 0.5, 8.0};
    case WorldKind::kClutter:
      return {1.5, 2.5, 0.5, 8.0};
    case WorldKind::kApartment:
      break;
  }
  return {8.0, 20.0, 4.0, 30.0};
}

camera::CameraModel YujinCamera() {
  return camera::CameraModel("yujin", 320, 240, {277.128129211, 277.128129211, 159.5, 119.5},
                             {-0.20, 0.05, 0.0, 0.0, 0.0}, {0.11, core::DegToRad(30.0), 0.03},
                             {{0.35, 0.30, 0.40}});
}

camera::CameraModel Webcam640Camera() {
  return camera::CameraModel("webcam640", 640, 480, {457.007362, 457.007362, 319.5, 239.5},
                             {-0.08, 0.012, 0.0, 0.0, 0.0}, {0.30, core::DegToRad(28.0), 0.10},
                             {{0.15, 0.12, 0.18}});
}

WorldSpec GenerateWorld(WorldKind kind, std::uint64_t seed,
                        const std::optional<Eigen::Vector2d>& size) {
  // The kind is drawn into the seed: the kinds' worlds of one seed are unlike.
  SeededRandom random(
      SplitMix64(seed ^ (0x9E3779B97F4A7C15ull * (static_cast<std::uint64_t>(kind) + 1))));
  const auto [width, height] = FloorSize(random, kind, size);
  const KindScale scale = ScaleOf(kind);
  const WorldStyle style = DrawStyle(random, scale.style);
  switch (kind) {
    case WorldKind::kMaze:
      return GenerateMaze(random, width, height, scale, style);
    case WorldKind::kClutter:
      return GenerateClutter(random, width, height, scale, style);
    case WorldKind::kRooms:
    case WorldKind::kApartment:
      break;
  }
  return GenerateRooms(random, kind, width, height, scale, style);
}

}  // namespace pirouette::sim
