#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "pirouette/camera/camera_model.h"

namespace pirouette::vision {

// Where the chessboard lay when its photo was taken: flat on the floor,
// its centre (the centre of its inner corners' grid, which is the printed
// board's centre) on the robot's forward axis.
struct MountCalibrationOptions {
  cv::Size pattern;       // inner corners (cols, rows)
  double square_m = 0.0;  // the side of one square, metres (> 0)
  // From the robot's centre of rotation to the board's centre, along the
  // robot's forward axis, on the floor (> 0).
  double board_distance_m = 0.0;
  // How far the board's face stands above the floor (card, a mounted board), >= 0.
  double board_thickness_m = 0.0;
};

struct MountCalibration {
  camera::Mount mount;  // height, tilt and forward (camera/camera_model.h)
  // The rotation about the optical axis, radians: positive when the horizon
  // would run down to the right in the image. The camera model has no roll;
  // more than a degree or two is worth fixing on the robot.
  double roll_rad = 0.0;
  // The board's centre to the left of the camera's forward axis, metres: ~0
  // when the board lay on the robot's axis and the camera looks straight ahead.
  double board_left_m = 0.0;
  double rms_px = 0.0;  // RMS reprojection error of the board's corners
};

// The camera's mount from one photo of a chessboard lying on the floor: the
// board's pose by cv::solvePnP (IPPE, then Levenberg–Marquardt) with the
// camera's intrinsics and distortion; the board's plane gives the height (the
// optical centre's distance to it plus the board's thickness), the tilt and
// the roll; the board's centre, measured along the camera's horizontal
// forward direction, and board_distance_m give `forward` (optical centre
// ahead of the centre of rotation). `corners`: from ChessboardDetector, in
// the camera's raw (distorted) image. Throws std::invalid_argument for bad
// options, a corner count that is not the pattern's, or a pose the camera
// model cannot hold (the board behind the camera, a tilt beyond ±90°).
MountCalibration CalibrateMount(const std::vector<cv::Point2f>& corners,
                                const camera::CameraModel& camera,
                                const MountCalibrationOptions& options);

}  // namespace pirouette::vision
