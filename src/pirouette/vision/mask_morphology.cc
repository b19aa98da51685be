#include "pirouette/vision/mask_morphology.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <opencv2/imgproc.hpp>

namespace pirouette::vision {
namespace {

constexpr std::uint8_t kOn = 255;

// Fills the run of `candidate` row y through x that is not filled yet, and
// returns its ends [left, right].
std::pair<int, int> FillRun(const std::uint8_t* candidate, std::uint8_t* filled, int width, int x) {
  int left = x;
  while (left > 0 && candidate[left - 1] != 0 && filled[left - 1] == 0) --left;
  int right = x;
  while (right + 1 < width && candidate[right + 1] != 0 && filled[right + 1] == 0) ++right;
  std::memset(filled + left, kOn, static_cast<std::size_t>(right - left) + 1);
  return {left, right};
}

// The pixels of `in` with an "on" 4-neighbour that are on in `allowed` and off
// in `in` itself: one step of geodesic dilation, without the pixels of `in`.
void FirstStep(const cv::Mat1b& in, const cv::Mat1b& allowed, cv::Mat1b& out) {
  const int width = in.cols;
  const int height = in.rows;
  out.create(in.size());
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* up = y > 0 ? in[y - 1] : nullptr;
    const std::uint8_t* down = y + 1 < height ? in[y + 1] : nullptr;
    const std::uint8_t* row = in[y];
    const std::uint8_t* a = allowed[y];
    std::uint8_t* o = out[y];
    // Vertical neighbours first (absent rows count as off), then horizontal.
    if (up != nullptr && down != nullptr) {
      for (int x = 0; x < width; ++x) o[x] = up[x] | down[x];
    } else if (up != nullptr || down != nullptr) {
      std::memcpy(o, up != nullptr ? up : down, static_cast<std::size_t>(width));
    } else {
      std::memset(o, 0, static_cast<std::size_t>(width));
    }
    if (width > 1) {
      o[0] |= row[1];
      for (int x = 1; x + 1 < width; ++x) o[x] |= row[x - 1] | row[x + 1];
      o[width - 1] |= row[width - 2];
    }
    for (int x = 0; x < width; ++x) o[x] &= a[x] & static_cast<std::uint8_t>(~row[x]);
  }
}

}  // namespace

void FillFromSeeds(const cv::Mat1b& candidate, const cv::Mat1b& seeds, cv::Mat1b& filled) {
  CV_Assert(candidate.size() == seeds.size());
  const int width = candidate.cols;
  const int height = candidate.rows;
  filled.create(candidate.size());
  filled.setTo(0);
  // Heckbert's fill: a span [left, right] filled in row y - dy leaves row y
  // to scan over [left, right] in direction dy; a run found there that
  // overhangs the span also leaves row y - dy to scan under the overhangs.
  struct Pending {
    int y;
    int left;
    int right;
    int dy;
  };
  std::vector<Pending> pending;
  const auto push = [&](int y, int left, int right, int dy) {
    if (y >= 0 && y < height && left <= right) pending.push_back({y, left, right, dy});
  };
  for (int y0 = 0; y0 < height; ++y0) {
    const std::uint8_t* c0 = candidate[y0];
    const std::uint8_t* s0 = seeds[y0];
    const std::uint8_t* f0 = filled[y0];
    for (int x0 = 0; x0 < width; ++x0) {
      // Seeds are few: skip eight at a time where there are none.
      if (x0 + 8 <= width) {
        std::uint64_t eight = 0;
        std::memcpy(&eight, s0 + x0, sizeof(eight));
        if (eight == 0) {
          x0 += 7;
          continue;
        }
      }
      if (s0[x0] == 0 || c0[x0] == 0 || f0[x0] != 0) continue;
      const auto [l0, r0] = FillRun(c0, filled[y0], width, x0);
      push(y0 - 1, l0, r0, -1);
      push(y0 + 1, l0, r0, 1);
      while (!pending.empty()) {
        const Pending span = pending.back();
        pending.pop_back();
        const std::uint8_t* c = candidate[span.y];
        std::uint8_t* f = filled[span.y];
        for (int x = span.left; x <= span.right; ++x) {
          if (c[x] == 0 || f[x] != 0) continue;
          const auto [left, right] = FillRun(c, f, width, x);
          push(span.y + span.dy, left, right, span.dy);
          push(span.y - span.dy, left, span.left - 2, -span.dy);
          push(span.y - span.dy, span.right + 2, right, -span.dy);
          x = right;
        }
      }
    }
  }
}

MaskCloser::MaskCloser(int size)
    : element_(cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size))) {
  CV_Assert(size >= 1);
  centred_runs_ = size % 2 == 1;
  radius_ = size / 2;
  for (int r = 0; r < element_.rows && centred_runs_; ++r) {
    const auto* e = element_.ptr<std::uint8_t>(r);
    const int half = static_cast<int>(std::count(e, e + size, 1)) / 2;
    for (int c = 0; c < size; ++c) {
      centred_runs_ = centred_runs_ && (e[c] != 0) == (std::abs(c - radius_) <= half);
    }
    half_widths_.push_back(half);
  }
}

void MaskCloser::Close(cv::Mat1b& mask) {
  if (!centred_runs_) {
    cv::morphologyEx(mask, mask, cv::MORPH_CLOSE, element_);
    return;
  }
  Apply(mask, dilated_, Op::kDilate);
  Apply(dilated_, mask, Op::kErode);
}

void MaskCloser::Apply(const cv::Mat1b& in, cv::Mat1b& out, Op op) {
  CV_Assert(in.isContinuous());
  const int width = in.cols;
  const int height = in.rows;
  const std::size_t n = in.total();
  const int widest = *std::max_element(half_widths_.begin(), half_widths_.end());
  // The image widened by 1, 2, … pixels along its rows (OR for a dilation,
  // AND for an erosion), all rows at once, then each row's ends redone: beyond
  // the row's ends nothing counts.
  widened_.resize(static_cast<std::size_t>(widest) + 1);
  widened_[0] = in;  // the others are buffers of their own
  for (int k = 1; k <= widest; ++k) {
    widened_[k].create(in.size());
    const auto* f = widened_[k - 1].ptr<std::uint8_t>(0);
    auto* t = widened_[k].ptr<std::uint8_t>(0);
    if (width == 1) {
      std::memcpy(t, f, n);
      continue;
    }
    if (op == Op::kDilate) {
      for (std::size_t i = 1; i + 1 < n; ++i) t[i] = f[i - 1] | f[i] | f[i + 1];
      for (std::size_t row = 0; row < n; row += static_cast<std::size_t>(width)) {
        const std::size_t last = row + static_cast<std::size_t>(width) - 1;
        t[row] = f[row] | f[row + 1];
        t[last] = f[last - 1] | f[last];
      }
    } else {
      for (std::size_t i = 1; i + 1 < n; ++i) t[i] = f[i - 1] & f[i] & f[i + 1];
      for (std::size_t row = 0; row < n; row += static_cast<std::size_t>(width)) {
        const std::size_t last = row + static_cast<std::size_t>(width) - 1;
        t[row] = f[row] & f[row + 1];
        t[last] = f[last - 1] & f[last];
      }
    }
  }
  // Each of the element's rows: its widening of the image shifted by its
  // offset; rows beyond the image neither add (dilation) nor remove (erosion).
  out.create(in.size());
  CV_Assert(out.data != in.data && out.isContinuous());
  auto* o = out.ptr<std::uint8_t>(0);
  std::memset(o, op == Op::kDilate ? 0 : kOn, n);
  for (int r = 0; r < static_cast<int>(half_widths_.size()); ++r) {
    const int dy = r - radius_;
    const int first = std::max(0, -dy);  // the output rows whose source row exists
    const int last = std::min(height, height - dy);
    if (first >= last) continue;
    std::uint8_t* to = o + static_cast<std::size_t>(first) * width;
    const auto* from = widened_[half_widths_[r]].ptr<std::uint8_t>(first + dy);
    const std::size_t count = static_cast<std::size_t>(last - first) * width;
    if (op == Op::kDilate) {
      for (std::size_t i = 0; i < count; ++i) to[i] |= from[i];
    } else {
      for (std::size_t i = 0; i < count; ++i) to[i] &= from[i];
    }
  }
}

void MaskGrower::Grow(cv::Mat1b& mask, const cv::Mat1b& allowed, int steps) {
  CV_Assert(mask.size() == allowed.size() && steps >= 0);
  if (steps == 0) return;
  const int width = mask.cols;
  const int height = mask.rows;
  FirstStep(mask, allowed, first_);
  frontier_.clear();
  CV_Assert(first_.isContinuous() && mask.isContinuous());
  const auto* f = first_.ptr<std::uint8_t>(0);
  auto* marked = mask.ptr<std::uint8_t>(0);
  const int n = width * height;
  for (int i = 0; i < n;) {
    // Few pixels join at each step: skip eight at a time where none does.
    if (i + 8 <= n) {
      std::uint64_t eight = 0;
      std::memcpy(&eight, f + i, sizeof(eight));
      if (eight == 0) {
        i += 8;
        continue;
      }
    }
    if (f[i] != 0) {
      marked[i] = kOn;
      frontier_.push_back(i);
    }
    ++i;
  }
  // Later steps: the allowed, unmarked 4-neighbours of the last step's pixels.
  auto* m = mask.ptr<std::uint8_t>(0);
  const auto* a = allowed.ptr<std::uint8_t>(0);
  CV_Assert(mask.isContinuous() && allowed.isContinuous());
  for (int step = 1; step < steps && !frontier_.empty(); ++step) {
    next_.clear();
    for (const int i : frontier_) {
      const int x = i % width;
      const auto visit = [&](int j) {
        if (m[j] == 0 && a[j] != 0) {
          m[j] = kOn;
          next_.push_back(j);
        }
      };
      if (x > 0) visit(i - 1);
      if (x + 1 < width) visit(i + 1);
      if (i >= width) visit(i - width);
      if (i + width < width * height) visit(i + width);
    }
    frontier_.swap(next_);
  }
}

}  // namespace pirouette::vision
