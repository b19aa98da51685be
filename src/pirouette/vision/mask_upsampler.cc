#include "pirouette/vision/mask_upsampler.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace pirouette::vision {
namespace {

int Reflect101(int i, int n) {
  while (i < 0 || i >= n) i = i < 0 ? -i : 2 * (n - 1) - i;
  return i;
}

constexpr int kMaxScale = 64;

// Decides the pixels of boundary cell (cx, cy) of `mask` (see the header).
void RefineCell(const cv::Mat1b& cell_mask, const cv::Mat3b& cell_bgr, const cv::Mat3b& bgr,
                int scale, const std::optional<VignettingCorrector>& corrector, int cx, int cy,
                cv::Mat1b& mask) {
  const int width = bgr.cols;
  const int height = bgr.rows;
  // The two classes' mean colours over the eight neighbours.
  std::array<std::array<int, 3>, 2> sum{};
  std::array<int, 2> count{};
  for (int ny = std::max(0, cy - 1); ny <= std::min(cell_mask.rows - 1, cy + 1); ++ny) {
    const std::uint8_t* labels = cell_mask[ny];
    const auto* colours = cell_bgr.ptr<std::uint8_t>(ny);
    for (int nx = std::max(0, cx - 1); nx <= std::min(cell_mask.cols - 1, cx + 1); ++nx) {
      if (ny == cy && nx == cx) continue;
      const int k = labels[nx] != 0 ? 1 : 0;
      for (int i = 0; i < 3; ++i) sum[k][i] += colours[3 * nx + i];
      ++count[k];
    }
  }
  // Nearer the floor's mean: |f - m1|² < |f - m0|², i.e. f · (m1 - m0) >
  // (|m1|² - |m0|²) / 2, with f = factor · (low-pass sum) / 16.
  std::array<float, 3> w{};
  double m1_squared = 0.0;
  double m0_squared = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double m1 = static_cast<double>(sum[1][i]) / count[1];
    const double m0 = static_cast<double>(sum[0][i]) / count[0];
    const double factor = corrector ? corrector->Factor(cx, cy, i) : 1.0;
    w[i] = static_cast<float>((m1 - m0) * factor);
    m1_squared += m1 * m1;
    m0_squared += m0 * m0;
  }
  const auto threshold = static_cast<float>(8.0 * (m1_squared - m0_squared));  // 16 · … / 2
  // The cell's pixel columns and one either side (reflected at the borders).
  const int x0 = cx * scale;
  std::array<int, kMaxScale + 2> at{};
  for (int k = 0; k < scale + 2; ++k) at[k] = 3 * Reflect101(x0 - 1 + k, width);
  std::array<std::array<int, 3>, kMaxScale + 2> columns{};
  for (int y = cy * scale; y < (cy + 1) * scale; ++y) {
    const auto* above = bgr.ptr<std::uint8_t>(Reflect101(y - 1, height));
    const auto* here = bgr.ptr<std::uint8_t>(y);
    const auto* below = bgr.ptr<std::uint8_t>(Reflect101(y + 1, height));
    // The vertical [1 2 1] sums, then the horizontal ones.
    for (int k = 0; k < scale + 2; ++k) {
      for (int i = 0; i < 3; ++i) {
        columns[k][i] = above[at[k] + i] + 2 * here[at[k] + i] + below[at[k] + i];
      }
    }
    std::uint8_t* out = mask[y] + x0;
    for (int k = 1; k <= scale; ++k) {
      float dot = 0.0f;
      for (int i = 0; i < 3; ++i) {
        dot += w[i] * static_cast<float>(columns[k - 1][i] + 2 * columns[k][i] + columns[k + 1][i]);
      }
      out[k - 1] = dot > threshold ? 255 : 0;
    }
  }
}

// Decides the pixels of the boundary's cells (a 4-neighbour labelled
// otherwise) of `mask`, one by one (RefineCell).
void RefineBoundary(const cv::Mat1b& cell_mask, const cv::Mat3b& cell_bgr, const cv::Mat3b& bgr,
                    int scale, const std::optional<VignettingCorrector>& corrector,
                    cv::Mat1b& mask) {
  const int cells_x = cell_mask.cols;
  const int cells_y = cell_mask.rows;
  std::vector<std::uint8_t> boundary(static_cast<std::size_t>(cells_x));
  for (int cy = 0; cy < cells_y; ++cy) {
    const std::uint8_t* labels = cell_mask[cy];
    const std::uint8_t* up = cell_mask[cy > 0 ? cy - 1 : cy];
    const std::uint8_t* down = cell_mask[cy + 1 < cells_y ? cy + 1 : cy];
    std::uint8_t* b = boundary.data();
    b[0] = static_cast<std::uint8_t>((labels[0] ^ up[0]) | (labels[0] ^ down[0]));
    for (int cx = 1; cx < cells_x; ++cx) {
      b[cx] = static_cast<std::uint8_t>((labels[cx] ^ up[cx]) | (labels[cx] ^ down[cx]) |
                                        (labels[cx] ^ labels[cx - 1]));
    }
    for (int cx = 0; cx + 1 < cells_x; ++cx) {
      b[cx] = static_cast<std::uint8_t>(b[cx] | (labels[cx] ^ labels[cx + 1]));
    }
    // Most rows hold few boundary cells: skip eight clear cells at a time.
    int cx = 0;
    while (cx < cells_x) {
      if (cx + 8 <= cells_x) {
        std::uint64_t eight = 0;
        std::memcpy(&eight, b + cx, sizeof(eight));
        if (eight == 0) {
          cx += 8;
          continue;
        }
      }
      if (b[cx] != 0) RefineCell(cell_mask, cell_bgr, bgr, scale, corrector, cx, cy, mask);
      ++cx;
    }
  }
}

}  // namespace

cv::Mat1b UpsampleFloorMask(const cv::Mat1b& cell_mask, const cv::Mat3b& cell_bgr,
                            const cv::Mat3b& bgr, int scale,
                            const std::optional<VignettingCorrector>& corrector) {
  CV_Assert(scale >= 1 && cell_mask.size() == cell_bgr.size());
  CV_Assert(!corrector || (corrector->scale() == scale && corrector->width() == cell_mask.cols &&
                           corrector->height() == cell_mask.rows));
  CV_Assert(cell_mask.cols == bgr.cols / scale && cell_mask.rows == bgr.rows / scale);
  CV_Assert(!cell_mask.empty() && scale <= kMaxScale && bgr.cols >= 2 && bgr.rows >= 2);
  const int width = bgr.cols;
  const int height = bgr.rows;
  const int cells_x = cell_mask.cols;
  const int cells_y = cell_mask.rows;
  cv::Mat1b mask(bgr.size());

  // Every pixel of the whole cells takes its cell's label: one row a row of
  // cells, copied to the cell's other rows.
  const int whole_width = cells_x * scale;
  const int whole_height = cells_y * scale;
  std::vector<int> cell_of(static_cast<std::size_t>(whole_width));
  for (int x = 0; x < whole_width; ++x) cell_of[x] = x / scale;
  for (int cy = 0; cy < cells_y; ++cy) {
    const std::uint8_t* labels = cell_mask[cy];
    std::uint8_t* row = mask[cy * scale];
    for (int x = 0; x < whole_width; ++x) row[x] = labels[cell_of[x]];
    for (int y = cy * scale + 1; y < (cy + 1) * scale; ++y) {
      std::memcpy(mask[y], row, static_cast<std::size_t>(whole_width));
    }
  }
  if (scale > 1) RefineBoundary(cell_mask, cell_bgr, bgr, scale, corrector, mask);
  // Beyond the whole cells, the nearest pixel's label.
  for (int y = 0; y < whole_height; ++y) {
    std::uint8_t* row = mask[y];
    std::memset(row + whole_width, row[whole_width - 1],
                static_cast<std::size_t>(width - whole_width));
  }
  for (int y = whole_height; y < height; ++y) {
    std::memcpy(mask[y], mask[whole_height - 1], static_cast<std::size_t>(width));
  }
  return mask;
}

}  // namespace pirouette::vision
