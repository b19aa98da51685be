#include "pirouette/eval/floor_masker.h"

#include <algorithm>
#include <vector>

namespace pirouette::eval {

FloorMasker::FloorMasker(vision::MaskSource source, const sim::World& world,
                         const camera::CameraModel& camera)
    : source_(source) {
  if (source == vision::MaskSource::kTruth) {
    caster_.emplace(world, camera);
  } else {
    segmenter_ = vision::MakeFloorSegmenter(source == vision::MaskSource::kPaper
                                                ? vision::SegmentationMethod::kPaper
                                                : vision::SegmentationMethod::kDefault,
                                            camera);
  }
}

cv::Mat1b FloorMasker::Mask(const cv::Mat3b& bgr_raw, const core::Pose2& world_T_robot) {
  if (source_ != vision::MaskSource::kTruth) return segmenter_->Segment(bgr_raw);
  const std::vector<std::uint8_t> truth = caster_->FloorMask(world_T_robot);
  cv::Mat1b mask(caster_->camera().height(), caster_->camera().width());
  std::copy(truth.begin(), truth.end(), mask.begin());
  return mask;
}

}  // namespace pirouette::eval
