#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pirouette/camera/camera_model.h"

namespace pirouette::vision {

// One photo of the chessboard: its name (for reports) and its inner corners
// as ChessboardDetector::Find gives them.
struct ChessboardView {
  std::string name;
  std::vector<cv::Point2f> corners;
};

struct IntrinsicsCalibrationOptions {
  cv::Size pattern;       // inner corners (cols, rows)
  double square_m = 0.0;  // the side of one square, metres (> 0)
  // The distortion model solved for: plumb_bob and rational_polynomial by
  // cv::calibrateCamera (the latter with CALIB_RATIONAL_MODEL), equidistant
  // by cv::fisheye::calibrate.
  camera::Distortion::Model model = camera::Distortion::Model::kPlumbBob;
  // plumb_bob's radial coefficients estimated: 2 (k1, k2; k3 held at 0, as
  // ROS's camera_calibration does by default) or 3. The other models estimate all.
  int radial_coefficients = 2;
  // A view whose RMS reprojection error exceeds both outlier_factor times the
  // median view's and outlier_floor_px is dropped, and the camera solved again
  // without it (a blurred photo, a board that was bent, a wrong detection).
  double outlier_factor = 3.0;
  double outlier_floor_px = 0.5;
};

struct ViewError {
  std::string name;
  double rms_px = 0.0;  // RMS distance between the detected and the reprojected corners
};

struct IntrinsicsCalibration {
  camera::Intrinsics intrinsics;
  camera::Distortion distortion;
  double rms_px = 0.0;             // over every corner of the views used
  std::vector<ViewError> used;     // in the order given
  std::vector<ViewError> dropped;  // the outliers, with their error before they were dropped
};

// The fewest views CalibrateIntrinsics accepts; a dozen or more, the board
// seen at many tilts and across the whole image, make a good calibration.
inline constexpr int kMinCalibrationViews = 3;

// Zhang's method (Zhang 2000, "A flexible new technique for camera
// calibration") through cv::calibrateCamera (cv::fisheye::calibrate for
// equidistant): pinhole intrinsics (no skew) and the options' distortion model from views of a
// planar chessboard in an image of `image_size`. The board's planes must not all be parallel in the
// camera frame (tilt it differently between photos). Outliers are dropped once (see the options),
// keeping at least kMinCalibrationViews. Throws std::invalid_argument for fewer views than that,
// views whose corner count is not the pattern's, or bad options.
IntrinsicsCalibration CalibrateIntrinsics(const std::vector<ChessboardView>& views,
                                          cv::Size image_size,
                                          const IntrinsicsCalibrationOptions& options);

// The board's inner corners in its own plane (z = 0), metres, in the order
// ChessboardDetector gives the corners, centred on the grid's centre.
std::vector<cv::Point3f> ChessboardObjectPoints(cv::Size pattern, double square_m);

}  // namespace pirouette::vision
