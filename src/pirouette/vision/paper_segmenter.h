#pragma once

#include <optional>

#include "pirouette/camera/camera_model.h"
#include "pirouette/vision/edge_map.h"
#include "pirouette/vision/floor_colour_model.h"
#include "pirouette/vision/floor_segmenter.h"
#include "pirouette/vision/vertical_direction_field.h"
#include "pirouette/vision/vignetting_corrector.h"

namespace pirouette::vision {

struct PaperSegmenterOptions {
  double blur_sigma = 1.5;  // the Gaussian low-pass, pixels
  // Low thresholds, chosen on simulated frames (the robot's camera, the
  // paper's setting), where wall bases can have little contrast; real photos
  // 0–69 would prefer higher ones (more texture), the default method serves those.
  EdgeMapOptions edges{20.0, 60.0, 15.0};
  FloorColourModelOptions colour;
  ReferenceRegion reference;
  // A seed pixel is floor when the colour model's likelihood there is at least this.
  double seed_likelihood = 0.05;
  int seed_search_rows = 6;  // how many bottom rows are searched for a floor seed
};

// The paper's segmenter (Taylor, Geva & Boles 2005, §4–5): a Gaussian
// low-pass, Canny edges, and a fill from the bottom of the image upward until
// edges stop it. The fill starts at a seed near the bottom centre, runs along
// the seed's row both ways until any edge, and from each pixel of that run up
// its column until a non-vertical edge (below): the floor mask is one run per column from the
// bottom, as the column-wise obstacle profile reads it. The seed is checked
// against the floor colour model; where it differs, the bottom rows are
// searched for the floor-coloured pixel nearest the centre, and the mask is
// empty when none is found (an obstacle fills the view).
//
// Near-vertical edges are left out of the boundary this way: edge pixels that
// run along the world vertical at their pixel (VerticalDirectionField) do not
// stop the fill up the columns (they do stop its run along the seed's row). An obstacle's base, a
// non-vertical edge, still stops it; its sides, which in a tilted camera lean across the columns
// beside the base (§5.2), do not end those columns' floor at a point where nothing stands on the
// floor. Because the fill only goes up the columns, it cannot leak sideways through a side into the
// obstacle.
//
// The colour model is learnt from the reference region of the first frame,
// then, frame by frame, from the part of the reference region the fill found floor.
class PaperSegmenter : public FloorSegmenter {
 public:
  PaperSegmenter(const std::optional<camera::CameraModel>& camera,
                 const PaperSegmenterOptions& options);

  cv::Mat1b Segment(const cv::Mat3b& bgr_raw) override;

  const FloorColourModel& colour_model() const { return colour_; }
  // The edge map of the last frame segmented (for pictures and tests); valid
  // until the next Segment.
  const EdgeMap& last_edges() const;

 private:
  PaperSegmenterOptions options_;
  std::optional<VignettingCorrector> corrector_;
  std::optional<VerticalDirectionField> vertical_;
  FloorColourModel colour_;
  std::optional<EdgeDetector> edges_;  // for the frames' size
};

}  // namespace pirouette::vision
