#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <vector>

namespace pirouette::vision {

// Operations on binary masks (8-bit, 0 off, 255 on) that the default
// segmenter runs on every frame, each equal to a composition of OpenCV calls
// (which the tests check) but in a few passes over the mask or in time
// proportional to the pixels they change, keeping their buffers.

// The pixels of `candidate` 4-connected within it to a pixel of `seeds` that
// is also in it: the connected components (cv::connectedComponents, 4-way) of
// candidate that hold a seed, by a scan-line flood fill from the seeds (Heckbert,
// "A seed fill algorithm", Graphics Gems 1990). `filled` is (re)allocated to
// the candidate's size unless it has it already; same sizes throughout.
void FillFromSeeds(const cv::Mat1b& candidate, const cv::Mat1b& seeds, cv::Mat1b& filled);

// Closing (dilation, then erosion) by a structuring element whose rows are
// runs centred on its anchor column, such as cv::getStructuringElement's
// ellipses, rectangles and crosses of odd size; pixels outside the image never
// count, as with cv::morphologyEx's default border. Each row of the element is
// a horizontal dilation of the image's row (by repeated 3-wide passes) ORed
// across the element's rows, so the cost is a few passes over the image.
// Elements of even size (not centred) are left to cv::morphologyEx.
class MaskCloser {
 public:
  // The element cv::getStructuringElement(MORPH_ELLIPSE, size × size), size >= 1.
  explicit MaskCloser(int size);

  // `mask` closed, in place: cv::morphologyEx(mask, mask, MORPH_CLOSE, element).
  void Close(cv::Mat1b& mask);

 private:
  enum class Op { kDilate, kErode };
  void Apply(const cv::Mat1b& in, cv::Mat1b& out, Op op);

  cv::Mat element_;
  bool centred_runs_ = false;       // whether the rows are centred runs (odd size)
  std::vector<int> half_widths_;    // per row of the element, top to bottom
  int radius_ = 0;                  // the element's half height
  std::vector<cv::Mat1b> widened_;  // the image widened by 0, 1, … max half width
  cv::Mat1b dilated_;
};

// Grows `mask` into `allowed` by `steps` steps of the 3×3 cross (a geodesic
// dilation): each step adds the allowed pixels 4-adjacent to the mask, as
// `steps` times mask |= dilate(mask, cross) & allowed, breadth first from the
// mask's edge. Same sizes.
class MaskGrower {
 public:
  void Grow(cv::Mat1b& mask, const cv::Mat1b& allowed, int steps);

 private:
  cv::Mat1b first_;  // the pixels the first step adds
  std::vector<int> frontier_;
  std::vector<int> next_;
};

}  // namespace pirouette::vision
