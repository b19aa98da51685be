#include "pirouette/tools/segment.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/draw/floor_overlay.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/tools/json_output.h"
#include "pirouette/vision/profile_extractor.h"
#include "pirouette/vision/vertical_direction_field.h"

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
    const vision::VerticalDirectionField vertical(*camera);
    const double max_range =
        request.max_range_m.value_or(camera::MaxRange(*camera, mapping::kSmallRobotCellM));
    result.profile = vision::ExtractProfile(result.floor_mask, ipm, max_range,
                                            segmenter->Unresolved(), &vertical);
  }
  if (!request.mask_path.empty()) io::WritePng(request.mask_path, result.floor_mask);
  if (!request.overlay_path.empty()) {
    io::WritePng(request.overlay_path, draw::DrawFloorOverlay(bgr, result.floor_mask));
  }
  return result;
}

std::string ObstacleProfileJson(const core::ObstacleProfile& profile) {
  nlohmann::ordered_json readings = nlohmann::ordered_json::array();
  for (const core::RangeReading& r : profile.readings) {
    readings.push_back({{"bearing_deg", RoundTo(core::RadToDeg(r.bearing_rad), 3)},
                        {"range_m", RoundTo(r.range_m, 4)},
                        {"kind", ReadingKindName(r.kind)}});
  }
  nlohmann::ordered_json json;
  json["max_range_m"] = RoundTo(profile.max_range_m, 4);
  json["readings"] = std::move(readings);
  return JsonText(json, 2);
}

}  // namespace pirouette::tools
