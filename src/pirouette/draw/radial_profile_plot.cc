#include "pirouette/draw/radial_profile_plot.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "pirouette/core/angle.h"
#include "pirouette/draw/palette.h"

namespace pirouette::draw {
namespace {

constexpr int kShift = 4;  // OpenCV's fractional bits for anti-aliased drawing
constexpr double kOne = 1 << kShift;

const cv::Scalar kGrid = Scalar(kGridColour);
const cv::Scalar kLabel = Scalar(kLabelColour);
const cv::Scalar kLowPass = Scalar(kLowPassColour);
const cv::Scalar kTruth = Scalar(kTruthColour);

// The bin's centre bearing, radians.
double BinBearing(int bin) {
  return core::DegToRad((bin + 0.5) * 360.0 / mapping::kRadialProfileBins);
}

// Maps a polar point of the plot to fixed-point pixels.
struct Polar {
  cv::Point2d centre;
  double px_per_m = 1.0;
  cv::Point At(double range_m, double bearing_rad) const {
    return {static_cast<int>(
                std::lround((centre.x + px_per_m * range_m * std::cos(bearing_rad)) * kOne)),
            static_cast<int>(
                std::lround((centre.y - px_per_m * range_m * std::sin(bearing_rad)) * kOne))};
  }
};

void DrawClosedCurve(cv::Mat3b& image, const Polar& polar, const std::vector<double>& ranges,
                     const cv::Scalar& colour, int thickness) {
  const int n = static_cast<int>(ranges.size());
  for (int b = 0; b < n; ++b) {
    const int next = (b + 1) % n;
    cv::line(image, polar.At(ranges[static_cast<std::size_t>(b)], BinBearing(b)),
             polar.At(ranges[static_cast<std::size_t>(next)], BinBearing(next)), colour, thickness,
             cv::LINE_AA, kShift);
  }
}

}  // namespace

cv::Mat3b PlotRadialProfile(const mapping::RadialProfile& rop, const std::vector<double>& low_pass,
                            const std::vector<double>& truth, const std::string& title,
                            int size_px) {
  cv::Mat3b image(size_px, size_px, kWhite);
  const double plot_range = std::max(0.1, std::ceil(rop.max_range_m * 1.1 * 10.0) / 10.0);
  const Polar polar{{size_px / 2.0, size_px / 2.0 + 10.0}, 0.42 * size_px / plot_range};
  const auto font = cv::FONT_HERSHEY_SIMPLEX;
  // Rings every 10 cm, spokes every 30°.
  for (int ring = 1; ring * 0.1 <= plot_range + 1e-9; ++ring) {
    cv::circle(image, polar.At(0.0, 0.0),
               static_cast<int>(std::lround(ring * 0.1 * polar.px_per_m * kOne)), kGrid, 1,
               cv::LINE_AA, kShift);
    const cv::Point label = polar.At(ring * 0.1, core::DegToRad(75.0));
    cv::putText(image, fmt::format("{} cm", ring * 10), {label.x >> kShift, label.y >> kShift},
                font, 0.35, kLabel, 1, cv::LINE_AA);
  }
  for (int degrees = 0; degrees < 360; degrees += 30) {
    const double bearing = core::DegToRad(degrees);
    cv::line(image, polar.At(0.0, bearing), polar.At(plot_range, bearing), kGrid, 1, cv::LINE_AA,
             kShift);
    const cv::Point label = polar.At(plot_range * 1.08, bearing);
    cv::putText(image, fmt::format("{}", degrees),
                {(label.x >> kShift) - 10, (label.y >> kShift) + 4}, font, 0.4, kLabel, 1,
                cv::LINE_AA);
  }
  // The max range, dashed.
  for (int degrees = 0; degrees < 360; degrees += 4) {
    cv::line(image, polar.At(rop.max_range_m, core::DegToRad(degrees)),
             polar.At(rop.max_range_m, core::DegToRad(degrees + 2)), kLabel, 1, cv::LINE_AA,
             kShift);
  }
  if (!truth.empty()) DrawClosedCurve(image, polar, truth, kTruth, 1);
  // The ROP, thick, each bin's arc in its kind's colour.
  const int n = static_cast<int>(rop.bins.size());
  for (int b = 0; b < n; ++b) {
    const mapping::RadialBin& bin = rop.bins[static_cast<std::size_t>(b)];
    const mapping::RadialBin& next = rop.bins[static_cast<std::size_t>((b + 1) % n)];
    const cv::Scalar colour = bin.readings == 0 ? kGrid : Scalar(KindColour(bin.kind));
    cv::line(image, polar.At(bin.range_m, BinBearing(b)),
             polar.At(next.range_m, BinBearing((b + 1) % n)), colour, 3, cv::LINE_AA, kShift);
  }
  DrawClosedCurve(image, polar, low_pass, kLowPass, 1);
  // The robot's centre.
  cv::circle(image, polar.At(0.0, 0.0), static_cast<int>(3 * kOne), kLowPass, cv::FILLED,
             cv::LINE_AA, kShift);
  // Title and legend.
  cv::putText(image, title, {10, 20}, font, 0.45, kLowPass, 1, cv::LINE_AA);
  int y = size_px - 62;
  const auto legend = [&](const cv::Scalar& colour, int thickness, const std::string& text) {
    cv::line(image, {10, y - 4}, {40, y - 4}, colour, thickness, cv::LINE_AA);
    cv::putText(image, text, {48, y}, font, 0.4, kLowPass, 1, cv::LINE_AA);
    y += 16;
  };
  legend(Scalar(kHitColour), 3, "ROP: hit  (azure: clear, amber: blind)");
  legend(kLowPass, 1,
         fmt::format("DCT low-pass, first {} coefficients", mapping::kRadialProfileCoefficients));
  if (!truth.empty()) legend(kTruth, 1, "truth: the world's geometry");
  legend(kLabel, 1, fmt::format("max range {:.3f} m (dashed)", rop.max_range_m));
  return image;
}

}  // namespace pirouette::draw
