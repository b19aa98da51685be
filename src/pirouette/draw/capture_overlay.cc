#include "pirouette/draw/capture_overlay.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "pirouette/draw/floor_overlay.h"
#include "pirouette/draw/palette.h"

namespace pirouette::draw {
namespace {

constexpr int kStripHeight = 48;    // the range bars, pixels
constexpr int kCaptionLine = 16;    // one caption line, pixels
constexpr double kFontScale = 0.9;  // cv::FONT_HERSHEY_PLAIN

// Writes `text` from `x` on the caption line whose baseline is `y`; returns
// the x after it.
int PutText(cv::Mat3b& image, const std::string& text, int x, int y, const cv::Vec3b& colour) {
  cv::putText(image, text, cv::Point(x, y), cv::FONT_HERSHEY_PLAIN, kFontScale,
              cv::Scalar(colour[0], colour[1], colour[2]), 1, cv::LINE_AA);
  int baseline = 0;
  return x + cv::getTextSize(text, cv::FONT_HERSHEY_PLAIN, kFontScale, 1, &baseline).width;
}

// The pixel where the floor point of reading `r` (robot frame) appears.
std::optional<Eigen::Vector2d> PixelOf(const core::RangeReading& r,
                                       const camera::CameraModel& camera,
                                       const Eigen::Isometry3d& camera_T_robot) {
  const Eigen::Vector2d p = core::PointOf(r);
  return camera.Project(camera_T_robot * Eigen::Vector3d(p.x(), p.y(), 0.0));
}

}  // namespace

std::vector<int> ReadingRows(const core::ObstacleProfile& profile,
                             const camera::CameraModel& camera) {
  const Eigen::Isometry3d camera_T_robot = camera.robot_T_camera().inverse();
  std::vector<int> rows;
  rows.reserve(profile.readings.size());
  for (const core::RangeReading& r : profile.readings) {
    const std::optional<Eigen::Vector2d> pixel = PixelOf(r, camera, camera_T_robot);
    if (!pixel) {
      rows.push_back(-1);
      continue;
    }
    const long row = std::lround(pixel->y());
    rows.push_back(static_cast<int>(std::clamp<long>(row, 0, camera.height() - 1)));
  }
  return rows;
}

std::vector<cv::Point> FootPixels(const core::ObstacleProfile& profile,
                                  const camera::CameraModel& camera) {
  const Eigen::Isometry3d camera_T_robot = camera.robot_T_camera().inverse();
  std::vector<cv::Point> pixels;
  for (const core::RangeReading& foot : profile.feet) {
    const std::optional<Eigen::Vector2d> pixel = PixelOf(foot, camera, camera_T_robot);
    if (!pixel) continue;
    const cv::Point p(static_cast<int>(std::lround(pixel->x())),
                      static_cast<int>(std::lround(pixel->y())));
    if (p.x >= 0 && p.y >= 0 && p.x < camera.width() && p.y < camera.height()) {
      pixels.push_back(p);
    }
  }
  return pixels;
}

cv::Mat3b DrawCaptureOverlay(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask,
                             const CaptureCaption& caption,
                             const std::optional<core::ObstacleProfile>& profile,
                             const std::vector<int>& reading_rows,
                             const std::vector<cv::Point>& foot_pixels) {
  CV_Assert(!profile || (profile->readings.size() == static_cast<std::size_t>(bgr.cols) &&
                         reading_rows.size() == profile->readings.size()));
  const int scale = std::max(1, (kMinOverlayWidth + bgr.cols - 1) / bgr.cols);
  cv::Mat3b view;
  cv::resize(DrawFloorOverlay(bgr, floor_mask), view, cv::Size(), scale, scale, cv::INTER_NEAREST);
  const int width = view.cols;
  const int strip = profile ? kStripHeight : 0;
  const int caption_height = 2 * kCaptionLine + 4;
  cv::Mat3b out(view.rows + strip + caption_height, width, kPanelColour);
  view.copyTo(out(cv::Rect(0, 0, width, view.rows)));

  if (profile) {
    const int bottom = bgr.rows - 1;
    for (int u = 0; u < bgr.cols; ++u) {
      const core::RangeReading& r = profile->readings[u];
      const int row = r.kind == core::ReadingKind::kBlind ? bottom : reading_rows[u];
      if (row < 0) continue;
      // A mark two frame pixels high, centred on the reading's row.
      const int y0 = std::clamp(row * scale - scale / 2, 0, view.rows - 2 * scale);
      out(cv::Rect(u * scale, y0, scale, 2 * scale)).setTo(KindColour(r.kind));
    }
    // A foot: a ring two frame pixels across, round the foot's pixel.
    const cv::Vec3b& hit = KindColour(core::ReadingKind::kHit);
    for (const cv::Point& foot : foot_pixels) {
      if (foot.x < 0 || foot.y < 0 || foot.x >= bgr.cols || foot.y >= bgr.rows) continue;
      const cv::Point centre(foot.x * scale + scale / 2, foot.y * scale + scale / 2);
      cv::circle(out, centre, 2 * scale, cv::Scalar(hit[0], hit[1], hit[2]), 1, cv::LINE_AA);
    }
    // The range strip: a bar a column, full height at the maximum range.
    const int top = view.rows;
    const int bar_max = kStripHeight - 4;
    for (int u = 0; u < bgr.cols; ++u) {
      const core::RangeReading& r = profile->readings[u];
      const double fraction = std::clamp(r.range_m / profile->max_range_m, 0.0, 1.0);
      const int h = static_cast<int>(std::lround(fraction * bar_max));
      if (h <= 0) continue;
      out(cv::Rect(u * scale, top + kStripHeight - h, scale, h)).setTo(KindColour(r.kind));
    }
    out(cv::Rect(0, top + kStripHeight - bar_max - 1, width, 1)).setTo(kRuleColour);
    PutText(out, fmt::format("{:.2f} m", profile->max_range_m), 2, top + 12, kTextColour);
  }

  const int line1 = view.rows + strip + kCaptionLine;
  const int line2 = line1 + kCaptionLine;
  PutText(out,
          fmt::format("#{:06d} floor {:.0f}% ref {:.0f}%", caption.index,
                      100.0 * caption.floor_fraction, 100.0 * caption.reference_fraction),
          2, line1, kTextColour);
  if (caption.counts) {
    int x = PutText(out, fmt::format("hit {}", caption.counts->hit), 2, line2, kHitColour);
    x = PutText(out, fmt::format(" clear {}", caption.counts->clear), x, line2, kClearColour);
    x = PutText(out, fmt::format(" blind {}", caption.counts->blind), x, line2, kBlindColour);
    if (caption.counts->feet > 0) {
      x = PutText(out, fmt::format(" feet {}", caption.counts->feet), x, line2, kHitColour);
    }
    if (caption.counts->nearest_hit_m) {
      PutText(out, fmt::format(" near {:.2f} m", *caption.counts->nearest_hit_m), x, line2,
              kTextColour);
    }
  } else {
    PutText(out, "no camera: no profile", 2, line2, kTextColour);
  }
  return out;
}

}  // namespace pirouette::draw
