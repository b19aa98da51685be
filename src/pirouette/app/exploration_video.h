#pragma once

#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

#include "pirouette/app/exploration.h"

namespace pirouette::app {

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

  void AddFrame(const FrameEvent& event);
  // Closes the file and gives it its final name.
  void Finish();

 private:
  std::string path_;
  std::string partial_path_;
  cv::VideoWriter writer_;
  std::vector<core::Pose2> path_so_far_;
  bool finished_ = false;
};

}  // namespace pirouette::app
