#pragma once

#include <array>
#include <optional>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/vision/edge_map.h"
#include "pirouette/vision/floor_colour_model.h"
#include "pirouette/vision/floor_segmenter.h"
#include "pirouette/vision/vertical_direction_field.h"
#include "pirouette/vision/vignetting_corrector.h"

namespace pirouette::vision {

struct AppearanceSegmenterOptions {
  double blur_sigma = 1.0;  // the Gaussian low-pass, pixels
  FloorColourModelOptions colour;
  // Tuned on photos 0–69: wide at the bottom, narrow at its top.
  ReferenceRegion reference{0.2, 0.6, 0.15, 2};
  // A pixel can be floor where the colour model's likelihood is at least this...
  double colour_threshold = 0.1;
  // ...and the texture histogram's likelihood is at least this.
  double texture_threshold = 0.1;
  int texture_window = 5;  // the side of the window the texture feature averages over
  // Whether the non-vertical Canny edges bound the floor (they stop the
  // connected component as they stop the paper's fill).
  bool use_edges = true;
  // Tuned on photos 0–69: stronger edges only, and a tighter vertical test.
  EdgeMapOptions edges{60.0, 180.0, 5.0};
  // Floor-coloured components touching the bottom rows (this many above the
  // reference region's margin) are floor too, as the paper searches the bottom
  // rows for a seed: an obstacle right in front may cover the reference region.
  int bottom_rows = 6;
  int close_size = 9;  // side of the closing that fills pinholes in the floor; 0 for none
  // The texture window and the low-pass blur the floor's edge: the floor then
  // grows back, a pixel at a time up to this many, into floor-coloured pixels
  // (colour judged on the frame low-passed by grow_blur_sigma only) until a
  // non-vertical edge stops it, so the boundary lies on the edge.
  int grow_steps = 8;
  double grow_blur_sigma = 0.7;
  // Refinement passes within the frame: the floor's colours against the
  // rest's (see Segment); a pixel passes where the floor's density is at least
  // refine_ratio times the rest's.
  int refine_passes = 1;
  double refine_ratio = 0.7;
  // The first model is chosen by the first pirouette, not the first frame: for
  // this many frames (12, one pirouette) each reference region's colours are
  // kept, and when more of them agree on another appearance than on the
  // model's, the model is learnt afresh from those (see Segment). 0 turns it off.
  int bootstrap_frames = 12;
  // Two reference regions agree when each one's colour model calls at least
  // this share of the other's pixels floor-coloured (at colour_threshold).
  double bootstrap_agreement = 0.8;
};

// The default segmenter, after Ulrich & Nourbakhsh (2000), "Appearance-based
// obstacle detection with monocular color vision": the floor's appearance is
// learnt online from a trapezoid in front of the robot (the reference region)
// and a pixel is floor where its appearance is common there. Appearance is
// colour (FloorColourModel: L*a*b* histogram) and a simple texture feature
// (the local mean gradient magnitude, histogrammed on a log scale); both must
// be common. The candidate floor is cut by the non-vertical Canny edges, as in
// the paper (near-vertical edges, the sides of obstacles, do not cut it: they
// are left out of the boundary), and the floor is the part connected to the
// reference region or to the bottom rows, closed and grown back to the edges. A refinement pass
// then weighs, within the frame, the colours of the floor just found against those of the rest (the
// two-class idea of GrabCut, with histograms and no graph cut), which removes colours the reference
// region shares with walls. Later frames learn from the part of the reference region found floor,
// with exponential forgetting, so the model follows the light and an obstacle right in front of the
// robot is not learnt as floor. The first frame alone may be filled by an
// obstacle (a wall a few cm away), so over the first pirouette the model
// follows the appearance most reference regions agree on, the majority vote of
// the paper's assumption that the reference region is floor.
class AppearanceSegmenter : public FloorSegmenter {
 public:
  AppearanceSegmenter(const std::optional<camera::CameraModel>& camera,
                      const AppearanceSegmenterOptions& options);

  cv::Mat1b Segment(const cv::Mat3b& bgr_raw) override;

  const FloorColourModel& colour_model() const { return colour_; }

 private:
  static constexpr int kTextureBins = 16;

  cv::Mat1b TextureBins(const cv::Mat1b& grey) const;
  using TextureHistogram = std::array<double, kTextureBins>;
  // The normalised histogram of `bins` in `region`; nullopt when it is empty.
  static std::optional<TextureHistogram> HistogramOf(const cv::Mat1b& bins,
                                                     const cv::Mat1b& region);
  void LearnTexture(const cv::Mat1b& bins, const cv::Mat1b& region);
  void LearnTexture(const TextureHistogram& frame);
  // Keeps the reference region's appearance during the first pirouette and
  // relearns the model when most regions so far agree on another appearance.
  void Bootstrap(const cv::Mat3b& blurred, const cv::Mat1b& texture, const cv::Mat1b& reference);

  // One reference region's appearance, kept while bootstrapping.
  struct ReferenceSample {
    std::vector<double> colour;  // FloorColourModel::Histogram
    TextureHistogram texture{};
    FloorColourModel model;  // learnt from `colour` alone
  };

  AppearanceSegmenterOptions options_;
  std::optional<VignettingCorrector> corrector_;
  std::optional<VerticalDirectionField> vertical_;
  FloorColourModel colour_;
  bool texture_learnt_ = false;
  std::array<double, kTextureBins> texture_histogram_{};
  std::array<float, kTextureBins> texture_likelihood_{};
  int frames_seen_ = 0;
  std::vector<ReferenceSample> samples_;      // while bootstrapping
  std::vector<std::vector<bool>> agreement_;  // agreement_[i][j]: samples i and j agree
};

}  // namespace pirouette::vision
