#pragma once

#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

#include "pirouette/core/pose2.h"
#include "pirouette/mapping/occupancy_grid.h"

namespace pirouette::draw {

// explore.mp4 (H.264 through OpenCV's FFmpeg backend): at each camera frame,
// the map growing on the left (with the path so far and the robot) beside
// the camera's view with its floor segmentation drawn over it.
// Written to a temporary name and renamed by Finish(), so that a run that
// dies never leaves a broken video under the final name.
class ExplorationVideo {
 public:
  // Throws std::runtime_error when the encoder cannot be opened.
  explicit ExplorationVideo(std::string path, double fps = 12.0);
  ExplorationVideo(const ExplorationVideo&) = delete;
  ExplorationVideo& operator=(const ExplorationVideo&) = delete;
  ~ExplorationVideo();

  // One camera frame: its raw image (BGR), its floor (255), where it was
  // taken in the map, and the map after it.
  void AddFrame(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask, const core::Pose2& map_T_robot,
                const mapping::OccupancyGrid& grid);
  // Closes the file and gives it its final name.
  void Finish();

 private:
  std::string path_;
  std::string partial_path_;
  cv::VideoWriter writer_;
  std::vector<core::Pose2> path_so_far_;
  bool finished_ = false;
};

}  // namespace pirouette::draw
