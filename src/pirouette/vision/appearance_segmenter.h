#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/vision/edge_map.h"
#include "pirouette/vision/floor_colour_model.h"
#include "pirouette/vision/floor_segmenter.h"
#include "pirouette/vision/mask_morphology.h"
#include "pirouette/vision/texture_feature.h"
#include "pirouette/vision/vertical_direction_field.h"
#include "pirouette/vision/vignetting_corrector.h"

namespace pirouette::vision {

struct AppearanceSegmenterOptions {
  // The segmenter works on the frame reduced by the integer factor
  // s = max(1, width / working_width), each cell the mean of s × s pixels: the
  // pixel sizes below (in cells, then) were tuned on 160×120 photos, and most
  // of the work then scales with the cells, not the pixels. The texture is measured at full
  // resolution, and the floor's boundary is placed to the pixel at the end
  // (UpsampleFloorMask). 0: the frame's own resolution.
  int working_width = 160;
  double blur_sigma = 1.0;  // the Gaussian low-pass, pixels (a binomial kernel: BinomialOrder)
  FloorColourModelOptions colour;
  // Tuned on photos 0–69: wide at the bottom, narrow at its top.
  ReferenceRegion reference{0.2, 0.6, 0.15, 2};
  // A pixel can be floor where the colour model's likelihood is at least this...
  double colour_threshold = 0.1;
  // ...and the texture histogram's likelihood is at least this.
  double texture_threshold = 0.1;
  // The side of the window the texture feature averages over (TextureFeature).
  int texture_window = 5;
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
  // The floor starts only from seed cells (the reference region and the
  // bottom rows) whose colour and texture are typical of the floor, not
  // merely possible: likelihoods at least these (the tests above then let the
  // floor grow). A frame filled by a wall a few centimetres away, its colour
  // a shade off the floor's (one lightness bin: likelihood 0.5 after the
  // model's smoothing) or its texture in the tail of the floor's, then has no
  // floor (every column blind) instead of all floor.
  double seed_colour_likelihood = 0.6;
  double seed_texture_likelihood = 0.3;
  // The model learns from the reference region's floor cells whose colour
  // likelihood is at least this: an obstacle's colour in the model's tail
  // (one that passed for the floor's) does not widen the model frame after
  // frame, while a real floor's broad histogram (camera noise, uneven light,
  // most of its pixels well below its peak) keeps its breadth.
  double learn_colour_likelihood = 0.45;
  // A frame whose floor reaches the top row in at least this share of the
  // columns shows no end of the floor: a robot facing a wall a few
  // centimetres away sees only wall, and where that wall's colour passes for
  // the floor's the whole frame is called floor. The model does not learn
  // from such a frame, so that it does not drift to the wall's colour; and
  // while bootstrapping, a reference region whose colours cover this share of
  // its whole frame (one appearance all over), or whose appearance runs from
  // the bottom of the view to its top in this share of the columns it is in
  // at the bottom (it ends nowhere), does not vote.
  double open_top_share = 0.9;
  // Two reference regions agree when each one's colour model calls at least
  // this share of the other's pixels floor-coloured (at colour_threshold).
  double bootstrap_agreement = 0.8;
};

// The default segmenter, after Ulrich & Nourbakhsh (2000), "Appearance-based
// obstacle detection with monocular color vision": the floor's appearance is
// learnt online from a trapezoid in front of the robot (the reference region)
// and a pixel is floor where its appearance is common there. Appearance is
// colour (FloorColourModel: L*a*b* histogram) and a simple texture feature
// (TextureFeature: the local mean gradient magnitude, histogrammed on a log
// scale); both must be common. The candidate floor is cut by the non-vertical Canny edges, as in
// the paper (near-vertical edges, the sides of obstacles, do not cut it: they
// are left out of the boundary), and the floor is the part connected to the
// reference region or to the bottom rows (where those look typical of the floor, not merely
// possible: a view filled by a wall that passes for the floor has no floor), closed and grown
// back to the edges. A refinement pass
// then weighs, within the frame, the colours of the floor just found against those of the rest (the
// two-class idea of GrabCut, with histograms and no graph cut), which removes colours the reference
// region shares with walls. Later frames learn from the part of the reference region found floor
// whose colour lies well within the model, with exponential forgetting, so the model follows the
// light and an obstacle right in front of the robot is not learnt as floor; a frame whose floor
// does not end (no boundary: a wall fills the view) teaches nothing. The first frame alone may be
// filled by an obstacle (a wall a few cm away), so over the first pirouette the model follows the
// appearance most reference regions agree on, the majority vote of the paper's assumption that the
// reference region is floor (a frame that shows no end of its reference appearance does not vote:
// one appearance all over, or one running from the bottom of the view to its top); run::FrameMapper
// maps the first pirouette's frames again once the vote is in (SettlingFrames).
//
// A floor's grain fades with range: once it is finer than a pixel, the far
// floor looks smoother than the reference region's (measured on rendered
// floors: the feature falls by about three bins each time the range doubles
// past about twice the region's, docs/worlds.md), and the texture test would
// end the floor in open floor, a ring of false walls. So above the reference
// region, the rows the texture was not learnt from, a cell of the floor's
// colour, off the edges, whose texture is smoother than any the model holds
// is unresolved (Unresolved), not an obstacle: a smooth thing of the floor's
// colour there and a faded floor look alike, and only a nearer look tells
// them apart. A texture rougher than the floor's still ends the floor.
//
// Speed: all the steps above run on the working grid (options.working_width:
// 160×120 cells for 320×240 and 640×480 frames), with the texture measured at
// full resolution and the boundary placed to the pixel (UpsampleFloorMask);
// each cell's colour is binned once a frame and each colour test is a look-up
// of its bin in a per-bin table rebuilt when a model changes; the components,
// closing and growth (mask_morphology.h) touch only the pixels they change;
// the buffers are kept from frame to frame. On the 160×120 photos (no camera)
// the grid is the photo itself.
class AppearanceSegmenter : public FloorSegmenter {
 public:
  AppearanceSegmenter(const std::optional<camera::CameraModel>& camera,
                      const AppearanceSegmenterOptions& options);

  cv::Mat1b Segment(const cv::Mat3b& bgr_raw) override;
  // The first pirouette, over which the model follows the majority of the
  // reference regions (options.bootstrap_frames).
  int SettlingFrames() const override { return options_.bootstrap_frames; }
  // The floor-coloured cells above the reference region whose texture is
  // smoother than any the floor's model holds (see Segment).
  const cv::Mat1b& Unresolved() const override { return unresolved_; }

  const FloorColourModel& colour_model() const { return colour_; }

 private:
  static constexpr int kTextureBins = TextureFeature::kBins;
  using TextureHistogram = std::array<double, kTextureBins>;

  // What depends on the frame's size: the working grid and its helpers.
  struct Grid {
    int scale = 1;
    cv::Size frame;
    cv::Size cells;
    std::optional<EdgeDetector> edges;
    std::optional<TextureFeature> texture;
    cv::Mat1b reference;       // the reference region's mask, on the grid
    int reference_top = 0;     // the reference region's highest row
    int reference_bottom = 0;  // ...and its lowest
    cv::Mat1b seeds;           // where floor components may start: reference or bottom rows
    cv::Mat1b everywhere;      // all 255
  };
  void MakeGrid(cv::Size frame, const std::optional<camera::CameraModel>& camera);

  // The normalised histogram of `bins` in `region`; nullopt when it is empty.
  static std::optional<TextureHistogram> HistogramOf(const cv::Mat1b& bins,
                                                     const cv::Mat1b& region);
  void LearnTexture(const cv::Mat1b& bins, const cv::Mat1b& region);
  void LearnTexture(const TextureHistogram& frame);
  // A texture histogram's likelihoods: smoothed by [1 2 1] / 4, over its peak.
  static std::array<float, kTextureBins> TextureLikelihood(const TextureHistogram& histogram);
  // Keeps the reference region's appearance during the first pirouette and
  // relearns the model when most regions so far agree on another appearance.
  void Bootstrap(const cv::Mat1w& colour_bins, const cv::Mat1b& texture,
                 const cv::Mat1b& reference);
  // The floor from a per-bin colour test (`pass`: 1 where a bin's colour may
  // be floor) of the low-passed cells and of the finely low-passed ones, into
  // floor_ (see Segment).
  void FloorFrom(const std::vector<std::uint8_t>& pass);
  // Whether floor_ ends below the top row in enough columns (see
  // options.open_top_share) for the frame to be learnt from.
  bool SeesFloorEnd() const;
  // strong_seeds_: the seed cells whose colour and texture are typical of the
  // floor (options.seed_colour_likelihood, seed_texture_likelihood).
  void StrongSeeds(const cv::Mat1b& texture);
  // unresolved_ (at the frame's size, from the grid's cells): see Segment.
  void FindUnresolved(const cv::Mat1b& texture, cv::Size frame);

  // One reference region's appearance, kept while bootstrapping.
  struct ReferenceSample {
    std::vector<double> colour;  // FloorColourModel::Histogram
    TextureHistogram texture{};
    FloorColourModel model;  // learnt from `colour` alone
  };
  // Whether the sample's appearance (colour and texture, at the thresholds
  // the floor is tested at) fills, from the reference region's bottom row to
  // the top row, at least options.open_top_share of the columns it is in at
  // that bottom row.
  bool OneAppearanceToTheTop(const ReferenceSample& sample, const cv::Mat1w& colour_bins,
                             const cv::Mat1b& texture);

  AppearanceSegmenterOptions options_;
  bool has_camera_;  // frames then have the camera's size, and a fixed grid
  std::optional<VignettingCorrector> corrector_;  // on the grid
  int blur_order_;
  int grow_blur_order_;
  Grid grid_;
  FloorColourModel colour_;
  FloorColourModel inside_;  // the refinement's two classes
  FloorColourModel outside_;
  bool texture_learnt_ = false;
  std::array<double, kTextureBins> texture_histogram_{};
  std::array<float, kTextureBins> texture_likelihood_{};
  int frames_seen_ = 0;
  std::vector<ReferenceSample> samples_;      // while bootstrapping
  std::vector<std::vector<bool>> agreement_;  // agreement_[i][j]: samples i and j agree

  // Buffers kept from frame to frame, all on the grid.
  cv::Mat3b corrected_;  // the frame reduced and corrected for vignetting
  cv::Mat blurred_;      // ...low-passed (blur_sigma)
  cv::Mat fine_;         // ...low-passed (grow_blur_sigma)
  cv::Mat1w bins_;       // FloorColourModel bins of blurred_
  cv::Mat1w fine_bins_;  // ...and of fine_
  cv::Mat1b texture_ok_;
  cv::Mat1b no_barrier_;  // all zeros: the barrier without edges
  cv::Mat1b candidate_;
  cv::Mat1b allowed_;
  cv::Mat1b edge_allowed_;
  cv::Mat1b floor_;
  cv::Mat1b learn_region_;
  cv::Mat1b strong_seeds_;
  cv::Mat1b sample_pass_;           // OneAppearanceToTheTop's cells
  cv::Mat1b unresolved_cells_;      // on the grid, grown by a cell
  cv::Mat1b unresolved_;            // at the frame's size
  std::vector<std::uint8_t> pass_;  // per colour bin: passes the colour test
  std::optional<MaskCloser> closer_;
  MaskGrower grower_;
};

}  // namespace pirouette::vision
