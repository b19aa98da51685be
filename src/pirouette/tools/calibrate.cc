#include "pirouette/tools/calibrate.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
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
#include "pirouette/vision/chessboard_detector.h"
#include "pirouette/vision/intrinsics_calibration.h"
#include "pirouette/vision/mount_calibration.h"
#include "pirouette/vision/vignetting_fit.h"

namespace pirouette::tools {
namespace {

namespace fs = std::filesystem;

// A fresh camera file's mount until `calibrate mount` measures it.
constexpr camera::Mount kPlaceholderMount{0.10, core::DegToRad(30.0), 0.0};

// Numbers as written to camera files: far finer than any calibration resolves.
double Rounded(double value, double step) { return std::round(value / step) * step; }

std::string JsonString(std::string_view text) {
  std::string out = "\"";
  for (const char ch : text) {
    switch (ch) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          out += fmt::format("\\u{:04x}", static_cast<unsigned>(ch));
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

std::string JsonNumbers(const double* values, std::size_t n, int decimals) {
  std::string out = "[";
  for (std::size_t i = 0; i < n; ++i) {
    out += fmt::format("{}{:.{}f}", i == 0 ? "" : ", ", values[i], decimals);
  }
  return out + "]";
}

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
  const cv::Size pattern = ParseBoardSize(request.board, "--board");
  CheckPositive(request.square_m, "--square", "the squares' side (metres)");
  if (request.radial_coefficients != 2 && request.radial_coefficients != 3) {
    throw core::InputError("--k-coefficients", 0, "",
                           fmt::format("expected 2 or 3, got {}", request.radial_coefficients));
  }
  const std::vector<fs::path> images = ListImages(request.images_dir);
  const vision::ChessboardDetector detector(pattern);
  CalibrationReport report;
  std::vector<vision::ChessboardView> views;
  std::vector<std::string> skipped;
  cv::Size image_size;
  std::string first;
  for (const fs::path& path : images) {
    const cv::Mat bgr = ReadBgr(path.string());
    const std::string name = path.filename().string();
    if (first.empty()) {
      image_size = bgr.size();
      first = name;
    } else if (bgr.size() != image_size) {
      throw core::InputError(path.string(), 0, "",
                             fmt::format("the image is {}, but {} is {}: every view must come from "
                                         "the same camera at the same resolution",
                                         SizeText(bgr.size()), first, SizeText(image_size)));
    }
    if (auto corners = detector.Find(bgr)) {
      views.push_back({name, std::move(*corners)});
    } else {
      skipped.push_back(name);
      report.notes.push_back(fmt::format("{}: no {} board found: skipped", name, request.board));
    }
  }
  if (views.empty()) {
    throw core::InputError(
        request.images_dir, 0, "",
        fmt::format("no {} board found in any of the {} images (--board counts the inner corners: "
                    "a board of 10 x 7 squares is 9x6)",
                    request.board, images.size()));
  }
  if (static_cast<int>(views.size()) < vision::kMinCalibrationViews) {
    throw core::InputError(request.images_dir, 0, "",
                           fmt::format("the board was found in only {} of the {} images; at least "
                                       "{} are needed (10 to 20 make a good calibration)",
                                       views.size(), images.size(), vision::kMinCalibrationViews));
  }

  vision::IntrinsicsCalibrationOptions options;
  options.pattern = pattern;
  options.square_m = request.square_m;
  options.radial_coefficients = request.radial_coefficients;
  const vision::IntrinsicsCalibration calibration =
      vision::CalibrateIntrinsics(views, image_size, options);
  for (const vision::ViewError& view : calibration.dropped) {
    report.notes.push_back(fmt::format(
        "{}: reprojection error {:.2f} px, far above the other views': dropped (a blurred photo, "
        "a bent board?)",
        view.name, view.rms_px));
  }

  // An existing camera file keeps its name, mount and vignetting.
  std::string name = request.camera_name;
  camera::Mount mount = kPlaceholderMount;
  camera::Vignetting vignetting;
  std::error_code error;
  if (fs::exists(request.out_path, error)) {
    const camera::CameraModel old = io::LoadCameraFile(request.out_path);
    name = old.name();
    mount = old.mount();
    vignetting = old.vignetting();
    report.notes.push_back(
        fmt::format("{}: intrinsics and distortion replaced; its name, mount and vignetting kept",
                    request.out_path));
  } else {
    report.notes.push_back(fmt::format(
        "{}: new camera file; its mount is a placeholder until `pirouette calibrate mount`, its "
        "vignetting 0 until `pirouette calibrate vignetting`",
        request.out_path));
  }
  const camera::Intrinsics& k = calibration.intrinsics;
  const camera::PlumbBob& d = calibration.distortion;
  constexpr double kPixelStep = 1e-4;
  constexpr double kDistortionStep = 1e-7;
  const camera::CameraModel model(name, image_size.width, image_size.height,
                                  {Rounded(k.fx, kPixelStep), Rounded(k.fy, kPixelStep),
                                   Rounded(k.cx, kPixelStep), Rounded(k.cy, kPixelStep)},
                                  {Rounded(d.k1, kDistortionStep), Rounded(d.k2, kDistortionStep),
                                   Rounded(d.p1, kDistortionStep), Rounded(d.p2, kDistortionStep),
                                   Rounded(d.k3, kDistortionStep)},
                                  mount, vignetting);
  WriteCamera(request.out_path, model);
  if (calibration.rms_px > 1.0) {
    report.notes.push_back(fmt::format(
        "reprojection error {:.2f} px is high (expect well under 1 px): check the photos for blur "
        "and the board for flatness, and --square",
        calibration.rms_px));
  }
  if (calibration.used.size() < 10) {
    report.notes.push_back(fmt::format(
        "only {} views used: 10 to 20, the board tilted differently and reaching every part of the "
        "image, give a more reliable calibration",
        calibration.used.size()));
  }
  report.notes.push_back(fmt::format("wrote {}", request.out_path));

  std::string used_views = "[";
  for (std::size_t i = 0; i < calibration.used.size(); ++i) {
    used_views += fmt::format(R"({}{{"image": {}, "error_px": {:.4f}}})", i == 0 ? "" : ", ",
                              JsonString(calibration.used[i].name), calibration.used[i].rms_px);
  }
  used_views += "]";
  std::string skipped_json = "[";
  for (std::size_t i = 0; i < skipped.size(); ++i) {
    skipped_json += (i == 0 ? "" : ", ") + JsonString(skipped[i]);
  }
  skipped_json += "]";
  std::string dropped_json = "[";
  for (std::size_t i = 0; i < calibration.dropped.size(); ++i) {
    dropped_json +=
        fmt::format(R"({}{{"image": {}, "error_px": {:.4f}}})", i == 0 ? "" : ", ",
                    JsonString(calibration.dropped[i].name), calibration.dropped[i].rms_px);
  }
  dropped_json += "]";
  const double distortion[5] = {d.k1, d.k2, d.p1, d.p2, d.k3};
  report.json = fmt::format(
      "{{\"views_used\": {}, \"views_skipped\": {}, \"views_dropped\": {}, "
      "\"reprojection_error_px\": {:.4f}, \"fx\": {:.4f}, \"fy\": {:.4f}, \"cx\": {:.4f}, "
      "\"cy\": {:.4f}, \"distortion\": {}, \"image_width\": {}, \"image_height\": {}, "
      "\"views\": {}, \"camera\": {}}}\n",
      calibration.used.size(), skipped_json, dropped_json, calibration.rms_px, k.fx, k.fy, k.cx,
      k.cy, JsonNumbers(distortion, 5, 7), image_size.width, image_size.height, used_views,
      JsonString(request.out_path));
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
    vignetting.k[c] = Rounded(fit->vignetting.k[c], 1e-4);
    if (fit->clamped[c]) {
      report.notes.push_back(fmt::format(
          "{}: the {} channel's corners are brighter than its centre: k set to 0 (was the surface "
          "evenly lit?)",
          request.image_path, kChannels[c]));
    }
    if (fit->rms_relative[c] > 0.02) {
      report.notes.push_back(fmt::format(
          "{}: the {} channel departs from the model by {:.1f}% RMS: the surface or its light is "
          "not uniform; the fit may be off",
          request.image_path, kChannels[c], 100.0 * fit->rms_relative[c]));
    }
  }
  WriteCamera(request.camera_path, WithVignetting(camera, vignetting));
  report.notes.push_back(fmt::format("wrote {} (vignetting.k)", request.camera_path));
  report.json = fmt::format(
      "{{\"k\": {}, \"centre_level\": {}, \"rms_relative\": {}, \"blocks_used\": {}, "
      "\"blocks\": {}, \"camera\": {}}}\n",
      JsonNumbers(vignetting.k.data(), 3, 4), JsonNumbers(fit->centre_level.data(), 3, 2),
      JsonNumbers(fit->rms_relative.data(), 3, 5), fit->blocks_used, fit->blocks,
      JsonString(request.camera_path));
  return report;
}

CalibrationReport CalibrateMount(const MountCalibrationRequest& request) {
  const cv::Size pattern = ParseBoardSize(request.board, "--board");
  CheckPositive(request.square_m, "--square", "the squares' side (metres)");
  CheckPositive(request.board_distance_m, "--board-distance",
                "the distance from the robot's centre to the board's centre (metres)");
  if (!(request.board_thickness_m >= 0.0) || !std::isfinite(request.board_thickness_m)) {
    throw core::InputError("--board-thickness", 0, "",
                           fmt::format("must be >= 0, got {}", request.board_thickness_m));
  }
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
  if (!(m.mount.height_m > 0.0) || !(std::abs(m.mount.tilt_rad) < core::DegToRad(89.99))) {
    throw core::InputError(request.image_path, 0, "",
                           fmt::format("the board's pose gives a mount the camera model cannot "
                                       "hold (height {:.4f} m, tilt {:.2f} deg)",
                                       m.mount.height_m, core::RadToDeg(m.mount.tilt_rad)));
  }
  CalibrationReport report;
  const double roll_deg = core::RadToDeg(m.roll_rad);
  if (std::abs(roll_deg) > 2.0) {
    report.notes.push_back(fmt::format(
        "the camera is rolled {:.1f} deg about its axis; the camera model has no roll: level it "
        "on the robot",
        roll_deg));
  }
  if (std::abs(m.board_left_m) > 0.02) {
    report.notes.push_back(fmt::format(
        "the board's centre is {:.3f} m {} of the camera's forward axis: was it on the robot's "
        "axis? (or the camera looks askew)",
        std::abs(m.board_left_m), m.board_left_m > 0 ? "left" : "right"));
  }
  if (m.rms_px > 1.0) {
    report.notes.push_back(fmt::format(
        "the board's corners reproject {:.2f} px off: check the intrinsics (calibrate intrinsics "
        "first) and --square",
        m.rms_px));
  }
  const camera::Mount mount{Rounded(m.mount.height_m, 1e-5),
                            core::DegToRad(Rounded(core::RadToDeg(m.mount.tilt_rad), 1e-3)),
                            Rounded(m.mount.forward_m, 1e-5)};
  WriteCamera(request.camera_path, WithMount(camera, mount));
  report.notes.push_back(fmt::format("wrote {} (mount)", request.camera_path));
  report.json = fmt::format(
      "{{\"height\": {:.5f}, \"tilt_deg\": {:.3f}, \"roll_deg\": {:.3f}, \"forward\": {:.5f}, "
      "\"board_left_m\": {:.5f}, \"reprojection_error_px\": {:.4f}, \"camera\": {}}}\n",
      m.mount.height_m, core::RadToDeg(m.mount.tilt_rad), roll_deg, m.mount.forward_m,
      m.board_left_m, m.rms_px, JsonString(request.camera_path));
  return report;
}

}  // namespace pirouette::tools
