#include "pirouette/vision/appearance_segmenter.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

#include "pirouette/vision/binomial_blur.h"
#include "pirouette/vision/mask_upsampler.h"

namespace pirouette::vision {
namespace {

// The refinement's two classes are compared bin by bin, so both are smoothed
// alike: one kernel, not each class's own lightness spread (the rest of a
// frame, walls, furniture and the world beyond, spreads over all of L*, and
// smoothed by that spread its density would lose to the floor's everywhere).
FloorColourModelOptions TwoClassOptions(FloorColourModelOptions options) {
  options.lightness_spread = 0.0;
  return options;
}

// Of the columns whose cell on row `bottom` passes `pass` (one flag per
// cell), the share that pass it in every cell from there up to the top row:
// one appearance from the bottom of the view to its top. 0 when no column
// passes at the bottom.
double FullColumnShare(const cv::Mat1b& pass, int bottom) {
  int present = 0;
  int full = 0;
  for (int u = 0; u < pass.cols; ++u) {
    if (pass(bottom, u) == 0) continue;
    ++present;
    int v = bottom - 1;
    while (v >= 0 && pass(v, u) != 0) --v;
    if (v < 0) ++full;
  }
  return present == 0 ? 0.0 : static_cast<double>(full) / present;
}

// The working grid's factor for frames `width` wide.
int ScaleFor(int width, int working_width) {
  return working_width > 0 ? std::max(1, width / working_width) : 1;
}

// Per colour bin, 1 where value >= threshold: a model's per-pixel test as a
// table, looked up at each cell's bin.
void PassTable(const std::vector<float>& value, float threshold, std::vector<std::uint8_t>& pass) {
  pass.resize(value.size());
  for (std::size_t i = 0; i < value.size(); ++i) pass[i] = value[i] >= threshold ? 1 : 0;
}
// Per colour bin, 1 where value >= factor · other: two models' test.
void PassTable(const std::vector<float>& value, float factor, const std::vector<float>& other,
               std::vector<std::uint8_t>& pass) {
  pass.resize(value.size());
  for (std::size_t i = 0; i < value.size(); ++i) pass[i] = value[i] >= factor * other[i] ? 1 : 0;
}

}  // namespace

AppearanceSegmenter::AppearanceSegmenter(const std::optional<camera::CameraModel>& camera,
                                         const AppearanceSegmenterOptions& options)
    : options_(options),
      has_camera_(camera.has_value()),
      blur_order_(BinomialOrder(options.blur_sigma)),
      grow_blur_order_(BinomialOrder(options.grow_blur_sigma)),
      colour_(options.colour),
      inside_(TwoClassOptions(options.colour)),
      outside_(TwoClassOptions(options.colour)) {
  CV_Assert(options.blur_sigma >= 0.0 && options.texture_window >= 1 && options.close_size >= 0);
  CV_Assert(options.bootstrap_frames >= 0 && options.bootstrap_agreement >= 0.0 &&
            options.bootstrap_agreement <= 1.0);
  CV_Assert(options.working_width >= 0 && options.grow_blur_sigma >= 0.0 &&
            options.grow_steps >= 0 && options.bottom_rows >= 0 && options.refine_passes >= 0);
  if (options.close_size > 0) closer_.emplace(options.close_size);
  if (camera) MakeGrid(cv::Size(camera->width(), camera->height()), camera);
}

void AppearanceSegmenter::MakeGrid(cv::Size frame,
                                   const std::optional<camera::CameraModel>& camera) {
  Grid grid;
  grid.scale = ScaleFor(frame.width, options_.working_width);
  grid.frame = frame;
  grid.cells = cv::Size(frame.width / grid.scale, frame.height / grid.scale);
  std::optional<VignettingCorrector> full_corrector;
  if (camera) {
    corrector_.emplace(*camera, grid.scale);
    full_corrector.emplace(*camera);
    grid.edges.emplace(VerticalDirectionField(*camera, grid.scale), options_.edges);
  } else {
    grid.edges.emplace(VerticalDirectionField(grid.cells.width, grid.cells.height), options_.edges);
  }
  grid.texture.emplace(grid.scale, options_.texture_window, blur_order_, full_corrector);
  grid.reference = ReferenceRegionMask(grid.cells, options_.reference);
  // The rows the region spans (cv::boundingRect of a mask: its non-zero pixels).
  const cv::Rect rows = cv::boundingRect(grid.reference);
  grid.reference_top = rows.empty() ? grid.cells.height : rows.y;
  grid.reference_bottom = rows.empty() ? 0 : rows.y + rows.height - 1;
  grid.seeds = grid.reference.clone();
  grid.everywhere = cv::Mat1b(grid.cells, std::uint8_t{255});
  if (options_.bottom_rows > 0) {
    const int from =
        std::max(0, grid.cells.height - options_.reference.margin - options_.bottom_rows);
    grid.seeds.rowRange(from, grid.cells.height).setTo(255);
  }
  grid_ = std::move(grid);
  no_barrier_ = cv::Mat1b(grid_.cells, std::uint8_t{0});
}

std::optional<AppearanceSegmenter::TextureHistogram> AppearanceSegmenter::HistogramOf(
    const cv::Mat1b& bins, const cv::Mat1b& region) {
  TextureHistogram frame{};
  double count = 0.0;
  for (int v = 0; v < bins.rows; ++v) {
    for (int u = 0; u < bins.cols; ++u) {
      if (region(v, u) == 0) continue;
      frame[bins(v, u)] += 1.0;
      count += 1.0;
    }
  }
  if (count == 0.0) return std::nullopt;
  for (double& h : frame) h /= count;
  return frame;
}

void AppearanceSegmenter::LearnTexture(const cv::Mat1b& bins, const cv::Mat1b& region) {
  if (const auto frame = HistogramOf(bins, region)) LearnTexture(*frame);
}

void AppearanceSegmenter::LearnTexture(const TextureHistogram& frame) {
  const double keep = texture_learnt_ ? 1.0 - options_.colour.forgetting : 0.0;
  for (int i = 0; i < kTextureBins; ++i) {
    texture_histogram_[i] = keep * texture_histogram_[i] + (1.0 - keep) * frame[i];
  }
  texture_learnt_ = true;
  texture_likelihood_ = TextureLikelihood(texture_histogram_);
}

std::array<float, AppearanceSegmenter::kTextureBins> AppearanceSegmenter::TextureLikelihood(
    const TextureHistogram& histogram) {
  // Smoothed by [1 2 1] / 4, then over its maximum.
  std::array<double, kTextureBins> smoothed{};
  for (int i = 0; i < kTextureBins; ++i) {
    const double lo = histogram[std::max(0, i - 1)];
    const double hi = histogram[std::min(kTextureBins - 1, i + 1)];
    smoothed[i] = 0.25 * lo + 0.5 * histogram[i] + 0.25 * hi;
  }
  const double peak = *std::max_element(smoothed.begin(), smoothed.end());
  std::array<float, kTextureBins> likelihood{};
  for (int i = 0; i < kTextureBins; ++i) {
    likelihood[i] = peak > 0.0 ? static_cast<float>(smoothed[i] / peak) : 0.0f;
  }
  return likelihood;
}

bool AppearanceSegmenter::OneAppearanceToTheTop(const ReferenceSample& sample,
                                                const cv::Mat1w& colour_bins,
                                                const cv::Mat1b& texture) {
  const std::vector<float>& colour = sample.model.likelihoods();
  const std::array<float, kTextureBins> texture_likelihood = TextureLikelihood(sample.texture);
  const auto colour_min = static_cast<float>(options_.colour_threshold);
  const auto texture_min = static_cast<float>(options_.texture_threshold);
  sample_pass_.create(grid_.cells);
  for (int v = 0; v < grid_.cells.height; ++v) {
    const std::uint16_t* b = colour_bins[v];
    const std::uint8_t* t = texture[v];
    std::uint8_t* out = sample_pass_[v];
    for (int u = 0; u < grid_.cells.width; ++u) {
      out[u] = colour[b[u]] >= colour_min && texture_likelihood[t[u]] >= texture_min ? 255 : 0;
    }
  }
  return FullColumnShare(sample_pass_, grid_.reference_bottom) >= options_.open_top_share;
}

void AppearanceSegmenter::Bootstrap(const cv::Mat1w& colour_bins, const cv::Mat1b& texture,
                                    const cv::Mat1b& reference) {
  if (frames_seen_ >= options_.bootstrap_frames) {
    samples_.clear();
    agreement_.clear();
    return;
  }
  ++frames_seen_;
  ReferenceSample sample{
      FloorColourModel::Histogram(colour_bins, reference), {}, FloorColourModel(options_.colour)};
  const auto texture_histogram = HistogramOf(texture, reference);
  if (sample.colour.empty() || !texture_histogram) return;
  sample.texture = *texture_histogram;
  sample.model.Learn(sample.colour);
  const auto threshold = static_cast<float>(options_.colour_threshold);
  // A frame that shows no end of its reference region's appearance says
  // nothing of which appearance is the floor's, and does not vote: the floor
  // ends at the base of whatever stands on it, below something else. So not
  // a frame whose reference appearance (colour and texture) runs from the
  // bottom of the view to its top in most of the columns it is in at the
  // bottom: a wall filling the view, even with the floor beside it ending at
  // the wall's far part (a maze's dead end), or open floor to the top. Nor,
  // the first frame aside, one whose reference colours cover most of the
  // frame (one appearance all over).
  if (OneAppearanceToTheTop(sample, colour_bins, texture)) return;
  if (colour_.learnt() &&
      sample.model.Coverage(FloorColourModel::Histogram(colour_bins, grid_.everywhere),
                            threshold) >= options_.open_top_share) {
    return;
  }
  const std::size_t n = samples_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const bool agree = std::min(samples_[i].model.Coverage(sample.colour, threshold),
                                sample.model.Coverage(samples_[i].colour, threshold)) >=
                       options_.bootstrap_agreement;
    agreement_[i].push_back(agree);
  }
  samples_.push_back(std::move(sample));
  agreement_.emplace_back(n + 1, false);
  for (std::size_t i = 0; i < n; ++i) agreement_[n][i] = agreement_[i][n];
  agreement_[n][n] = true;
  if (!colour_.learnt()) return;  // the first region: Segment learns it as before

  // The appearance most regions agree on (the earliest on a tie, so that the
  // model changes only on a strict majority)...
  std::size_t best = 0;
  long best_support = -1;
  for (std::size_t i = 0; i <= n; ++i) {
    const long support = std::count(agreement_[i].begin(), agreement_[i].end(), true);
    if (support > best_support) {
      best = i;
      best_support = support;
    }
  }
  // ...replaces the model when the model does not hold it already.
  if (std::min(colour_.Coverage(samples_[best].colour, threshold),
               samples_[best].model.Coverage(colour_.histogram(), threshold)) >=
      options_.bootstrap_agreement) {
    return;
  }
  const auto members = static_cast<double>(best_support);
  std::vector<double> colour(FloorColourModel::kBins, 0.0);
  TextureHistogram texture_mean{};
  for (std::size_t j = 0; j <= n; ++j) {
    if (!agreement_[best][j]) continue;
    for (int b = 0; b < FloorColourModel::kBins; ++b) {
      colour[b] += samples_[j].colour[b] / members;
    }
    for (int b = 0; b < kTextureBins; ++b) {
      texture_mean[b] += samples_[j].texture[b] / members;
    }
  }
  colour_.Relearn(colour);
  texture_learnt_ = false;
  LearnTexture(texture_mean);
}

cv::Mat1b AppearanceSegmenter::Segment(const cv::Mat3b& bgr_raw) {
  CV_Assert(!bgr_raw.empty());
  if (has_camera_) {
    CV_Assert(bgr_raw.size() == grid_.frame);
  } else if (bgr_raw.size() != grid_.frame) {
    MakeGrid(bgr_raw.size(), std::nullopt);
  }
  const int scale = grid_.scale;

  // The frame on the grid: reduced and corrected (a view of the frame when
  // there is nothing to do: the buffers never alias the caller's frame).
  if (corrector_) {
    corrector_->ReduceAndApply(bgr_raw, corrected_);
  } else if (scale > 1) {
    ReduceByBlockMean(bgr_raw, scale, corrected_);
  }
  const cv::Mat3b& corrected = corrector_ || scale > 1 ? corrected_ : bgr_raw;
  BinomialBlur(corrected, blurred_, blur_order_);
  BinomialBlur(corrected, fine_, grow_blur_order_);
  FloorColourModel::Bins(blurred_, bins_);
  FloorColourModel::Bins(fine_, fine_bins_);
  if (options_.use_edges) grid_.edges->Find(blurred_);
  const cv::Mat1b& texture = grid_.texture->Bins(bgr_raw);
  const cv::Mat1b& reference = grid_.reference;

  Bootstrap(bins_, texture, reference);
  if (!colour_.learnt()) colour_.Learn(FloorColourModel::Histogram(bins_, reference));
  if (!texture_learnt_) LearnTexture(texture, reference);

  texture_ok_.create(grid_.cells);
  std::array<std::uint8_t, kTextureBins> texture_pass{};
  for (int i = 0; i < kTextureBins; ++i) {
    texture_pass[i] = texture_likelihood_[i] >= options_.texture_threshold ? 255 : 0;
  }
  for (int v = 0; v < texture.rows; ++v) {
    const std::uint8_t* t = texture[v];
    std::uint8_t* ok = texture_ok_[v];
    for (int u = 0; u < texture.cols; ++u) ok[u] = texture_pass[t[u]];
  }

  const auto threshold = static_cast<float>(options_.colour_threshold);
  StrongSeeds(texture);
  PassTable(colour_.likelihoods(), threshold, pass_);
  FloorFrom(pass_);
  for (int pass = 0; pass < options_.refine_passes; ++pass) {
    // A two-class refinement within the frame: the colours of the floor just
    // found against those of the rest; a pixel is floor-coloured where the
    // floor's colour density is at least refine_ratio times the rest's.
    const auto [inside, outside] = FloorColourModel::Histograms(bins_, floor_);
    if (inside.empty() || outside.empty()) break;
    inside_.Relearn(inside);
    outside_.Relearn(outside);
    PassTable(inside_.densities(), static_cast<float>(options_.refine_ratio), outside_.densities(),
              pass_);
    FloorFrom(pass_);
  }

  if (SeesFloorEnd()) {
    learn_region_.create(grid_.cells);
    cv::bitwise_and(reference, floor_, learn_region_);
    // ...where its colour lies well within the model.
    const std::vector<float>& likelihood = colour_.likelihoods();
    const auto learn_min = static_cast<float>(options_.learn_colour_likelihood);
    for (int v = 0; v < grid_.cells.height; ++v) {
      const std::uint16_t* b = bins_[v];
      std::uint8_t* learn = learn_region_[v];
      for (int u = 0; u < grid_.cells.width; ++u) {
        if (likelihood[b[u]] < learn_min) learn[u] = 0;
      }
    }
    colour_.Learn(FloorColourModel::Histogram(bins_, learn_region_));
    LearnTexture(texture, learn_region_);
  }
  FindUnresolved(texture, bgr_raw.size());
  if (scale == 1) return floor_.clone();
  return UpsampleFloorMask(floor_, corrected, bgr_raw, scale, corrector_);
}

void AppearanceSegmenter::FindUnresolved(const cv::Mat1b& texture, cv::Size frame) {
  // The smoothest texture the floor's model takes.
  int smoothest = kTextureBins;
  for (int i = kTextureBins - 1; i >= 0; --i) {
    if (texture_likelihood_[i] >= options_.texture_threshold) smoothest = i;
  }
  const cv::Mat1b& barrier = options_.use_edges ? grid_.edges->barrier() : no_barrier_;
  unresolved_cells_.create(grid_.cells);
  unresolved_cells_.setTo(0);
  bool any = false;
  for (int v = 0; v < grid_.reference_top; ++v) {
    const std::uint16_t* b = bins_[v];
    const std::uint8_t* t = texture[v];
    const std::uint8_t* f = floor_[v];
    const std::uint8_t* bar = barrier[v];
    std::uint8_t* out = unresolved_cells_[v];
    for (int u = 0; u < grid_.cells.width; ++u) {
      if (f[u] == 0 && pass_[b[u]] != 0 && bar[u] == 0 && t[u] < smoothest) {
        out[u] = 255;
        any = true;
      }
    }
  }
  if (!any) {
    unresolved_.release();
    return;
  }
  // Grown by a cell: the floor's boundary is placed to the pixel within the
  // cells (UpsampleFloorMask), so the first pixel past it may lie in the
  // floor cell below an unresolved one.
  cv::dilate(unresolved_cells_, unresolved_cells_, cv::Mat());
  cv::resize(unresolved_cells_, unresolved_, frame, 0.0, 0.0, cv::INTER_NEAREST);
}

void AppearanceSegmenter::StrongSeeds(const cv::Mat1b& texture) {
  const std::vector<float>& colour = colour_.likelihoods();
  const auto colour_min = static_cast<float>(options_.seed_colour_likelihood);
  const auto texture_min = static_cast<float>(options_.seed_texture_likelihood);
  strong_seeds_.create(grid_.cells);
  for (int v = 0; v < grid_.cells.height; ++v) {
    const std::uint8_t* seed = grid_.seeds[v];
    const std::uint16_t* b = bins_[v];
    const std::uint8_t* t = texture[v];
    std::uint8_t* out = strong_seeds_[v];
    for (int u = 0; u < grid_.cells.width; ++u) {
      out[u] =
          seed[u] != 0 && colour[b[u]] >= colour_min && texture_likelihood_[t[u]] >= texture_min
              ? 255
              : 0;
    }
  }
}

bool AppearanceSegmenter::SeesFloorEnd() const {
  const std::uint8_t* top = floor_[0];
  const auto open = static_cast<double>(
      std::count_if(top, top + grid_.cells.width, [](std::uint8_t f) { return f != 0; }));
  return open < options_.open_top_share * grid_.cells.width;
}

void AppearanceSegmenter::FloorFrom(const std::vector<std::uint8_t>& pass) {
  // The floor from a colour test (which cells of `blurred_`, and of `fine_`,
  // have a floor colour): floor-coloured, floor-textured cells off the
  // barrier, the components touching the reference region (or the bottom
  // rows), closed, and grown back to the edges.
  const cv::Mat1b& barrier = options_.use_edges ? grid_.edges->barrier() : no_barrier_;
  candidate_.create(grid_.cells);
  allowed_.create(grid_.cells);
  edge_allowed_.create(grid_.cells);
  for (int v = 0; v < grid_.cells.height; ++v) {
    const std::uint16_t* b = bins_[v];
    const std::uint16_t* fb = fine_bins_[v];
    const std::uint8_t* t = texture_ok_[v];
    const std::uint8_t* bar = barrier[v];
    std::uint8_t* c = candidate_[v];
    std::uint8_t* a = allowed_[v];
    std::uint8_t* e = edge_allowed_[v];
    for (int u = 0; u < grid_.cells.width; ++u) {
      const std::uint8_t fine_ok = pass[fb[u]] != 0 ? 255 : 0;
      c[u] = pass[b[u]] != 0 ? static_cast<std::uint8_t>(t[u] & ~bar[u]) : 0;
      a[u] = static_cast<std::uint8_t>(fine_ok & ~bar[u]);
      // Canny's edge pixel may be the floor's last one: it joins the floor
      // where its colour is the floor's (the floor does not grow on past it).
      e[u] = static_cast<std::uint8_t>(fine_ok & bar[u]);
    }
  }
  FillFromSeeds(candidate_, strong_seeds_, floor_);
  if (closer_) closer_->Close(floor_);
  grower_.Grow(floor_, allowed_, options_.grow_steps);
  grower_.Grow(floor_, edge_allowed_, 1);
}

}  // namespace pirouette::vision
