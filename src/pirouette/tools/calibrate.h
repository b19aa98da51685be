#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace pirouette::tools {

// `pirouette calibrate intrinsics`: every image in a folder (png, jpg, jpeg,
// bmp, tif, tiff; by name) searched for the chessboard, the camera solved by
// Zhang's method from the views where it was found, and the camera file
// written (atomically) with the intrinsics and distortion.
struct IntrinsicsCalibrationRequest {
  std::string images_dir;
  std::string board;      // "COLSxROWS": inner corners, e.g. "9x6"
  double square_m = 0.0;  // the printed squares' side, metres
  std::string out_path;   // the camera file to write
  // The camera file's camera_name when out_path does not exist yet (an
  // existing file keeps its name, mount and vignetting).
  std::string camera_name = "camera";
  int radial_coefficients = 2;  // plumb_bob's: 2: k1, k2 (k3 = 0); 3: k1, k2, k3
  // The distortion model: plumb_bob, rational_polynomial (wide angle) or
  // equidistant (fisheye), as ROS's camera_info names them.
  std::string model = "plumb_bob";
};

// `pirouette calibrate vignetting`: vignetting.k of the camera file fitted to
// a raw photo of a uniform, evenly lit surface filling the view; the camera
// file is rewritten (atomically) with it, its other fields unchanged.
struct VignettingCalibrationRequest {
  std::string image_path;
  std::string camera_path;
};

// `pirouette calibrate mount`: the camera's height, tilt and forward offset
// from one photo of the chessboard lying flat on the floor, its centre
// board_distance_m ahead of the robot's centre of rotation along the robot's
// forward axis; the camera file's `mount` is rewritten (atomically).
struct MountCalibrationRequest {
  std::string image_path;
  std::string board;
  double square_m = 0.0;
  double board_distance_m = 0.0;
  double board_thickness_m = 0.0;
  std::string camera_path;
};

// What a calibration prints: `json` (one object, for standard output) and
// `notes` (one line each, for standard error: views skipped or dropped,
// warnings, the file written).
struct CalibrationReport {
  std::string json;
  std::vector<std::string> notes;
};

// Each throws core::InputError (exit code 2) naming the file or option for bad
// input: a missing folder or file, an image OpenCV cannot read or of another
// size than the rest (or than the camera's), a bad --board, --square or
// --board-distance, a board found in no image (or in too few: fewer than
// vision::kMinCalibrationViews), an over- or under-exposed flat field; and
// std::runtime_error when the file cannot be written (exit code 1).
CalibrationReport CalibrateIntrinsics(const IntrinsicsCalibrationRequest& request);
CalibrationReport CalibrateVignetting(const VignettingCalibrationRequest& request);
CalibrationReport CalibrateMount(const MountCalibrationRequest& request);

// "COLSxROWS" (or "COLS×ROWS", "COLS,ROWS") inner corners, each 2..100, as
// cv::Size(cols, rows); throws core::InputError naming `option` otherwise.
cv::Size ParseBoardSize(const std::string& text, const std::string& option);

}  // namespace pirouette::tools
