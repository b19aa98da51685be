#include "pirouette/vision/vignetting_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace pirouette::vision {
namespace {

constexpr int kSaturated = 250;
constexpr double kDark = 8.0;
constexpr int kMinBlocks = 20;

struct Block {
  double rho2 = 0.0;                 // the block's mean ρ²
  std::array<double, 3> level = {};  // mean R, G, B
  bool usable = true;
};

struct Line {
  double a = 0.0;
  double b = 0.0;
};

// Least squares y = a + b·x over the usable blocks.
Line FitLine(const std::vector<Block>& blocks, const std::vector<bool>& keep, int channel) {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (!keep[i]) continue;
    const double x = blocks[i].rho2;
    const double y = 1.0 / blocks[i].level[static_cast<std::size_t>(channel)];
    n += 1.0;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double denominator = n * sxx - sx * sx;
  if (!(n >= 2.0) || !(std::abs(denominator) > 0.0)) return {n > 0.0 ? sy / n : 0.0, 0.0};
  const double b = (n * sxy - sx * sy) / denominator;
  return {(sy - b * sx) / n, b};
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

VignettingFit FitVignetting(const cv::Mat3b& bgr, const camera::CameraModel& camera) {
  CV_Assert(bgr.cols == camera.width() && bgr.rows == camera.height());
  const double cx = camera.intrinsics().cx;
  const double cy = camera.intrinsics().cy;
  const double r_max2 = camera.vignetting_r_max_squared();
  // Blocks of side s: about 80 across, fine enough for a smooth ρ² and coarse
  // enough to average the noise away.
  const int side = std::max(1, std::min(bgr.cols, bgr.rows) / 60);
  std::vector<Block> blocks;
  for (int v0 = 0; v0 + side <= bgr.rows; v0 += side) {
    for (int u0 = 0; u0 + side <= bgr.cols; u0 += side) {
      Block block;
      std::array<double, 3> sum = {0.0, 0.0, 0.0};
      double rho2 = 0.0;
      for (int v = v0; v < v0 + side; ++v) {
        const auto* row = bgr.ptr<cv::Vec3b>(v);
        for (int u = u0; u < u0 + side; ++u) {
          for (int c = 0; c < 3; ++c) {
            const int value = row[u][2 - c];  // OpenCV's B, G, R → R, G, B
            sum[static_cast<std::size_t>(c)] += value;
            if (value >= kSaturated) block.usable = false;
          }
          rho2 += ((u - cx) * (u - cx) + (v - cy) * (v - cy)) / r_max2;
        }
      }
      const double area = static_cast<double>(side) * side;
      block.rho2 = rho2 / area;
      for (std::size_t c = 0; c < 3; ++c) {
        block.level[c] = sum[c] / area;
        if (block.level[c] < kDark) block.usable = false;
      }
      blocks.push_back(block);
    }
  }

  VignettingFit fit;
  fit.blocks = static_cast<int>(blocks.size());
  std::vector<bool> keep(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i) keep[i] = blocks[i].usable;
  std::array<Line, 3> lines;
  const auto relative_residual = [&](std::size_t i, int c) {
    const Line& line = lines[static_cast<std::size_t>(c)];
    const double model = line.a + line.b * blocks[i].rho2;
    return (1.0 / blocks[i].level[static_cast<std::size_t>(c)] - model) / model;
  };
  for (int round = 0; round < 3; ++round) {
    if (std::count(keep.begin(), keep.end(), true) < kMinBlocks) {
      throw std::invalid_argument(
          "FitVignetting: too few usable blocks (the photo is over- or under-exposed)");
    }
    for (int c = 0; c < 3; ++c) lines[static_cast<std::size_t>(c)] = FitLine(blocks, keep, c);
    if (round == 2) break;
    // Drop the outliers of any channel, judged against the current fit.
    std::array<double, 3> limit{};
    for (int c = 0; c < 3; ++c) {
      std::vector<double> residuals;
      for (std::size_t i = 0; i < blocks.size(); ++i) {
        if (keep[i]) residuals.push_back(std::abs(relative_residual(i, c)));
      }
      limit[static_cast<std::size_t>(c)] = std::max(4.0 * 1.4826 * Median(residuals), 1e-4);
    }
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      if (!keep[i]) continue;
      for (int c = 0; c < 3; ++c) {
        if (std::abs(relative_residual(i, c)) > limit[static_cast<std::size_t>(c)]) keep[i] = false;
      }
    }
  }

  fit.blocks_used = static_cast<int>(std::count(keep.begin(), keep.end(), true));
  for (int c = 0; c < 3; ++c) {
    const auto ci = static_cast<std::size_t>(c);
    const Line& line = lines[ci];
    double k = line.a > 0.0 ? line.b / line.a : 0.0;
    if (!(k >= 0.0)) {
      k = 0.0;
      fit.clamped[ci] = true;
    }
    fit.vignetting.k[ci] = k;
    fit.centre_level[ci] = line.a > 0.0 ? 1.0 / line.a : 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      if (keep[i]) sum += relative_residual(i, c) * relative_residual(i, c);
    }
    fit.rms_relative[ci] = std::sqrt(sum / std::max(fit.blocks_used, 1));
  }
  return fit;
}

}  // namespace pirouette::vision
