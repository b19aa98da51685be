#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/image.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/sim/world.h"

namespace pirouette::sim {

// What a camera ray meets first.
struct RayHit {
  enum class Kind {
    kFloor,   // the floor, inside its rectangle: free floor
    kSolid,   // a side or the top of an obstacle or wall
    kGround,  // the ground plane beyond the floor's rectangle
    kNothing  // the ray rises above the horizon and meets nothing
  };

  Kind kind = Kind::kNothing;
  double distance = 0.0;                              // along the ray, metres
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();  // where it meets it
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // of the face it meets
  int solid = -1;                                     // index into World::solids() for kSolid
};

// The ground truth of what a camera sees: a plain CPU ray caster of a World
// (the floor, the ground around it, and vertical prisms with their tops), one
// exact ray per (sub-)pixel through the camera's lens model. Cylinders are
// their exact circles here (the renderer draws them as kCylinderSides-gons).
// Slow and simple on purpose: the reference the renderer and the vision code
// are measured against. Immutable; holds a reference to the world.
class RayCaster {
 public:
  RayCaster(const World& world, const camera::CameraModel& camera);

  const camera::CameraModel& camera() const { return camera_; }

  // The camera's pose in the world with the robot at world_T_robot.
  Eigen::Isometry3d WorldTCamera(const core::Pose2& world_T_robot) const;

  // What the ray through `pixel` (raw image coordinates, sub-pixel) meets first.
  RayHit Cast(const Eigen::Isometry3d& world_T_camera, const Eigen::Vector2d& pixel) const;
  // The same for a ray given in the world: origin and unit direction.
  RayHit Cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) const;

  // The image the camera sees, shaded as the renderer shades (ambient plus
  // Lambert under the world's light) with the camera's vignetting; no noise,
  // no texture, no anti-aliasing (the bench's straightforward peer).
  core::ImageRgb8 Render(const core::Pose2& world_T_robot) const;

  // The true floor mask at pixel centres, row-major: 255 where the pixel's
  // ray meets free floor first, 0 elsewhere.
  std::vector<std::uint8_t> FloorMask(const core::Pose2& world_T_robot) const;

  // The true obstacle profile: for each image column, walking up from the
  // bottom row, the first ray that does not meet free floor; the transition
  // is bisected to 1e-3 pixel between the last floor pixel and it. The
  // reading's range is from the robot's centre to the floor point (the
  // camera model's, in the robot frame) just below the transition and its
  // bearing atan2(y, x) of that point, as vision::ExtractProfile reads them:
  //   kBlind when the bottom pixel already sees no free floor (range and
  //     bearing of the bottom pixel's floor point);
  //   kClear when the floor reaches max_range_m before any transition (range
  //     = max_range_m, bearing of the first pixel beyond it, or of the top
  //     pixel);
  //   kHit otherwise;
  // and kClear at the transition's range where the ray just above it meets
  // an obstacle 3 rows or more above the image of that point's foot (or
  // whose foot is out of view: a column crossing the slanted image of a
  // vertical side, the paper's §5.2: the transition's floor point is not
  // where the obstacle stands), as vision::ExtractProfile reads such a
  // column with the camera's verticals.
  core::ObstacleProfile TrueProfile(const core::Pose2& world_T_robot, double max_range_m) const;

 private:
  bool SeesFreeFloor(const Eigen::Isometry3d& world_T_camera, const Eigen::Vector2d& pixel) const;
  // The camera model's floor point (robot frame) of column u at row v, from
  // the precomputed ray when v is a whole row.
  std::optional<Eigen::Vector2d> FloorPoint(int u, double v) const;
  const Eigen::Vector3d& PixelRay(int u, int v) const;

  const World& world_;
  camera::CameraModel camera_;
  std::vector<Eigen::Vector3d> rays_;  // unit rays of the pixel centres, camera frame, row-major
};

}  // namespace pirouette::sim
