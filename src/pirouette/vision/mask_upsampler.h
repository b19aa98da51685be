#pragma once

#include <opencv2/core.hpp>
#include <optional>

#include "pirouette/vision/vignetting_corrector.h"

namespace pirouette::vision {

// The floor mask of a frame from the mask found on its reduced copy (a cell
// per scale × scale block of pixels, its colour the block's mean), with the
// boundary placed to the pixel rather than to the cell.
//
// A cell whose four neighbours share its label passes the label to all its
// pixels. A cell on the mask's boundary (a 4-neighbour labelled otherwise)
// holds the edge somewhere inside it or beside it; each of its pixels goes to
// the class whose local mean colour is nearer its own (the nearest-mean rule,
// a two-class split of the boundary's colours as in the refinement pass of the
// segmenter): the classes' means are those of the cell's eight neighbours of
// each label, the pixel's colour is its own low-passed by [1 2 1]² / 16,
// corrected by its cell's vignetting factors when a corrector is given.
//
// The pixels beyond the last whole cell (a frame whose size is not a multiple
// of the scale) take the label of the nearest pixel of the whole cells.
//
// `cell_mask` (255 floor, 0 not) and `cell_bgr` (corrected, if `corrector`)
// are the reduced frame's, (bgr.cols / scale) × (bgr.rows / scale), scale >=
// 1; `corrector`, if any, corrects that grid (its scale is `scale`). Returns a
// new mask of bgr's size.
cv::Mat1b UpsampleFloorMask(const cv::Mat1b& cell_mask, const cv::Mat3b& cell_bgr,
                            const cv::Mat3b& bgr, int scale,
                            const std::optional<VignettingCorrector>& corrector);

}  // namespace pirouette::vision
