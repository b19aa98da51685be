#include "pirouette/tools/calibrate.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/tools/json_output.h"
#include "pirouette/vision/chessboard_detector.h"
#include "pirouette/vision/intrinsics_calibration.h"
#include "pirouette/vision/mount_calibration.h"
#include "pirouette/vision/vignetting_fit.h"

namespace pirouette::tools {
namespace {

namespace fs = std::filesystem;

// A fresh camera file's mount until `calibrate mount` measures it: 10 cm
// above the floor, tilted 30° down, over the centre of rotation, about where
// a small robot's camera sits, so that the file loads and its ranges are
// roughly right; a guess, replaced by the measurement.
constexpr camera::Mount kPlaceholderMount{0.10, core::DegToRad(30.0), 0.0};

// Decimals of the numbers written to camera files (and printed): far finer
// than any calibration resolves, yet few enough that the files read easily.
constexpr int kPixelDecimals = 4;       // fx, fy, cx, cy: 1e-4 px
constexpr int kDistortionDecimals = 7;  // k1, k2, p1, p2, k3
constexpr int kVignettingDecimals = 4;  // vignetting.k
constexpr int kMountDecimals = 5;       // mount height and forward, metres: 0.01 mm
constexpr int kTiltDecimals = 3;        // mount tilt, degrees
// Decimals of the reports' other figures.
constexpr int kErrorDecimals = 4;        // reprojection errors, pixels
constexpr int kLevelDecimals = 2;        // the flat field's centre level, 0-255
constexpr int kDepartureDecimals = 5;    // the flat field's RMS relative departure
constexpr int kRollDecimals = 3;         // degrees
constexpr int kBoardOffsetDecimals = 5;  // metres

// Past these, a note says what to check. Lower thresholds would warn about
// sound calibrations from slightly soft photos; higher ones let blur, a bent
// board or uneven light pass unremarked.
// RMS reprojection error, pixels: well under 1 px from sharp photos of a flat board.
constexpr double kHighReprojectionPx = 1.0;
// Views used: 10 to 20, the board tilted differently and reaching every part
// of the image, make a reliable calibration.
constexpr std::size_t kRecommendedViews = 10;
// A flat field's RMS relative departure from the vignetting model: a few
// thousandths for a uniform, evenly lit surface.
constexpr double kFlatFieldDeparture = 0.02;
// The camera's roll, degrees: the camera model has none.
constexpr double kRollWarningDeg = 2.0;
// The board's centre off the camera's forward axis, metres: it should lie on
// the robot's axis.
constexpr double kBoardOffsetWarningM = 0.02;
// The largest tilt a camera file holds: the model's tilt lies in (-90°, 90°).
constexpr double kMaxTiltDeg = 89.99;

std::string SizeText(cv::Size size) { return fmt::format("{}x{}", size.width, size.height); }

double CheckPositive(double value, const std::string& option, const std::string& meaning) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw core::InputError(option, 0, "", fmt::format("{} must be > 0, got {}", meaning, value));
  }
  return value;
}

bool IsImageName(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".tif" ||
         ext == ".tiff";
}

// The folder's images, by name.
std::vector<fs::path> ListImages(const std::string& dir) {
  std::error_code error;
  if (!fs::exists(dir, error)) throw core::InputError(dir, 0, "", "no such folder");
  if (!fs::is_directory(dir, error)) throw core::InputError(dir, 0, "", "not a folder");
  std::vector<fs::path> images;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    if (entry.is_regular_file(error) && IsImageName(entry.path())) images.push_back(entry.path());
  }
  if (error) throw core::InputError(dir, 0, "", "cannot list the folder: " + error.message());
  std::sort(images.begin(), images.end());
  if (images.empty()) {
    throw core::InputError(dir, 0, "", "no images (png, jpg, jpeg, bmp, tif, tiff) in the folder");
  }
  return images;
}

// The image as 8-bit BGR, as the sensor delivered it (EXIF orientation ignored).
cv::Mat ReadBgr(const std::string& path) {
  std::error_code error;
  if (!fs::exists(path, error)) throw core::InputError(path, 0, "", "no such file");
  cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR | cv::IMREAD_IGNORE_ORIENTATION);
  if (bgr.empty()) throw core::InputError(path, 0, "", "not an image OpenCV can read");
  return bgr;
}

void CheckCameraSize(const cv::Mat& image, const std::string& path,
                     const camera::CameraModel& camera, const std::string& camera_path) {
  if (image.cols != camera.width() || image.rows != camera.height()) {
    throw core::InputError(
        path, 0, "",
        fmt::format("the image is {}, but the camera file {} is for {}x{} images",
                    SizeText(image.size()), camera_path, camera.width(), camera.height()));
  }
}

camera::CameraModel WithVignetting(const camera::CameraModel& c, const camera::Vignetting& v) {
  return {c.name(), c.width(), c.height(), c.intrinsics(), c.distortion(), c.mount(), v};
}

camera::CameraModel WithMount(const camera::CameraModel& c, const camera::Mount& mount) {
  return {c.name(), c.width(), c.height(), c.intrinsics(), c.distortion(), mount, c.vignetting()};
}

void WriteCamera(const std::string& path, const camera::CameraModel& camera) {
  io::WriteFileAtomically(path, io::CameraFileText(camera));
}

// The inner corners of a valid `calibrate intrinsics` request.
cv::Size CheckIntrinsicsRequest(const IntrinsicsCalibrationRequest& request) {
  const cv::Size pattern = ParseBoardSize(request.board, "--board");
  CheckPositive(request.square_m, "--square", "the squares' side (metres)");
  if (request.radial_coefficients != 2 && request.radial_coefficients != 3) {
    throw core::InputError("--k-coefficients", 0, "",
                           fmt::format("expected 2 or 3, got {}", request.radial_coefficients));
  }
  if (!camera::ModelNamed(request.model)) {
    throw core::InputError(
        "--model", 0, "",
        fmt::format("expected plumb_bob, rational_polynomial or equidistant, got '{}'",
                    request.model));
  }
  return pattern;
}

// The board's corners in each image where it was found, and the names of the
// others; every image must have the first's size.
struct BoardViews {
  std::vector<vision::ChessboardView> views;
  std::vector<std::string> skipped;
  cv::Size image_size;
};

BoardViews FindBoards(const std::vector<fs::path>& images, cv::Size pattern) {
  const vision::ChessboardDetector detector(pattern);
  BoardViews found;
  std::string first;
  for (const fs::path& path : images) {
    const cv::Mat bgr = ReadBgr(path.string());
    const std::string name = path.filename().string();
    if (first.empty()) {
      found.image_size = bgr.size();
      first = name;
    } else if (bgr.size() != found.image_size) {
      throw core::InputError(path.string(), 0, "",
                             fmt::format("the image is {}, but {} is {}: every view must come from "
                                         "the same camera at the same resolution",
                                         SizeText(bgr.size()), first, SizeText(found.image_size)));
    }
    if (auto corners = detector.Find(bgr)) {
      found.views.push_back({name, std::move(*corners)});
    } else {
      found.skipped.push_back(name);
    }
  }
  return found;
}

void CheckEnoughViews(const BoardViews& found, std::size_t images,
                      const IntrinsicsCalibrationRequest& request) {
  if (found.views.empty()) {
    throw core::InputError(
        request.images_dir, 0, "",
        fmt::format("no {} board found in any of the {} images (--board counts the inner corners: "
                    "a board of 10 x 7 squares is 9x6)",
                    request.board, images));
  }
  if (static_cast<int>(found.views.size()) < vision::kMinCalibrationViews) {
    throw core::InputError(request.images_dir, 0, "",
                           fmt::format("the board was found in only {} of the {} images; at least "
                                       "{} are needed (10 to 20 make a good calibration)",
                                       found.views.size(), images, vision::kMinCalibrationViews));
  }
}

// What a calibrated camera file keeps of the one it replaces (or a new one's
// placeholders), and the note that says which.
struct KeptFields {
  std::string name;
  camera::Mount mount = kPlaceholderMount;
  camera::Vignetting vignetting;
  std::string note;
};

KeptFields KeptFromCameraFile(const IntrinsicsCalibrationRequest& request) {
  KeptFields kept;
  std::error_code error;
  if (fs::exists(request.out_path, error)) {
    const camera::CameraModel old = io::LoadCameraFile(request.out_path);
    kept.name = old.name();
    kept.mount = old.mount();
    kept.vignetting = old.vignetting();
    kept.note =
        fmt::format("{}: intrinsics and distortion replaced; its name, mount and vignetting kept",
                    request.out_path);
  } else {
    kept.name = request.camera_name;
    kept.note = fmt::format(
        "{}: new camera file; its mount is a placeholder until `pirouette calibrate mount`, its "
        "vignetting 0 until `pirouette calibrate vignetting`",
        request.out_path);
  }
  return kept;
}

// The camera file's intrinsics and distortion as written and printed.
camera::Intrinsics RoundedIntrinsics(const camera::Intrinsics& k) {
  return {RoundTo(k.fx, kPixelDecimals), RoundTo(k.fy, kPixelDecimals),
          RoundTo(k.cx, kPixelDecimals), RoundTo(k.cy, kPixelDecimals)};
}

camera::Distortion RoundedDistortion(const camera::Distortion& d) {
  std::vector<double> coefficients = d.Coefficients();
  for (double& c : coefficients) c = RoundTo(c, kDistortionDecimals);
  return *camera::Distortion::FromCoefficients(d.model, coefficients);
}

// The notes on a calibration that worked but may not be reliable.
std::vector<std::string> IntrinsicsQualityNotes(const vision::IntrinsicsCalibration& calibration) {
  std::vector<std::string> notes;
  if (calibration.rms_px > kHighReprojectionPx) {
    notes.push_back(fmt::format(
        "reprojection error {:.2f} px is high (expect well under 1 px): check the photos for blur "
        "and the board for flatness, and --square",
        calibration.rms_px));
  }
  if (calibration.used.size() < kRecommendedViews) {
    notes.push_back(fmt::format(
        "only {} views used: 10 to 20, the board tilted differently and reaching every part of the "
        "image, give a more reliable calibration",
        calibration.used.size()));
  }
  return notes;
}

nlohmann::ordered_json ViewErrorsJson(const std::vector<vision::ViewError>& views) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const vision::ViewError& view : views) {
    out.push_back({{"image", view.name}, {"error_px", RoundTo(view.rms_px, kErrorDecimals)}});
  }
  return out;
}

std::string IntrinsicsJson(const IntrinsicsCalibrationRequest& request, const BoardViews& found,
                           const vision::IntrinsicsCalibration& calibration) {
  const camera::Intrinsics k = RoundedIntrinsics(calibration.intrinsics);
  const camera::Distortion d = RoundedDistortion(calibration.distortion);
  nlohmann::ordered_json json;
  json["views_used"] = calibration.used.size();
  json["views_skipped"] = found.skipped;
  json["views_dropped"] = ViewErrorsJson(calibration.dropped);
  json["reprojection_error_px"] = RoundTo(calibration.rms_px, kErrorDecimals);
  json["fx"] = k.fx;
  json["fy"] = k.fy;
  json["cx"] = k.cx;
  json["cy"] = k.cy;
  json["distortion_model"] = camera::ModelName(d.model);
  json["distortion"] = d.Coefficients();
  json["image_width"] = found.image_size.width;
  json["image_height"] = found.image_size.height;
  json["views"] = ViewErrorsJson(calibration.used);
  json["camera"] = request.out_path;
  return JsonText(json, -1);
}

// The inner corners of a valid `calibrate mount` request.
cv::Size CheckMountRequest(const MountCalibrationRequest& request) {
  const cv::Size pattern = ParseBoardSize(request.board, "--board");
  CheckPositive(request.square_m, "--square", "the squares' side (metres)");
  CheckPositive(request.board_distance_m, "--board-distance",
                "the distance from the robot's centre to the board's centre (metres)");
  if (!(request.board_thickness_m >= 0.0) || !std::isfinite(request.board_thickness_m)) {
    throw core::InputError("--board-thickness", 0, "",
                           fmt::format("must be >= 0, got {}", request.board_thickness_m));
  }
  return pattern;
}

// The notes on a measured mount that may be off: a rolled camera, a board
// off the axis, corners that reproject badly.
std::vector<std::string> MountNotes(const vision::MountCalibration& m) {
  std::vector<std::string> notes;
  const double roll_deg = core::RadToDeg(m.roll_rad);
  if (std::abs(roll_deg) > kRollWarningDeg) {
    notes.push_back(fmt::format(
        "the camera is rolled {:.1f} deg about its axis; the camera model has no roll: level it "
        "on the robot",
        roll_deg));
  }
  if (std::abs(m.board_left_m) > kBoardOffsetWarningM) {
    notes.push_back(fmt::format(
        "the board's centre is {:.3f} m {} of the camera's forward axis: was it on the robot's "
        "axis? (or the camera looks askew)",
        std::abs(m.board_left_m), m.board_left_m > 0 ? "left" : "right"));
  }
  if (m.rms_px > kHighReprojectionPx) {
    notes.push_back(fmt::format(
        "the board's corners reproject {:.2f} px off: check the intrinsics (calibrate intrinsics "
        "first) and --square",
        m.rms_px));
  }
  return notes;
}

}  // namespace

cv::Size ParseBoardSize(const std::string& text, const std::string& option) {
  const auto bad = [&](const std::string& why) {
    return core::InputError(option, 0, "",
                            fmt::format("expected COLSxROWS inner corners (e.g. 9x6 for a board of "
                                        "10 x 7 squares), got '{}': {}",
                                        text, why));
  };
  std::size_t at = std::string::npos;
  std::size_t width = 1;
  for (const std::string_view separator : {"x", "X", "\u00d7", ","}) {
    at = text.find(separator);
    if (at != std::string::npos) {
      width = separator.size();
      break;
    }
  }
  if (at == std::string::npos) throw bad("no 'x' between the two counts");
  const auto whole = [&](std::string_view part) {
    int value = 0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (error != std::errc() || end != part.data() + part.size() || part.empty()) {
      throw bad(fmt::format("'{}' is not a whole number", part));
    }
    if (value < 2 || value > 100) throw bad(fmt::format("{} is outside 2..100", value));
    return value;
  };
  const std::string_view all(text);
  const int cols = whole(all.substr(0, at));
  const int rows = whole(all.substr(at + width));
  return {cols, rows};
}

CalibrationReport CalibrateIntrinsics(const IntrinsicsCalibrationRequest& request) {
  const cv::Size pattern = CheckIntrinsicsRequest(request);
  const std::vector<fs::path> images = ListImages(request.images_dir);
  const BoardViews found = FindBoards(images, pattern);
  CalibrationReport report;
  for (const std::string& name : found.skipped) {
    report.notes.push_back(fmt::format("{}: no {} board found: skipped", name, request.board));
  }
  CheckEnoughViews(found, images.size(), request);

  vision::IntrinsicsCalibrationOptions options;
  options.pattern = pattern;
  options.square_m = request.square_m;
  options.radial_coefficients = request.radial_coefficients;
  options.model = *camera::ModelNamed(request.model);
  const vision::IntrinsicsCalibration calibration =
      vision::CalibrateIntrinsics(found.views, found.image_size, options);
  for (const vision::ViewError& view : calibration.dropped) {
    report.notes.push_back(fmt::format(
        "{}: reprojection error {:.2f} px, far above the other views': dropped (a blurred photo, "
        "a bent board?)",
        view.name, view.rms_px));
  }

  const KeptFields kept = KeptFromCameraFile(request);
  report.notes.push_back(kept.note);
  WriteCamera(
      request.out_path,
      camera::CameraModel(kept.name, found.image_size.width, found.image_size.height,
                          RoundedIntrinsics(calibration.intrinsics),
                          RoundedDistortion(calibration.distortion), kept.mount, kept.vignetting));
  for (std::string& note : IntrinsicsQualityNotes(calibration)) {
    report.notes.push_back(std::move(note));
  }
  report.notes.push_back(fmt::format("wrote {}", request.out_path));
  report.json = IntrinsicsJson(request, found, calibration);
  return report;
}

CalibrationReport CalibrateVignetting(const VignettingCalibrationRequest& request) {
  const camera::CameraModel camera = io::LoadCameraFile(request.camera_path);
  const cv::Mat bgr = ReadBgr(request.image_path);
  CheckCameraSize(bgr, request.image_path, camera, request.camera_path);
  std::optional<vision::VignettingFit> fit;
  try {
    fit = vision::FitVignetting(bgr, camera);
  } catch (const std::invalid_argument&) {
    throw core::InputError(request.image_path, 0, "",
                           "too few usable pixels: the photo is over- or under-exposed (take it "
                           "so that its brightest part stays below 250)");
  }
  CalibrationReport report;
  static constexpr const char* kChannels[] = {"red", "green", "blue"};
  camera::Vignetting vignetting;
  for (std::size_t c = 0; c < 3; ++c) {
    vignetting.k[c] = RoundTo(fit->vignetting.k[c], kVignettingDecimals);
    if (fit->clamped[c]) {
      report.notes.push_back(fmt::format(
          "{}: the {} channel's corners are brighter than its centre: k set to 0 (was the surface "
          "evenly lit?)",
          request.image_path, kChannels[c]));
    }
    if (fit->rms_relative[c] > kFlatFieldDeparture) {
      report.notes.push_back(fmt::format(
          "{}: the {} channel departs from the model by {:.1f}% RMS: the surface or its light is "
          "not uniform; the fit may be off",
          request.image_path, kChannels[c], 100.0 * fit->rms_relative[c]));
    }
  }
  WriteCamera(request.camera_path, WithVignetting(camera, vignetting));
  report.notes.push_back(fmt::format("wrote {} (vignetting.k)", request.camera_path));
  const auto rounded = [](const std::array<double, 3>& v, int decimals) {
    return nlohmann::ordered_json{RoundTo(v[0], decimals), RoundTo(v[1], decimals),
                                  RoundTo(v[2], decimals)};
  };
  nlohmann::ordered_json json;
  json["k"] = vignetting.k;
  json["centre_level"] = rounded(fit->centre_level, kLevelDecimals);
  json["rms_relative"] = rounded(fit->rms_relative, kDepartureDecimals);
  json["blocks_used"] = fit->blocks_used;
  json["blocks"] = fit->blocks;
  json["camera"] = request.camera_path;
  report.json = JsonText(json, -1);
  return report;
}

CalibrationReport CalibrateMount(const MountCalibrationRequest& request) {
  const cv::Size pattern = CheckMountRequest(request);
  const camera::CameraModel camera = io::LoadCameraFile(request.camera_path);
  const cv::Mat bgr = ReadBgr(request.image_path);
  CheckCameraSize(bgr, request.image_path, camera, request.camera_path);
  const auto corners = vision::ChessboardDetector(pattern).Find(bgr);
  if (!corners) {
    throw core::InputError(request.image_path, 0, "",
                           fmt::format("no {} board found (--board counts the inner corners: a "
                                       "board of 10 x 7 squares is 9x6; the whole board must be "
                                       "in view)",
                                       request.board));
  }
  vision::MountCalibrationOptions options;
  options.pattern = pattern;
  options.square_m = request.square_m;
  options.board_distance_m = request.board_distance_m;
  options.board_thickness_m = request.board_thickness_m;
  vision::MountCalibration m;
  try {
    m = vision::CalibrateMount(*corners, camera, options);
  } catch (const std::invalid_argument& e) {
    throw core::InputError(request.image_path, 0, "", e.what());
  }
  if (!(m.mount.height_m > 0.0) || !(std::abs(m.mount.tilt_rad) < core::DegToRad(kMaxTiltDeg))) {
    throw core::InputError(request.image_path, 0, "",
                           fmt::format("the board's pose gives a mount the camera model cannot "
                                       "hold (height {:.4f} m, tilt {:.2f} deg)",
                                       m.mount.height_m, core::RadToDeg(m.mount.tilt_rad)));
  }
  CalibrationReport report;
  report.notes = MountNotes(m);
  const camera::Mount mount{
      RoundTo(m.mount.height_m, kMountDecimals),
      core::DegToRad(RoundTo(core::RadToDeg(m.mount.tilt_rad), kTiltDecimals)),
      RoundTo(m.mount.forward_m, kMountDecimals)};
  WriteCamera(request.camera_path, WithMount(camera, mount));
  report.notes.push_back(fmt::format("wrote {} (mount)", request.camera_path));
  nlohmann::ordered_json json;
  json["height"] = RoundTo(m.mount.height_m, kMountDecimals);
  json["tilt_deg"] = RoundTo(core::RadToDeg(m.mount.tilt_rad), kTiltDecimals);
  json["roll_deg"] = RoundTo(core::RadToDeg(m.roll_rad), kRollDecimals);
  json["forward"] = RoundTo(m.mount.forward_m, kMountDecimals);
  json["board_left_m"] = RoundTo(m.board_left_m, kBoardOffsetDecimals);
  json["reprojection_error_px"] = RoundTo(m.rms_px, kErrorDecimals);
  json["camera"] = request.camera_path;
  report.json = JsonText(json, -1);
  return report;
}

}  // namespace pirouette::tools
