#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/odometry_noise.h"
#include "pirouette/core/pose2.h"
#include "pirouette/core/rgb.h"

namespace pirouette::sim {

// The floor is the rectangle [0, size.x] × [0, size.y] at z = 0.
// A point this near a solid (metres) lies on its face, and so in it: a
// solid is closed. Far above the rounding of a face's distance (~1e-17 m on
// a floor of metres), far below any cell. Without it, a point on a face was
// in the solid or not by that rounding: on a 1 cm grid whose centres fell on
// both faces of a 1 cm wall (a generated maze's wall along a whole
// centimetre), the wall was in the truth of eval or not.
inline constexpr double kOnFaceM = 1e-9;

struct Floor {
  Eigen::Vector2d size = Eigen::Vector2d::Zero();
  core::Rgb colour;
  double texture = 0.0;  // 0..1, amplitude of fine colour noise
};

// The optional walls around the floor's rectangle, standing outside it.
struct BoundaryWalls {
  double height = 0.0;
  double thickness = 0.0;
  core::Rgb colour;
};

struct Light {
  double ambient = 0.45;                         // 0..1
  Eigen::Vector3d direction = {0.3, 0.2, -1.0};  // the way the light travels (not normalised)
  double intensity = 0.6;                        // 0..1
};

struct Circle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0;
};

// Every obstacle and wall is a vertical prism standing on the floor: a
// footprint extruded from z = 0 to `height`.
struct Solid {
  enum class Kind { kBox, kCylinder, kWall, kPrism, kBoundaryWall, kGridBlock };

  Kind kind = Kind::kBox;
  // The footprint as a simple polygon, counter-clockwise. For a cylinder, the
  // regular kCylinderSides-gon inscribed in its circle, used for rendering;
  // `circle` is the exact footprint, used for geometry.
  std::vector<Eigen::Vector2d> footprint;
  std::optional<Circle> circle;  // set for cylinders only
  double height = 0.0;
  core::Rgb colour;

  // The distance from p to the footprint: positive outside, negative inside
  // (exact for polygons and circles).
  double SignedDistance(const Eigen::Vector2d& p) const;
};

inline constexpr int kCylinderSides = 64;

// A printed calibration chessboard lying flat on the floor: `cols` × `rows`
// inner corners (OpenCV's patternSize), so (cols + 1) × (rows + 1) squares
// of side `square`, the corner square at its lower left (-x, -y in the board's
// frame) black, inside a white margin one square wide. `cols` run along the
// board's yaw direction. It is paper thin: only the renderer draws it; the
// robot drives over it, and it is no part of the occupancy ground truth.
struct Chessboard {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // the centre of the inner corners' grid
  int cols = 0;
  int rows = 0;
  double square = 0.0;  // metres
  double yaw_rad = 0.0;
  core::Rgb dark{20, 20, 20};
  core::Rgb light{235, 235, 235};

  // The corner (col, row) of the inner grid, col in [0, cols), row in [0, rows), on the floor.
  Eigen::Vector2d InnerCorner(int col, int row) const;
};

struct RobotSpec {
  core::Pose2 start;  // world_T_robot at the start
  double radius = 0.0;
  camera::CameraModel camera;
  core::OdometryNoise odometry_noise;
};

// A world: the floor, what stands on it, the light and the robot. The
// ground truth that the simulator renders and that maps are judged against.
class World {
 public:
  World(std::string name, Floor floor, std::optional<BoundaryWalls> walls,
        std::vector<Solid> obstacles, Light light, RobotSpec robot,
        std::vector<Chessboard> chessboards = {});

  const std::string& name() const { return name_; }
  const Floor& floor() const { return floor_; }
  const std::optional<BoundaryWalls>& walls() const { return walls_; }
  const std::vector<Solid>& obstacles() const { return obstacles_; }
  // The obstacles and the four boundary walls (if any): all that is drawn.
  const std::vector<Solid>& solids() const { return solids_; }
  // The chessboards on the floor: drawn, but not obstacles (see Chessboard).
  const std::vector<Chessboard>& chessboards() const { return chessboards_; }
  const Light& light() const { return light_; }
  const RobotSpec& robot() const { return robot_; }

  bool OnFloor(const Eigen::Vector2d& p) const;
  // True where p lies inside a solid (or on its face, within kOnFaceM) or
  // off the floor (the ground truth of SPEC.md's eval).
  bool IsOccupied(const Eigen::Vector2d& p) const;
  // The distance from p to the nearest occupied point (a solid or the floor's
  // edge); 0 inside a solid or off the floor (on a face, at most kOnFaceM).
  double Clearance(const Eigen::Vector2d& p) const;
  // True where a disc of `radius` centred at p touches nothing occupied.
  bool DiscFits(const Eigen::Vector2d& p, double radius) const { return Clearance(p) > radius; }

  // The distance along the ray from `origin` (on the floor) in `direction`
  // (unit) to the first occupied point, if it is within max_range.
  std::optional<double> RayCast(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                                double max_range) const;

 private:
  std::string name_;
  Floor floor_;
  std::optional<BoundaryWalls> walls_;
  std::vector<Solid> obstacles_;
  std::vector<Solid> solids_;
  Light light_;
  RobotSpec robot_;
  std::vector<Chessboard> chessboards_;
};

// Builders for the footprints of the file's shapes (angles in radians).
Solid MakeBox(const Eigen::Vector2d& centre, const Eigen::Vector2d& size, double yaw_rad,
              double height, core::Rgb colour);
Solid MakeCylinder(const Eigen::Vector2d& centre, double radius, double height, core::Rgb colour);
Solid MakeWall(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double thickness,
               double height, core::Rgb colour);
// `points` may be given in either orientation; it must be a simple polygon.
Solid MakePrism(std::vector<Eigen::Vector2d> points, double height, core::Rgb colour);

}  // namespace pirouette::sim
