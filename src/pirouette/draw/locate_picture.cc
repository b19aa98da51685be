#include "pirouette/draw/locate_picture.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "pirouette/draw/map_picture.h"
#include "pirouette/draw/palette.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::draw {
namespace {

constexpr int kShift = MapCanvas::kShift;

const cv::Scalar kTruth = Scalar(kTruthColour);
const cv::Scalar kRight = Scalar(kRightColour);
const cv::Scalar kWrong = Scalar(kWrongColour);
const cv::Scalar kCannotTell = Scalar(kCannotTellColour);
const cv::Scalar kHit = Scalar(kHitColour);

}  // namespace

cv::Mat3b DrawLocatePicture(const mapping::TrinaryMap& map,
                            const std::vector<localize::LocateTrial>& trials, double coarse_cell_m,
                            int target_width_px) {
  const core::GridGeometry& g = map.geometry;
  MapCanvas canvas = MapCanvas::OfTrinary(map, target_width_px);
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

  for (const localize::LocateTrial& t : trials) {
    if (t.answer.candidates.empty()) continue;
    const core::Pose2& best = t.answer.world_T_robot;
    const cv::Scalar& colour = !t.answer.found ? kCannotTell : t.right ? kRight : kWrong;
    if (trials.size() == 1) {
      const localize::PlaceView& view = t.seen.view;
      for (std::size_t b = 0; b < view.ranges_m.size() && b < t.seen.kinds.size(); ++b) {
        if (t.seen.kinds[b] != core::ReadingKind::kHit) continue;
        const double bearing = best.heading() + (static_cast<double>(b) + 0.5) * 2.0 *
                                                    std::numbers::pi / mapping::kRadialProfileBins;
        const Eigen::Vector2d p =
            best.translation() +
            view.ranges_m[b] * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
        cv::circle(image, pixel(p), MapCanvas::Fixed(std::max(1, scale / 2)), kHit, cv::FILLED,
                   cv::LINE_AA, kShift);
      }
    }
    if ((best.translation() - t.truth.translation()).norm() > coarse_cell_m) {
      cv::line(image, pixel(t.truth.translation()), pixel(best.translation()), colour,
               std::max(1, scale / 4), cv::LINE_AA, kShift);
    }
    cv::circle(image, pixel(best.translation()), MapCanvas::Fixed(dot), colour, cv::FILLED,
               cv::LINE_AA, kShift);
    tick(best, colour);
  }
  for (const localize::LocateTrial& t : trials) {
    cv::circle(image, pixel(t.truth.translation()), MapCanvas::Fixed(dot + 3), kTruth, 2,
               cv::LINE_AA, kShift);
    tick(t.truth, kTruth);
  }
  return image;
}

}  // namespace pirouette::draw
