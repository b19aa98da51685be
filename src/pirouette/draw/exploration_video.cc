#include "pirouette/draw/exploration_video.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "pirouette/draw/floor_overlay.h"
#include "pirouette/draw/map_picture.h"
#include "pirouette/draw/palette.h"

namespace pirouette::draw {
namespace {

constexpr int kPanel = 480;      // each panel's height; the map's is square
constexpr int kMarginCells = 5;  // round the map's known cells, as map.pgm has

// `image` scaled to fit in a w × h box, centred on `background`.
// `roi` is a header onto the frame's pixels, taken by value so that it can be written.
void PlaceFitted(const cv::Mat3b& image,
                 cv::Mat3b roi) {  // NOLINT(performance-unnecessary-value-param)
  const double s = std::min(static_cast<double>(roi.cols) / image.cols,
                            static_cast<double>(roi.rows) / image.rows);
  cv::Mat3b scaled;
  cv::resize(image, scaled, {}, s, s, s < 1.0 ? cv::INTER_AREA : cv::INTER_NEAREST);
  const int x = (roi.cols - scaled.cols) / 2;
  const int y = (roi.rows - scaled.rows) / 2;
  scaled.copyTo(roi(cv::Rect(x, y, scaled.cols, scaled.rows)));
}

}  // namespace

ExplorationVideo::ExplorationVideo(std::string path, double fps)
    : path_(std::move(path)), partial_path_(path_ + ".partial.mp4") {
  writer_.open(partial_path_, cv::CAP_FFMPEG, cv::VideoWriter::fourcc('a', 'v', 'c', '1'), fps,
               cv::Size(kPanel + kPanel * 4 / 3, kPanel));
  if (!writer_.isOpened()) {
    throw std::runtime_error("cannot open a video encoder (H.264 through FFmpeg) for " +
                             partial_path_);
  }
}

ExplorationVideo::~ExplorationVideo() {
  if (!finished_) {
    writer_.release();
    std::error_code ignored;
    std::filesystem::remove(partial_path_, ignored);
  }
}

void ExplorationVideo::AddFrame(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask,
                                const core::Pose2& map_T_robot,
                                const mapping::OccupancyGrid& grid) {
  path_so_far_.push_back(map_T_robot);
  cv::Mat3b canvas(kPanel, kPanel + kPanel * 4 / 3, kWhite);
  const cv::Mat3b map = DrawMapPicture(grid.CroppedToKnown(kMarginCells), path_so_far_, {}, kPanel);
  PlaceFitted(map, canvas(cv::Rect(0, 0, kPanel, kPanel)));
  const cv::Mat3b view = DrawFloorOverlay(bgr, floor_mask);
  PlaceFitted(view, canvas(cv::Rect(kPanel, 0, kPanel * 4 / 3, kPanel)));
  writer_.write(canvas);
}

void ExplorationVideo::Finish() {
  writer_.release();
  std::filesystem::rename(partial_path_, path_);
  finished_ = true;
}

}  // namespace pirouette::draw
