#include "pirouette/app/map_picture.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace pirouette::app {
namespace {

constexpr int kShift = 4;  // OpenCV's fractional bits for anti-aliased drawing
constexpr double kOne = 1 << kShift;

const cv::Scalar kPathColour(200, 90, 20);   // blue (BGR)
const cv::Scalar kStopColour(0, 140, 255);   // orange
const cv::Scalar kStartColour(40, 170, 40);  // green
const cv::Scalar kRobotColour(30, 30, 220);  // red

}  // namespace

cv::Mat3b DrawMapPicture(const mapping::OccupancyGrid& grid, const std::vector<core::Pose2>& path,
                         const std::vector<core::Pose2>& stops, int target_width_px) {
  const core::GridGeometry& g = grid.geometry();
  const int scale = std::max(1, target_width_px / g.width());
  cv::Mat3b cells(g.height(), g.width());
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const core::CellIndex c{x, y};
      std::uint8_t v = 160;  // unknown
      if (grid.Known(c)) {
        v = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - grid.Probability(c))));
      }
      cells(g.height() - 1 - y, x) = cv::Vec3b(v, v, v);
    }
  }
  cv::Mat3b image;
  cv::resize(cells, image, {}, scale, scale, cv::INTER_NEAREST);
  const auto pixel = [&](const Eigen::Vector2d& p) {
    const double u = (p.x() - g.origin().x()) / g.resolution() * scale;
    const double v = (g.height() - (p.y() - g.origin().y()) / g.resolution()) * scale;
    return cv::Point(static_cast<int>(std::lround(u * kOne)),
                     static_cast<int>(std::lround(v * kOne)));
  };
  const int thickness = std::max(1, scale / 2);
  for (std::size_t i = 1; i < path.size(); ++i) {
    cv::line(image, pixel(path[i - 1].translation()), pixel(path[i].translation()), kPathColour,
             thickness, cv::LINE_AA, kShift);
  }
  const int dot = std::max(3, 2 * scale);
  for (const core::Pose2& stop : stops) {
    cv::circle(image, pixel(stop.translation()), static_cast<int>(dot * kOne), kStopColour,
               cv::FILLED, cv::LINE_AA, kShift);
  }
  if (!path.empty()) {
    cv::circle(image, pixel(path.front().translation()), static_cast<int>((dot + 2) * kOne),
               kStartColour, 2, cv::LINE_AA, kShift);
    const core::Pose2& last = path.back();
    const double arrow_m = 3.0 * dot * g.resolution() / scale;
    cv::circle(image, pixel(last.translation()), static_cast<int>((dot + 1) * kOne), kRobotColour,
               cv::FILLED, cv::LINE_AA, kShift);
    cv::line(image, pixel(last.translation()),
             pixel(last.translation() + arrow_m * last.Direction()), kRobotColour, thickness + 1,
             cv::LINE_AA, kShift);
  }
  return image;
}

}  // namespace pirouette::app
