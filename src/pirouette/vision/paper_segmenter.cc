#include "pirouette/vision/paper_segmenter.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace pirouette::vision {

PaperSegmenter::PaperSegmenter(const std::optional<camera::CameraModel>& camera,
                               const PaperSegmenterOptions& options)
    : options_(options), colour_(options.colour) {
  CV_Assert(options.blur_sigma >= 0.0 && options.seed_search_rows >= 1);
  if (camera) {
    corrector_.emplace(*camera);
    vertical_.emplace(*camera);
  }
}

const EdgeMap& PaperSegmenter::last_edges() const {
  static const EdgeMap kNone;
  return edges_ ? edges_->edges() : kNone;
}

cv::Mat1b PaperSegmenter::Segment(const cv::Mat3b& bgr_raw) {
  const cv::Mat3b blurred = PrepareFrame(bgr_raw, corrector_, vertical_, options_.blur_sigma);
  if (!edges_ || edges_->vertical().directions().data != vertical_->directions().data) {
    edges_.emplace(*vertical_, options_.edges);
  }
  const EdgeMap& edges = edges_->Find(blurred);

  // The barrier: the edges that are not vertical in the world.
  const cv::Mat1b& barrier = edges_->barrier();

  const cv::Mat1b reference = ReferenceRegionMask(bgr_raw.size(), options_.reference);
  if (!colour_.learnt()) colour_.Learn(blurred, reference);

  // The seed: the bottom-centre pixel if it is floor-coloured and not on an
  // edge, else the nearest such pixel to the centre in the bottom rows.
  const int width = bgr_raw.cols;
  const int height = bgr_raw.rows;
  const int centre = width / 2;
  std::optional<cv::Point> seed;
  const int first_row = height - 1 - options_.reference.margin;
  for (int v = first_row; v >= std::max(0, first_row - options_.seed_search_rows + 1) && !seed;
       --v) {
    for (int offset = 0; offset <= width / 2 && !seed; ++offset) {
      for (const int u : {centre - offset, centre + offset}) {
        if (u < 0 || u >= width || edges.edges(v, u) != 0) continue;
        if (colour_.Likelihood(blurred(v, u)) >= options_.seed_likelihood) {
          seed = cv::Point(u, v);
          break;
        }
      }
    }
  }
  cv::Mat1b floor(bgr_raw.size(), std::uint8_t{0});
  if (!seed) return floor;

  // The fill: along the seed's row both ways until any edge, and from each
  // pixel of that run up its column until a barrier (and down to the bottom).
  auto fill_column = [&](int u) {
    for (int v = seed->y; v >= 0 && barrier(v, u) == 0; --v) floor(v, u) = 255;
    for (int v = seed->y + 1; v < height && barrier(v, u) == 0; ++v) floor(v, u) = 255;
  };
  const cv::Mat1b& any_edge = edges.edges;
  for (int u = seed->x; u < width && any_edge(seed->y, u) == 0; ++u) fill_column(u);
  for (int u = seed->x - 1; u >= 0 && any_edge(seed->y, u) == 0; --u) fill_column(u);

  cv::Mat1b learn_region = reference & floor;
  colour_.Learn(blurred, learn_region);
  return floor;
}

}  // namespace pirouette::vision
