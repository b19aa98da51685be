#include "pirouette/vision/mount_calibration.h"

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <stdexcept>

#include "pirouette/vision/intrinsics_calibration.h"

namespace pirouette::vision {

MountCalibration CalibrateMount(const std::vector<cv::Point2f>& corners,
                                const camera::CameraModel& camera,
                                const MountCalibrationOptions& options) {
  if (options.pattern.width < 2 || options.pattern.height < 2 || !(options.square_m > 0.0) ||
      !(options.board_distance_m > 0.0) || !(options.board_thickness_m >= 0.0)) {
    throw std::invalid_argument("CalibrateMount: bad pattern, square, distance or thickness");
  }
  if (corners.size() != static_cast<std::size_t>(options.pattern.area())) {
    throw std::invalid_argument("CalibrateMount: the corners are not the pattern's");
  }
  const std::vector<cv::Point3f> board = ChessboardObjectPoints(options.pattern, options.square_m);
  const camera::Intrinsics& k = camera.intrinsics();
  const cv::Matx33d camera_matrix(k.fx, 0.0, k.cx, 0.0, k.fy, k.cy, 0.0, 0.0, 1.0);
  const camera::Distortion& d = camera.distortion();
  const std::vector<double> coefficients = d.Coefficients();
  const cv::Mat model_distortion = cv::Mat(coefficients, true).reshape(1, 1);
  const bool fisheye = d.model == camera::Distortion::Model::kEquidistant;
  // solvePnP has no fisheye model: a fisheye's corners are first moved to
  // where an ideal pinhole camera with the same matrix would see them.
  std::vector<cv::Point2f> pinhole_corners = corners;
  cv::Mat distortion = model_distortion;
  if (fisheye) {
    cv::fisheye::undistortPoints(corners, pinhole_corners, camera_matrix, model_distortion,
                                 cv::noArray(), camera_matrix);
    distortion = cv::Mat();
  }
  cv::Mat rvec;
  cv::Mat tvec;
  if (!cv::solvePnP(board, pinhole_corners, camera_matrix, distortion, rvec, tvec, false,
                    cv::SOLVEPNP_IPPE)) {
    throw std::invalid_argument("CalibrateMount: no pose of the board fits its corners");
  }
  cv::solvePnPRefineLM(board, pinhole_corners, camera_matrix, distortion, rvec, tvec);

  std::vector<cv::Point2f> projected;
  if (fisheye) {
    cv::fisheye::projectPoints(board, projected, rvec, tvec, camera_matrix, model_distortion);
  } else {
    cv::projectPoints(board, rvec, tvec, camera_matrix, distortion, projected);
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < projected.size(); ++i) {
    const cv::Point2f e = projected[i] - corners[i];
    sum += e.dot(e);
  }

  cv::Matx33d rotation;
  cv::Rodrigues(rvec, rotation);
  // In the camera frame (x right, y down, z along the axis): the board's
  // centre, and its plane's normal turned towards the camera: the floor's "up".
  const cv::Vec3d centre(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
  cv::Vec3d up(rotation(0, 2), rotation(1, 2), rotation(2, 2));
  if (up.dot(centre) > 0.0) up = -up;
  if (!(centre[2] > 0.0)) {
    throw std::invalid_argument("CalibrateMount: the board is behind the camera");
  }
  // The camera's horizontal forward direction and the robot's left.
  const cv::Vec3d axis(0.0, 0.0, 1.0);
  cv::Vec3d forward = axis - axis.dot(up) * up;
  const double forward_norm = cv::norm(forward);
  if (!(forward_norm > 1e-9)) {
    throw std::invalid_argument("CalibrateMount: the camera looks straight down (tilt 90°)");
  }
  forward /= forward_norm;
  const cv::Vec3d left = up.cross(forward);

  MountCalibration result;
  result.mount.height_m = -up.dot(centre) + options.board_thickness_m;
  result.mount.tilt_rad = std::asin(std::clamp(-up[2], -1.0, 1.0));
  result.mount.forward_m = options.board_distance_m - centre.dot(forward);
  result.roll_rad = std::atan2(up[0], -up[1]);
  result.board_left_m = centre.dot(left);
  result.rms_px = std::sqrt(sum / static_cast<double>(projected.size()));
  return result;
}

}  // namespace pirouette::vision
