#include "pirouette/vision/floor_segmenter.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "pirouette/vision/appearance_segmenter.h"
#include "pirouette/vision/paper_segmenter.h"

namespace pirouette::vision {

const cv::Mat1b& NothingUnresolved() {
  static const cv::Mat1b kNothing;
  return kNothing;
}

const cv::Mat1b& FloorSegmenter::Unresolved() const { return NothingUnresolved(); }

std::optional<SegmentationMethod> ParseSegmentationMethod(std::string_view name) {
  if (name == "paper") return SegmentationMethod::kPaper;
  if (name == "default") return SegmentationMethod::kDefault;
  return std::nullopt;
}

std::string_view SegmentationMethodName(SegmentationMethod method) {
  switch (method) {
    case SegmentationMethod::kPaper:
      return "paper";
    case SegmentationMethod::kDefault:
      return "default";
  }
  return "default";
}

std::unique_ptr<FloorSegmenter> MakeFloorSegmenter(
    SegmentationMethod method, const std::optional<camera::CameraModel>& camera) {
  switch (method) {
    case SegmentationMethod::kPaper:
      return std::make_unique<PaperSegmenter>(camera, PaperSegmenterOptions{});
    case SegmentationMethod::kDefault:
      return std::make_unique<AppearanceSegmenter>(camera, AppearanceSegmenterOptions{});
  }
  return nullptr;
}

cv::Mat1b ReferenceRegionMask(cv::Size size, const ReferenceRegion& region) {
  cv::Mat1b mask(size, std::uint8_t{0});
  const int bottom = size.height - 1 - region.margin;
  const int rows = std::max(1, static_cast<int>(std::lround(region.height * size.height)));
  const int top = std::max(0, bottom - rows + 1);
  for (int v = top; v <= bottom; ++v) {
    const double t = rows > 1 ? static_cast<double>(bottom - v) / (rows - 1) : 0.0;
    const double width = region.bottom_width + t * (region.top_width - region.bottom_width);
    const double half = 0.5 * width * size.width;
    const double centre = 0.5 * (size.width - 1);
    const int u0 = std::max(0, static_cast<int>(std::ceil(centre - half)));
    const int u1 = std::min(size.width - 1, static_cast<int>(std::floor(centre + half)));
    for (int u = u0; u <= u1; ++u) mask(v, u) = 255;
  }
  return mask;
}

cv::Mat3b PrepareFrame(const cv::Mat3b& bgr_raw,
                       const std::optional<VignettingCorrector>& corrector,
                       std::optional<VerticalDirectionField>& vertical, double blur_sigma) {
  CV_Assert(!bgr_raw.empty());
  if (corrector) {
    CV_Assert(bgr_raw.cols == corrector->width() && bgr_raw.rows == corrector->height());
  } else if (!vertical || vertical->width() != bgr_raw.cols || vertical->height() != bgr_raw.rows) {
    vertical.emplace(bgr_raw.cols, bgr_raw.rows);
  }
  cv::Mat3b corrected = corrector ? corrector->Apply(bgr_raw) : bgr_raw;
  if (blur_sigma <= 0.0) return corrected;
  cv::Mat3b blurred;
  cv::GaussianBlur(corrected, blurred, cv::Size(), blur_sigma);
  return blurred;
}

}  // namespace pirouette::vision
