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

namespace pirouette::app {

// `pirouette capture`: a real camera and floor checked before a run. Frames
// from any OpenCV VideoCapture source are segmented in order by one online
// segmenter (the floor model learns from them as it would on the robot), and
// each frame used is written with its floor, and with a camera its obstacle
// profile, drawn over it.

// Frames used from a live source (a device or a stream) when no count is given.
inline constexpr int kLiveDefaultFrames = 100;

// A video source as the user names it.
struct VideoSource {
  std::string name;                 // as given, for messages
  std::optional<int> device_index;  // "0", "1", …: a camera device
  bool is_stream = false;           // a URL (scheme://…): rtsp, http, …
  // A device or a stream: it has no end of its own.
  bool live() const { return device_index.has_value() || is_stream; }
};

// A string of decimal digits is a device index; "scheme://…" a stream; anything
// else a file path (write "./0" for a file named "0"). Throws core::InputError
// for an empty source.
VideoSource ParseVideoSource(std::string_view source);

struct LiveCaptureRequest {
  std::string source;       // see ParseVideoSource
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

// How a profile's columns read: counts of each kind and the nearest hit.
struct ProfileCounts {
  int hit = 0;
  int clear = 0;
  int blind = 0;
  std::optional<double> nearest_hit_m;  // nullopt: no hit
};
ProfileCounts CountReadings(const core::ObstacleProfile& profile);

// What one frame used showed.
struct CaptureFrame {
  int index = 0;                        // in the source, from 0 (skipped frames counted)
  std::string image;                    // the overlay's file name in the output folder
  double floor_fraction = 0.0;          // of all the frame's pixels
  double reference_fraction = 0.0;      // of the reference region (bottom centre) that is floor
  std::optional<ProfileCounts> counts;  // of its obstacle profile, with a camera
  double seconds = 0.0;                 // segmentation and profile, not reading or writing
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

// The pixel row of each reading's floor point in the frame of `camera` (the
// column's own row where the profile read it), clamped into the frame; -1
// where the point cannot be seen (behind the camera).
std::vector<int> ReadingRows(const core::ObstacleProfile& profile,
                             const camera::CameraModel& camera);

// The overlay of one frame (BGR): the floor tinted green with its boundary in
// red (DrawFloorOverlay), and with a profile (`profile`, the frame's, and
// `reading_rows` from ReadingRows) a mark per column at its reading's row (hit
// yellow, clear cyan, blind magenta at the bottom), enlarged by a whole factor to at least
// kMinOverlayWidth pixels wide; below it, with a profile, each column's range as a bar (full
// height: the maximum range), then a caption: the frame's index, floor fractions and counts.
inline constexpr int kMinOverlayWidth = 320;
cv::Mat3b DrawCaptureOverlay(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask,
                             const CaptureFrame& frame,
                             const std::optional<core::ObstacleProfile>& profile,
                             const std::vector<int>& reading_rows);

// One line of profiles.jsonl, without the newline: {"frame": …, "image": …,
// "floor_fraction": …, "reference_fraction": …, "seconds": …} and with
// counts "hit", "clear", "blind" (columns) and "nearest_hit_m" (null when no
// hit).
std::string CaptureFrameJson(const CaptureFrame& frame);

// The capture's summary as JSON (format pirouette-capture/1): source, camera,
// method, frame size, frames used and read, why it stopped, mean floor and
// reference fractions, with a camera the mean counts a frame and the maximum
// range, seconds a frame, and the output folder.
std::string LiveCaptureSummaryJson(const LiveCaptureRequest& request,
                                   const LiveCaptureResult& result);

}  // namespace pirouette::app
