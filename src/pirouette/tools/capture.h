#pragma once

#include <atomic>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/vision/floor_segmenter.h"

namespace pirouette::tools {

// `pirouette capture`: a real camera and floor checked before a run. Frames
// from any OpenCV VideoCapture source are segmented in order by one online
// segmenter (the floor model learns from them as it would on the robot), and
// each frame used is written with its floor, and with a camera its obstacle
// profile, drawn over it.

// Frames used from a live source (a device or a stream) when no count is given.
inline constexpr int kLiveDefaultFrames = 100;

struct LiveCaptureRequest {
  std::string source;       // see io::ParseVideoSource
  std::string camera_path;  // empty: no camera (no correction, no profile)
  vision::SegmentationMethod method = vision::SegmentationMethod::kDefault;
  std::string out_dir = "capture";
  // Frames used before stopping; nullopt: all of a file, kLiveDefaultFrames
  // of a live source; 0: no limit (until the source ends or a stop).
  std::optional<int> max_frames;
  int every = 1;  // use every k-th frame of the source (>= 1); the others are skipped unseen
  // The profile's maximum range; nullopt: the camera's, by the paper's rule
  // (camera::MaxRange with 1 cm cells).
  std::optional<double> max_range_m;
  // Checked before each frame is read; when set, the capture stops and keeps
  // what it wrote.
  const std::atomic<bool>* stop_requested = nullptr;
};

// What one frame used showed.
struct CaptureFrame {
  int index = 0;                    // in the source, from 0 (skipped frames counted)
  std::string image;                // the overlay's file name in the output folder
  double floor_fraction = 0.0;      // of all the frame's pixels
  double reference_fraction = 0.0;  // of the reference region (bottom centre) that is floor
  std::optional<core::ProfileCounts> counts;  // of its obstacle profile, with a camera
  double seconds = 0.0;                       // segmentation and profile, not reading or writing
};

struct LiveCaptureProgress {
  int frames = 0;  // used so far
  const CaptureFrame* last = nullptr;
  double elapsed_s = 0.0;
};

enum class CaptureStop {
  kEnd,          // the source had no more frames
  kFrameLimit,   // max_frames were used
  kInterrupted,  // stop_requested was set
};
std::string_view CaptureStopName(CaptureStop stop);

struct LiveCaptureResult {
  std::vector<CaptureFrame> frames;  // in order
  int frames_read = 0;               // from the source, skipped ones included
  cv::Size frame_size;
  std::optional<double> max_range_m;  // with a camera
  CaptureStop stop = CaptureStop::kEnd;
  double wall_time_s = 0.0;
};

// Runs a capture: OUT/NNNNNN.png (NNNNNN the frame's index in the source) for
// each frame used, and OUT/profiles.jsonl (one CaptureFrameJson line a frame,
// rewritten every few seconds and at the end), all written atomically; the
// output folder is made at the first write, so refused input leaves none.
// `on_frame` (may be empty) is called after each frame used.
// Throws core::InputError (exit 2) for a bad request, a missing file, a source
// that cannot be opened or gives no frame, a bad camera file, or a frame whose
// size is not the camera's (naming both sizes); std::runtime_error when an
// output cannot be written (exit 1).
LiveCaptureResult RunLiveCapture(
    const LiveCaptureRequest& request,
    const std::function<void(const LiveCaptureProgress&)>& on_frame = {});

// One line of profiles.jsonl, without the newline: {"frame": …, "image": …,
// "floor_fraction": …, "reference_fraction": …, "seconds": …} and with
// counts "hit", "clear", "blind" (columns), "feet" (hits at the feet of
// obstacles' sides, ObstacleProfile::feet) and "nearest_hit_m" (a column's
// or a foot's; null when there is none).
std::string CaptureFrameJson(const CaptureFrame& frame);

// The capture's summary as JSON (format pirouette-capture/1): source, camera,
// method, frame size, frames used and read, why it stopped, mean floor and
// reference fractions, with a camera the mean counts a frame and the maximum
// range, seconds a frame, and the output folder.
std::string LiveCaptureSummaryJson(const LiveCaptureRequest& request,
                                   const LiveCaptureResult& result);

}  // namespace pirouette::tools
