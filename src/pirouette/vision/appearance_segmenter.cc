#include "pirouette/vision/appearance_segmenter.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace pirouette::vision {

AppearanceSegmenter::AppearanceSegmenter(const std::optional<camera::CameraModel>& camera,
                                         const AppearanceSegmenterOptions& options)
    : options_(options), colour_(options.colour) {
  CV_Assert(options.blur_sigma >= 0.0 && options.texture_window >= 1 && options.close_size >= 0);
  CV_Assert(options.bootstrap_frames >= 0 && options.bootstrap_agreement >= 0.0 &&
            options.bootstrap_agreement <= 1.0);
  if (camera) {
    corrector_.emplace(*camera);
    vertical_.emplace(*camera);
  }
}

cv::Mat1b AppearanceSegmenter::TextureBins(const cv::Mat1b& grey) const {
  cv::Mat1f dx;
  cv::Mat1f dy;
  cv::Sobel(grey, dx, CV_32F, 1, 0, 3, 0.125);
  cv::Sobel(grey, dy, CV_32F, 0, 1, 3, 0.125);
  cv::Mat1f magnitude = cv::abs(dx) + cv::abs(dy);
  cv::blur(magnitude, magnitude, cv::Size(options_.texture_window, options_.texture_window));
  cv::Mat1b bins(grey.size());
  for (int v = 0; v < grey.rows; ++v) {
    for (int u = 0; u < grey.cols; ++u) {
      const double bin = 3.0 * std::log2(1.0 + magnitude(v, u));
      bins(v, u) = static_cast<std::uint8_t>(std::min<double>(kTextureBins - 1, bin));
    }
  }
  return bins;
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
  // Smoothed by [1 2 1] / 4, then over its maximum.
  std::array<double, kTextureBins> smoothed{};
  for (int i = 0; i < kTextureBins; ++i) {
    const double lo = texture_histogram_[std::max(0, i - 1)];
    const double hi = texture_histogram_[std::min(kTextureBins - 1, i + 1)];
    smoothed[i] = 0.25 * lo + 0.5 * texture_histogram_[i] + 0.25 * hi;
  }
  const double peak = *std::max_element(smoothed.begin(), smoothed.end());
  for (int i = 0; i < kTextureBins; ++i) {
    texture_likelihood_[i] = peak > 0.0 ? static_cast<float>(smoothed[i] / peak) : 0.0f;
  }
}

void AppearanceSegmenter::Bootstrap(const cv::Mat3b& blurred, const cv::Mat1b& texture,
                                    const cv::Mat1b& reference) {
  if (frames_seen_ >= options_.bootstrap_frames) {
    samples_.clear();
    agreement_.clear();
    return;
  }
  ++frames_seen_;
  ReferenceSample sample{
      FloorColourModel::Histogram(blurred, reference), {}, FloorColourModel(options_.colour)};
  const auto texture_histogram = HistogramOf(texture, reference);
  if (sample.colour.empty() || !texture_histogram) return;
  sample.texture = *texture_histogram;
  sample.model.Learn(sample.colour);
  const auto threshold = static_cast<float>(options_.colour_threshold);
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
  colour_ = FloorColourModel(options_.colour);
  colour_.Learn(colour);
  texture_learnt_ = false;
  LearnTexture(texture_mean);
}

cv::Mat1b AppearanceSegmenter::Segment(const cv::Mat3b& bgr_raw) {
  const cv::Mat3b corrected = PrepareFrame(bgr_raw, corrector_, vertical_, 0.0);
  cv::Mat3b blurred;
  if (options_.blur_sigma > 0.0) {
    cv::GaussianBlur(corrected, blurred, cv::Size(), options_.blur_sigma);
  } else {
    blurred = corrected;
  }
  cv::Mat1b grey;
  cv::cvtColor(blurred, grey, cv::COLOR_BGR2GRAY);
  const cv::Mat1b texture = TextureBins(grey);

  const cv::Mat1b reference = ReferenceRegionMask(bgr_raw.size(), options_.reference);
  Bootstrap(blurred, texture, reference);
  if (!colour_.learnt()) colour_.Learn(blurred, reference);
  if (!texture_learnt_) LearnTexture(texture, reference);

  cv::Mat1b texture_ok(bgr_raw.size());
  for (int v = 0; v < texture.rows; ++v) {
    for (int u = 0; u < texture.cols; ++u) {
      texture_ok(v, u) = texture_likelihood_[texture(v, u)] >= options_.texture_threshold ? 255 : 0;
    }
  }
  cv::Mat1b barrier(bgr_raw.size(), std::uint8_t{0});
  if (options_.use_edges) {
    const EdgeMap edges = FindEdges(blurred, *vertical_, options_.edges);
    barrier = edges.edges & ~edges.vertical;
  }
  cv::Mat3b fine;
  cv::GaussianBlur(corrected, fine, cv::Size(), options_.grow_blur_sigma);

  // The floor from a colour test (which pixels of `blurred`, and of `fine`,
  // have a floor colour): floor-coloured, floor-textured pixels off the
  // barrier, the components touching the reference region, closed, and grown
  // back to the edges.
  const int bottom_rows_from = options_.bottom_rows > 0
                                   ? bgr_raw.rows - options_.reference.margin - options_.bottom_rows
                                   : bgr_raw.rows;
  auto floor_from = [&](const cv::Mat1b& colour_ok, const cv::Mat1b& fine_colour_ok) {
    const cv::Mat1b candidate = colour_ok & texture_ok & ~barrier;
    cv::Mat1i labels;
    const int count = cv::connectedComponents(candidate, labels, 4, CV_32S);
    std::vector<std::uint8_t> keep(static_cast<std::size_t>(count), 0);
    for (int v = 0; v < labels.rows; ++v) {
      for (int u = 0; u < labels.cols; ++u) {
        if ((reference(v, u) != 0 || v >= bottom_rows_from) && candidate(v, u) != 0) {
          keep[labels(v, u)] = 1;
        }
      }
    }
    cv::Mat1b floor(bgr_raw.size(), std::uint8_t{0});
    for (int v = 0; v < labels.rows; ++v) {
      for (int u = 0; u < labels.cols; ++u) {
        if (keep[labels(v, u)] != 0) floor(v, u) = 255;
      }
    }
    if (options_.close_size > 0) {
      cv::morphologyEx(floor, floor, cv::MORPH_CLOSE,
                       cv::getStructuringElement(
                           cv::MORPH_ELLIPSE, cv::Size(options_.close_size, options_.close_size)));
    }
    const cv::Mat1b allowed = fine_colour_ok & ~barrier;
    const cv::Mat cross = cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3));
    for (int step = 0; step < options_.grow_steps; ++step) {
      cv::Mat1b grown;
      cv::dilate(floor, grown, cross);
      floor |= grown & allowed;
    }
    // Canny's edge pixel may be the floor's last one: it joins the floor
    // where its colour is the floor's (the floor does not grow on past it).
    cv::Mat1b grown;
    cv::dilate(floor, grown, cross);
    floor |= grown & barrier & fine_colour_ok;
    return floor;
  };

  const auto threshold = static_cast<float>(options_.colour_threshold);
  cv::Mat1b floor =
      floor_from(colour_.Likelihood(blurred) >= threshold, colour_.Likelihood(fine) >= threshold);
  for (int pass = 0; pass < options_.refine_passes; ++pass) {
    // A two-class refinement within the frame: the colours of the floor just
    // found against those of the rest; a pixel is floor-coloured where the
    // floor's colour density is at least refine_ratio times the rest's.
    FloorColourModel inside(options_.colour);
    FloorColourModel outside(options_.colour);
    inside.Learn(blurred, floor);
    outside.Learn(blurred, ~floor);
    if (!inside.learnt() || !outside.learnt()) break;
    const auto ratio = static_cast<float>(options_.refine_ratio);
    const cv::Mat1b colour_ok = inside.Density(blurred) >= ratio * outside.Density(blurred);
    const cv::Mat1b fine_ok = inside.Density(fine) >= ratio * outside.Density(fine);
    floor = floor_from(colour_ok, fine_ok);
  }

  const cv::Mat1b learn_region = reference & floor;
  colour_.Learn(blurred, learn_region);
  LearnTexture(texture, learn_region);
  return floor;
}

}  // namespace pirouette::vision
