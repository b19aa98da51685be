#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string_view>

#include "pirouette/core/pose2.h"
#include "pirouette/sim/ray_caster.h"
#include "pirouette/sim/world.h"
#include "pirouette/vision/floor_segmenter.h"
#include "pirouette/vision/mask_source.h"

namespace pirouette::eval {

// Floor masks of a simulated robot's frames, in the order they are taken (a
// segmenter learns the floor online). Holds a reference to the world.
class FloorMasker {
 public:
  FloorMasker(vision::MaskSource source, const sim::World& world,
              const camera::CameraModel& camera);

  // The mask (255 floor) of a raw BGR frame taken with the robot at
  // world_T_robot; only kTruth looks at the pose.
  cv::Mat1b Mask(const cv::Mat3b& bgr_raw, const core::Pose2& world_T_robot);
  // The segmenter's settling frames (vision::FloorSegmenter::SettlingFrames);
  // 0 for the truth.
  int SettlingFrames() const { return segmenter_ ? segmenter_->SettlingFrames() : 0; }
  // Where the last mask's floor may go on unresolved
  // (vision::FloorSegmenter::Unresolved); empty for the truth.
  const cv::Mat1b& Unresolved() const {
    return segmenter_ ? segmenter_->Unresolved() : vision::NothingUnresolved();
  }

 private:
  vision::MaskSource source_;
  std::unique_ptr<vision::FloorSegmenter> segmenter_;  // unless kTruth
  std::optional<sim::RayCaster> caster_;               // for kTruth
};

}  // namespace pirouette::eval
