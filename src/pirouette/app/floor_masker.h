#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string_view>

#include "pirouette/core/pose2.h"
#include "pirouette/sim/ray_caster.h"
#include "pirouette/sim/world.h"
#include "pirouette/vision/floor_segmenter.h"

namespace pirouette::app {

// Where the floor masks of simulated frames come from: one of vision's
// segmenters, or the simulator's truth (the ray caster's mask, to measure
// the profile extraction alone).
enum class MaskSource { kPaper, kDefault, kTruth };

// "paper" | "default" | "truth"; nullopt for any other name.
std::optional<MaskSource> ParseMaskSource(std::string_view name);
std::string_view MaskSourceName(MaskSource source);

// Floor masks of a simulated robot's frames, in the order they are taken (a
// segmenter learns the floor online). Holds a reference to the world.
class FloorMasker {
 public:
  FloorMasker(MaskSource source, const sim::World& world, const camera::CameraModel& camera);

  // The mask (255 floor) of a raw BGR frame taken with the robot at
  // world_T_robot; only kTruth looks at the pose.
  cv::Mat1b Mask(const cv::Mat3b& bgr_raw, const core::Pose2& world_T_robot);

 private:
  MaskSource source_;
  std::unique_ptr<vision::FloorSegmenter> segmenter_;  // unless kTruth
  std::optional<sim::RayCaster> caster_;               // for kTruth
};

}  // namespace pirouette::app
