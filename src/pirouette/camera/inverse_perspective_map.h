#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "pirouette/camera/camera_model.h"

namespace pirouette::camera {

// The inverse perspective mapping as a lookup table built once: for each raw
// (distorted) pixel centre, the point of the flat floor it sees, in the robot
// frame (metres). Pixels at or above the horizon see no floor.
class InversePerspectiveMap {
 public:
  explicit InversePerspectiveMap(const CameraModel& camera);

  int width() const { return width_; }
  int height() const { return height_; }

  // The floor point seen at the centre of pixel (u, v); nullopt above the horizon.
  std::optional<Eigen::Vector2f> At(int u, int v) const;
  bool SeesFloor(int u, int v) const { return sees_floor_[Index(u, v)] != 0; }

 private:
  std::size_t Index(int u, int v) const;

  int width_;
  int height_;
  std::vector<Eigen::Vector2f> floor_points_;  // valid where sees_floor_
  std::vector<std::uint8_t> sees_floor_;
};

// The range of the farthest floor point the image's bottom row sees: nearer
// than this, some bearings of the camera see no floor at all.
double NearRange(const InversePerspectiveMap& ipm);

}  // namespace pirouette::camera
