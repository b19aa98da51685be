#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string_view>

#include "pirouette/camera/camera_model.h"
#include "pirouette/vision/vertical_direction_field.h"
#include "pirouette/vision/vignetting_corrector.h"

namespace pirouette::vision {

// Decides which pixels of a camera frame are floor. A segmenter learns the
// floor's appearance online from the frames it is given, in order (the first
// ones: the robot's first pirouette), so it has state; it is deterministic: the
// same frames in the same order give the same masks.
class FloorSegmenter {
 public:
  virtual ~FloorSegmenter() = default;

  // The floor mask of a raw frame (BGR, as the camera gives it: distorted and
  // vignetted): 255 floor, 0 not, the frame's size. With a camera, the frame
  // must have the camera's size (callers check input; a mismatch is a bug).
  virtual cv::Mat1b Segment(const cv::Mat3b& bgr_raw) = 0;

  // How many first frames the segmenter learns the floor's appearance from
  // before its masks hold (0: from the first). A run's first frames are its
  // first pirouette: their masks are to be made again once it has seen them
  // all (run::FrameMapper does).
  virtual int SettlingFrames() const { return 0; }

  // Where the last frame Segment was given may show more floor that the
  // segmenter could not resolve: 255 at pixels that are not floor in its
  // mask but whose floor cannot be ruled out (see AppearanceSegmenter), 0
  // elsewhere; the frame's size, or empty when there are none (always, for a
  // segmenter that does not say). ProfileExtractor reads a column whose floor
  // ends at such a pixel as seen free to there, not as an obstacle's base.
  // Valid until the next Segment.
  virtual const cv::Mat1b& Unresolved() const;
};

// An empty mask: nothing unresolved (FloorSegmenter::Unresolved's default).
const cv::Mat1b& NothingUnresolved();

enum class SegmentationMethod {
  kPaper,    // Taylor, Geva & Boles 2005: low-pass, Canny, flood fill from the bottom
  kDefault,  // floor appearance (colour + texture) learnt online, with edges
};

// "paper" | "default"; nullopt for any other name.
std::optional<SegmentationMethod> ParseSegmentationMethod(std::string_view name);
std::string_view SegmentationMethodName(SegmentationMethod method);

// A segmenter of the method with its default options. With a camera, frames
// are corrected for vignetting and near-vertical edges are judged by the
// camera's geometry; without one (a photo of unknown geometry) the frame is
// used as is and vertical means up the image.
std::unique_ptr<FloorSegmenter> MakeFloorSegmenter(
    SegmentationMethod method, const std::optional<camera::CameraModel>& camera);

// Where the floor is sampled: a trapezoid in front of the robot at the bottom
// centre of the image (Ulrich & Nourbakhsh 2000), as fractions of the image.
struct ReferenceRegion {
  double height = 0.2;        // of the image's height, up from the bottom row
  double bottom_width = 0.5;  // of the image's width, at the bottom row
  double top_width = 0.3;     // of the image's width, at the region's top row
  int margin = 2;             // rows left out at the very bottom (lens and sensor border)
};

// The first steps every segmenter takes on a raw frame. With a corrector (a
// known camera) the frame must have the camera's size and is corrected for
// vignetting; without one, `vertical` is (re)built as "up the image" for the
// frame's size. Then a Gaussian low-pass of `blur_sigma` pixels (none when
// <= 0). Returns the corrected, low-passed frame.
cv::Mat3b PrepareFrame(const cv::Mat3b& bgr_raw,
                       const std::optional<VignettingCorrector>& corrector,
                       std::optional<VerticalDirectionField>& vertical, double blur_sigma);

// The reference region's mask (255 inside) for an image of `size`.
cv::Mat1b ReferenceRegionMask(cv::Size size, const ReferenceRegion& region);

}  // namespace pirouette::vision
