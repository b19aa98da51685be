#include "pirouette/tools/segment.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/input_error.h"
#include "pirouette/draw/floor_overlay.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/vision/profile_extractor.h"

namespace pirouette::tools {

SegmentImageResult SegmentImage(const SegmentImageRequest& request) {
  const cv::Mat3b bgr = io::ToBgrMat(io::ReadImage(request.image_path));
  std::optional<camera::CameraModel> camera;
  if (!request.camera_path.empty()) {
    camera = io::LoadCameraFile(request.camera_path);
    if (camera->width() != bgr.cols || camera->height() != bgr.rows) {
      throw core::InputError(
          request.image_path, 0, "",
          fmt::format("the image is {}×{} but the camera {} is {}×{}", bgr.cols, bgr.rows,
                      request.camera_path, camera->width(), camera->height()));
    }
  }
  if (request.max_range_m && !(*request.max_range_m > 0.0)) {
    throw core::InputError("", 0, "max-range", "must be a positive number of metres");
  }
  auto segmenter = vision::MakeFloorSegmenter(request.method, camera);
  SegmentImageResult result;
  result.floor_mask = segmenter->Segment(bgr);
  if (camera) {
    const camera::InversePerspectiveMap ipm(*camera);
    const double max_range = request.max_range_m.value_or(camera::MaxRange(*camera, 0.01));
    result.profile = vision::ExtractProfile(result.floor_mask, ipm, max_range);
  }
  if (!request.mask_path.empty()) io::WritePng(request.mask_path, result.floor_mask);
  if (!request.overlay_path.empty()) {
    io::WritePng(request.overlay_path, draw::DrawFloorOverlay(bgr, result.floor_mask));
  }
  return result;
}

std::string ObstacleProfileJson(const core::ObstacleProfile& profile) {
  std::string out =
      fmt::format("{{\n  \"max_range_m\": {:.4f},\n  \"readings\": [", profile.max_range_m);
  for (std::size_t i = 0; i < profile.readings.size(); ++i) {
    const core::RangeReading& r = profile.readings[i];
    const char* kind = r.kind == core::ReadingKind::kHit     ? "hit"
                       : r.kind == core::ReadingKind::kClear ? "clear"
                                                             : "blind";
    out +=
        fmt::format("{}\n    {{\"bearing_deg\": {:.3f}, \"range_m\": {:.4f}, \"kind\": \"{}\"}}",
                    i == 0 ? "" : ",", r.bearing_rad * 180.0 / std::numbers::pi, r.range_m, kind);
  }
  out += "\n  ]\n}\n";
  return out;
}

}  // namespace pirouette::tools
