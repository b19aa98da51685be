#include <cstdio>
#include <memory>
#include <string>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "pirouette/tools/calibrate.h"

namespace pirouette::cli {
namespace {

// The JSON on standard output, the notes on standard error (SPEC.md).
void Print(const tools::CalibrationReport& report) {
  for (const std::string& note : report.notes) std::fprintf(stderr, "%s\n", note.c_str());
  std::fputs(report.json.c_str(), stdout);
}

// --board and --square, both required: the printed chessboard of intrinsics and mount.
void AddBoardOptions(CLI::App* app, std::string& board, double& square_m) {
  app->add_option("--board", board,
                  "COLSxROWS: the board's inner corners (where four squares meet), as OpenCV "
                  "counts them: a board of 10 x 7 squares is 9x6")
      ->required();
  app->add_option("--square", square_m, "side of one printed square, metres (measure it)")
      ->required();
}

constexpr const char* kUpdatedCamera = "the one to update";

}  // namespace

Command AddCalibrateCommand(CLI::App& parent) {
  CLI::App* cmd = parent.add_subcommand(
      "calibrate",
      "Calibrate a real camera with a printed chessboard, in three steps that each write into the "
      "camera file: intrinsics (focal length, principal point, lens distortion) from 10-20 photos "
      "of the board; vignetting from one photo of a uniform surface; the mount (height, tilt, "
      "forward) from one photo of the board lying on the floor ahead of the robot. See "
      "docs/calibration.md.\n  example: pirouette calibrate intrinsics --images photos/ --board "
      "9x6 --square 0.025 --out camera.yaml");
  cmd->require_subcommand(1);

  auto intrinsics = std::make_shared<tools::IntrinsicsCalibrationRequest>();
  CLI::App* in = cmd->add_subcommand(
      "intrinsics",
      "Find the chessboard in every image of a folder (sub-pixel corners; images where it is not "
      "found are reported and skipped, views whose reprojection error is far above the rest are "
      "reported and dropped), solve the camera (Zhang's method, OpenCV), write the camera file "
      "(ROS camera_info fields; an existing file keeps its name, mount and vignetting) and print "
      "{\"views_used\", \"views_skipped\", \"reprojection_error_px\", \"fx\", \"fy\", \"cx\", "
      "\"cy\", \"distortion\": [k1, k2, p1, p2, k3], ...} as JSON.\n  example: pirouette "
      "calibrate intrinsics --images photos/ --board 9x6 --square 0.025 --out camera.yaml");
  in->add_option("--images", intrinsics->images_dir,
                 "folder of photos of the board (png, jpg, jpeg, bmp, tif, tiff), all from the "
                 "camera at the resolution the robot will use")
      ->required();
  AddBoardOptions(in, intrinsics->board, intrinsics->square_m);
  in->add_option("--out", intrinsics->out_path, "the camera file to write (YAML)")->required();
  in->add_option("--name", intrinsics->camera_name,
                 "camera_name of a new camera file (an existing file keeps its own)")
      ->capture_default_str();
  in->add_option("--k-coefficients", intrinsics->radial_coefficients,
                 "radial distortion coefficients to estimate: 2 (k1, k2; k3 = 0) or 3")
      ->capture_default_str();
  in->add_option("--model", intrinsics->model,
                 "the lens's distortion model: plumb_bob (most lenses), rational_polynomial "
                 "(wide angle, 8 coefficients) or equidistant (fisheye, OpenCV's cv::fisheye)")
      ->capture_default_str();

  auto vignetting = std::make_shared<tools::VignettingCalibrationRequest>();
  CLI::App* vg = cmd->add_subcommand(
      "vignetting",
      "Fit the lens's vignetting (per channel R, G, B: the light passed falls as 1 / (1 + "
      "k·(r/r_max)²), which also removes a colour tint; Taylor, Geva & Boles 2005, §2.1) to a "
      "photo "
      "of a uniform, evenly lit, matte surface that fills the whole view (white paper, a plain "
      "wall), not over-exposed, and write vignetting.k into the camera file. Run it after "
      "`calibrate intrinsics` (it uses the principal point).\n  example: pirouette calibrate "
      "vignetting --image flat.png --camera camera.yaml");
  AddImageOption(vg, vignetting->image_path, "of the uniform surface")->required();
  AddCameraOption(vg, vignetting->camera_path, kUpdatedCamera)->required();

  auto mount = std::make_shared<tools::MountCalibrationRequest>();
  CLI::App* mt = cmd->add_subcommand(
      "mount",
      "Measure where the camera sits on the robot from one photo, taken by the robot's camera, of "
      "the chessboard lying flat on the floor in front of the robot, its centre on the robot's "
      "forward axis: the camera's height above the floor, its tilt (downward pitch) and its "
      "forward offset from the robot's centre of rotation are written into the camera file's "
      "mount; its roll is reported. Run it after `calibrate intrinsics`.\n  example: pirouette "
      "calibrate mount --image board.png --board 9x6 --square 0.025 --board-distance 0.30 "
      "--camera camera.yaml");
  AddImageOption(mt, mount->image_path, "from the robot's camera, of the board on the floor")
      ->required();
  AddBoardOptions(mt, mount->board, mount->square_m);
  mt->add_option("--board-distance", mount->board_distance_m,
                 "metres, measured on the floor along the robot's forward axis, from the robot's "
                 "centre of rotation (the point it spins about: the middle of the drive wheels' "
                 "axle) to the centre of the board (the centre of the printed squares)")
      ->required();
  mt->add_option("--board-thickness", mount->board_thickness_m,
                 "metres: how far the printed face stands above the floor (0 for paper)")
      ->capture_default_str();
  AddCameraOption(mt, mount->camera_path, kUpdatedCamera)->required();

  return {cmd, [in, vg, mt, intrinsics, vignetting, mount] {
            if (in->parsed()) Print(tools::CalibrateIntrinsics(*intrinsics));
            if (vg->parsed()) Print(tools::CalibrateVignetting(*vignetting));
            if (mt->parsed()) Print(tools::CalibrateMount(*mount));
          }};
}

}  // namespace pirouette::cli
