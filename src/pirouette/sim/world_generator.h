#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "pirouette/camera/camera_model.h"
#include "pirouette/sim/world_spec.h"

namespace pirouette::sim {

// The kinds of world `pirouette world generate` draws (SPEC.md, "Worlds
// nobody drew by hand"):
//  - rooms: rooms joined by doors just wider than the robot, a few things in each;
//  - maze: corridors one and a half to three robot diameters wide, a random spanning tree;
//  - clutter: one room full of boxes, cylinders, prisms and short walls;
//  - apartment: rooms, doors and furniture at the apartment robot's scale (8-20 m).
// The first three are for the paper's Yujin robot (radius 0.04 m, the
// camera of worlds/yujin.yaml), the apartment for worlds/apartment.yaml's
// robot (radius 0.15 m, worlds/webcam640.yaml).
enum class WorldKind { kRooms, kMaze, kClutter, kApartment };

inline constexpr std::array<WorldKind, 4> kWorldKinds = {
    WorldKind::kRooms, WorldKind::kMaze, WorldKind::kClutter, WorldKind::kApartment};

// "rooms" | "maze" | "clutter" | "apartment", the command line's names.
std::string_view WorldKindName(WorldKind kind);
std::optional<WorldKind> ParseWorldKind(std::string_view name);

// The floor sizes of a kind, metres a side: drawn in [default_min,
// default_max] unless given, and allowed in [min, max].
struct WorldSizeLimits {
  double default_min = 0.0;
  double default_max = 0.0;
  double min = 0.0;
  double max = 0.0;
};
WorldSizeLimits SizeLimitsOf(WorldKind kind);

// The shipped cameras (worlds/yujin.yaml, worlds/webcam640.yaml), written
// inline into generated worlds so that they load from any folder.
camera::CameraModel YujinCamera();
camera::CameraModel Webcam640Camera();

// One draw of a world of `kind` from `seed`: floor `size` (metres, rounded
// to the millimetre; each side within SizeLimitsOf(kind)'s min..max), or a
// size drawn. The same arguments give the same spec on every platform: a
// seeded std::mt19937_64 with distributions of its own (SeededRandom),
// layouts on whole millimetres, angles from a table. Checks nothing of
// reachability: nearly every draw is valid, and the caller
// (tools::GenerateValidWorld) checks each with the evaluator's and draws
// again from a derived seed when one is not. Throws std::invalid_argument
// for a size outside the limits.
WorldSpec GenerateWorld(WorldKind kind, std::uint64_t seed,
                        const std::optional<Eigen::Vector2d>& size = std::nullopt);

}  // namespace pirouette::sim
