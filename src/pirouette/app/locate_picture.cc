#include "pirouette/app/locate_picture.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "pirouette/app/map_picture.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::app {
namespace {

constexpr int kShift = MapCanvas::kShift;

const cv::Scalar kTruthColour(40, 170, 40);   // green (BGR)
const cv::Scalar kRightColour(200, 90, 20);   // blue
const cv::Scalar kWrongColour(30, 30, 220);   // red
const cv::Scalar kCannotColour(0, 140, 255);  // orange
const cv::Scalar kHitColour(255, 220, 0);     // cyan

}  // namespace

cv::Mat3b DrawLocatePicture(const LocateResult& result, int target_width_px) {
  if (!result.map) throw std::invalid_argument("DrawLocatePicture: the result has no map");
  const mapping::TrinaryMap& map = *result.map;
  const core::GridGeometry& g = map.geometry;
  MapCanvas canvas = MapCanvas::Of(
      g,
      [&](const core::CellIndex& c) -> std::uint8_t {
        const mapping::CellState s = map.At(c);
        return s == mapping::CellState::kFree ? 255 : s == mapping::CellState::kOccupied ? 0 : 160;
      },
      target_width_px);
  cv::Mat3b& image = canvas.image;
  const int scale = canvas.scale;
  const auto pixel = [&](const Eigen::Vector2d& p) { return canvas.Pixel(p); };
  const int dot = std::max(3, 2 * scale);
  const double tick_m = 3.0 * dot * g.resolution() / scale;
  const int thickness = std::max(1, scale / 2);
  const auto tick = [&](const core::Pose2& pose, const cv::Scalar& colour) {
    cv::line(image, pixel(pose.translation()),
             pixel(pose.translation() + tick_m * pose.Direction()), colour, thickness + 1,
             cv::LINE_AA, kShift);
  };

  for (const localize::LocateTrial& t : result.trials) {
    if (t.answer.candidates.empty()) continue;
    const core::Pose2& best = t.answer.world_T_robot;
    const cv::Scalar& colour = !t.answer.found ? kCannotColour
                               : t.right       ? kRightColour
                                               : kWrongColour;
    if (result.trials.size() == 1) {
      const localize::PlaceView& view = t.seen.view;
      for (std::size_t b = 0; b < view.ranges_m.size() && b < t.seen.kinds.size(); ++b) {
        if (t.seen.kinds[b] != core::ReadingKind::kHit) continue;
        const double bearing = best.heading() + (static_cast<double>(b) + 0.5) * 2.0 *
                                                    std::numbers::pi / mapping::kRadialProfileBins;
        const Eigen::Vector2d p =
            best.translation() +
            view.ranges_m[b] * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
        cv::circle(image, pixel(p), MapCanvas::Fixed(std::max(1, scale / 2)), kHitColour,
                   cv::FILLED, cv::LINE_AA, kShift);
      }
    }
    if ((best.translation() - t.truth.translation()).norm() > result.coarse_cell_m) {
      cv::line(image, pixel(t.truth.translation()), pixel(best.translation()), colour,
               std::max(1, scale / 4), cv::LINE_AA, kShift);
    }
    cv::circle(image, pixel(best.translation()), MapCanvas::Fixed(dot), colour, cv::FILLED,
               cv::LINE_AA, kShift);
    tick(best, colour);
  }
  for (const localize::LocateTrial& t : result.trials) {
    cv::circle(image, pixel(t.truth.translation()), MapCanvas::Fixed(dot + 3), kTruthColour, 2,
               cv::LINE_AA, kShift);
    tick(t.truth, kTruthColour);
  }
  return image;
}

}  // namespace pirouette::app
