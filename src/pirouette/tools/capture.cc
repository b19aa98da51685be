#include "pirouette/tools/capture.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <system_error>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/input_error.h"
#include "pirouette/draw/capture_overlay.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/io/video_source.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/run/stage_timer.h"
#include "pirouette/tools/json_output.h"
#include "pirouette/vision/profile_extractor.h"
#include "pirouette/vision/vertical_direction_field.h"

namespace pirouette::tools {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// profiles.jsonl is rewritten at most this often while a capture runs, so that
// a capture that dies keeps the summary of most of its frames.
constexpr double kProfilesFlushSeconds = 5.0;

void PrepareOutDir(const std::string& out_dir) {
  std::error_code error;
  if (fs::exists(out_dir, error) && !fs::is_directory(out_dir, error)) {
    throw core::InputError(out_dir, 0, "", "exists and is not a folder");
  }
  fs::create_directories(out_dir, error);
  if (error) {
    throw std::runtime_error(
        fmt::format("{}: the output folder cannot be created: {}", out_dir, error.message()));
  }
}

void WriteProfiles(const std::string& out_dir, const std::vector<CaptureFrame>& frames) {
  std::string text;
  for (const CaptureFrame& frame : frames) {
    text += CaptureFrameJson(frame);
    text += '\n';
  }
  io::WriteFileAtomically((fs::path(out_dir) / "profiles.jsonl").string(), text);
}

void CheckCaptureRequest(const LiveCaptureRequest& request) {
  if (request.every < 1) throw core::InputError("", 0, "every", "must be 1 or more");
  if (request.max_frames && *request.max_frames < 0) {
    throw core::InputError("", 0, "frames", "must be 0 (no limit) or more");
  }
  if (request.max_range_m && !(*request.max_range_m > 0.0)) {
    throw core::InputError("", 0, "max-range", "must be a positive number of metres");
  }
}

// With a camera file: the camera and the extractor of its frames' profiles.
struct CaptureCamera {
  std::optional<camera::CameraModel> camera;
  std::optional<vision::ProfileExtractor> extractor;
};

CaptureCamera LoadCaptureCamera(const LiveCaptureRequest& request) {
  CaptureCamera loaded;
  if (request.camera_path.empty()) return loaded;
  loaded.camera = io::LoadCameraFile(request.camera_path);
  const double max_range =
      request.max_range_m.value_or(camera::MaxRange(*loaded.camera, mapping::kSmallRobotCellM));
  loaded.extractor.emplace(camera::InversePerspectiveMap(*loaded.camera), max_range,
                           vision::VerticalDirectionField(*loaded.camera));
  return loaded;
}

// The output folder, made at the first write so that refused input leaves none.
class OutFolder {
 public:
  explicit OutFolder(std::string dir) : dir_(std::move(dir)) {}
  void Prepare() {
    if (!ready_) PrepareOutDir(dir_);
    ready_ = true;
  }

 private:
  std::string dir_;
  bool ready_ = false;
};

// Why the capture stops before reading another frame, if it does.
std::optional<CaptureStop> StopBeforeFrame(const LiveCaptureRequest& request, int limit,
                                           std::size_t frames_used) {
  if (limit > 0 && static_cast<int>(frames_used) >= limit) return CaptureStop::kFrameLimit;
  if (request.stop_requested != nullptr && request.stop_requested->load()) {
    return CaptureStop::kInterrupted;
  }
  return std::nullopt;
}

// Refuses a frame of another size than the camera's, keeping the summary of
// the frames used so far.
void CheckFrameSize(const cv::Mat3b& bgr, int index, const LiveCaptureRequest& request,
                    const CaptureCamera& camera, const std::string& source,
                    const std::vector<CaptureFrame>& frames) {
  if (!camera.camera ||
      (bgr.cols == camera.camera->width() && bgr.rows == camera.camera->height())) {
    return;
  }
  if (!frames.empty()) WriteProfiles(request.out_dir, frames);
  throw core::InputError(
      source, 0, "",
      fmt::format("frame {} is {}×{} but the camera {} is {}×{}", index, bgr.cols, bgr.rows,
                  request.camera_path, camera.camera->width(), camera.camera->height()));
}

// Segments one frame used (and reads its profile) and writes its overlay.
// `reference` is the reference region's mask at the frame's size.
CaptureFrame CaptureOne(const cv::Mat3b& bgr, int index, vision::FloorSegmenter& segmenter,
                        const CaptureCamera& camera, const cv::Mat1b& reference,
                        const std::string& out_dir, OutFolder& out) {
  const Clock::time_point t0 = Clock::now();
  const cv::Mat1b mask = segmenter.Segment(bgr);
  std::optional<core::ObstacleProfile> profile;
  if (camera.extractor) profile = camera.extractor->Extract(mask);
  CaptureFrame frame;
  frame.seconds = run::Seconds(Clock::now() - t0);
  frame.index = index;
  frame.image = fmt::format("{:06d}.png", index);
  frame.floor_fraction = static_cast<double>(cv::countNonZero(mask)) / bgr.size().area();
  const int reference_pixels = cv::countNonZero(reference);
  frame.reference_fraction =
      reference_pixels > 0
          ? static_cast<double>(cv::countNonZero(mask & reference)) / reference_pixels
          : 0.0;
  if (profile) frame.counts = core::CountReadings(*profile);

  const std::vector<int> rows =
      profile ? draw::ReadingRows(*profile, *camera.camera) : std::vector<int>();
  const std::vector<cv::Point> feet =
      profile ? draw::FootPixels(*profile, *camera.camera) : std::vector<cv::Point>();
  out.Prepare();
  io::WritePng(
      (fs::path(out_dir) / frame.image).string(),
      draw::DrawCaptureOverlay(
          bgr, mask, {frame.index, frame.floor_fraction, frame.reference_fraction, frame.counts},
          profile, rows, feet));
  return frame;
}

}  // namespace

std::string_view CaptureStopName(CaptureStop stop) {
  switch (stop) {
    case CaptureStop::kEnd:
      return "end";
    case CaptureStop::kFrameLimit:
      return "frames";
    case CaptureStop::kInterrupted:
      break;
  }
  return "interrupted";
}

LiveCaptureResult RunLiveCapture(const LiveCaptureRequest& request,
                                 const std::function<void(const LiveCaptureProgress&)>& on_frame) {
  const Clock::time_point start = Clock::now();
  CheckCaptureRequest(request);
  const io::VideoSource source = io::ParseVideoSource(request.source);
  const CaptureCamera camera = LoadCaptureCamera(request);
  LiveCaptureResult result;
  if (camera.extractor) result.max_range_m = camera.extractor->max_range_m();
  cv::VideoCapture capture = io::OpenVideoSource(source);
  OutFolder out(request.out_dir);

  const int limit = request.max_frames.value_or(source.live() ? kLiveDefaultFrames : 0);
  const std::unique_ptr<vision::FloorSegmenter> segmenter =
      vision::MakeFloorSegmenter(request.method, camera.camera);
  cv::Mat1b reference;  // the reference region of the current frame size
  Clock::time_point last_flush = start;
  cv::Mat raw;
  for (int index = 0;; ++index) {
    if (const std::optional<CaptureStop> stop =
            StopBeforeFrame(request, limit, result.frames.size())) {
      result.stop = *stop;
      break;
    }
    if (!capture.grab()) break;
    ++result.frames_read;
    if (index % request.every != 0) continue;
    if (!capture.retrieve(raw) || raw.empty()) break;
    const cv::Mat3b bgr = io::ToBgrFrame(raw, source.name);
    if (result.frames.empty()) result.frame_size = bgr.size();
    CheckFrameSize(bgr, index, request, camera, source.name, result.frames);
    if (reference.size() != bgr.size()) {
      reference = vision::ReferenceRegionMask(bgr.size(), vision::ReferenceRegion{});
    }
    result.frames.push_back(
        CaptureOne(bgr, index, *segmenter, camera, reference, request.out_dir, out));
    if (run::Seconds(Clock::now() - last_flush) >= kProfilesFlushSeconds) {
      WriteProfiles(request.out_dir, result.frames);
      last_flush = Clock::now();
    }
    if (on_frame) {
      on_frame({static_cast<int>(result.frames.size()), &result.frames.back(),
                run::Seconds(Clock::now() - start)});
    }
  }
  if (result.frames_read == 0 && result.stop == CaptureStop::kEnd) {
    throw core::InputError(source.name, 0, "", "no frame could be read from it");
  }
  out.Prepare();
  WriteProfiles(request.out_dir, result.frames);
  result.wall_time_s = run::Seconds(Clock::now() - start);
  return result;
}

std::string CaptureFrameJson(const CaptureFrame& frame) {
  nlohmann::ordered_json line;
  line["frame"] = frame.index;
  line["image"] = frame.image;
  line["floor_fraction"] = RoundTo(frame.floor_fraction, 4);
  line["reference_fraction"] = RoundTo(frame.reference_fraction, 4);
  if (frame.counts) {
    line["hit"] = frame.counts->hit;
    line["clear"] = frame.counts->clear;
    line["blind"] = frame.counts->blind;
    line["feet"] = frame.counts->feet;
    line["nearest_hit_m"] = frame.counts->nearest_hit_m
                                ? nlohmann::ordered_json(RoundTo(*frame.counts->nearest_hit_m, 4))
                                : nlohmann::ordered_json(nullptr);
  }
  line["seconds"] = RoundTo(frame.seconds, 5);
  return line.dump();
}

std::string LiveCaptureSummaryJson(const LiveCaptureRequest& request,
                                   const LiveCaptureResult& result) {
  nlohmann::ordered_json summary;
  summary["format"] = "pirouette-capture/1";
  summary["source"] = request.source;
  summary["camera"] = request.camera_path.empty() ? nlohmann::ordered_json(nullptr)
                                                  : nlohmann::ordered_json(request.camera_path);
  summary["method"] = std::string(vision::SegmentationMethodName(request.method));
  summary["frame_size"] = {result.frame_size.width, result.frame_size.height};
  summary["frames"] = result.frames.size();
  summary["frames_read"] = result.frames_read;
  summary["every"] = request.every;
  summary["stopped"] = std::string(CaptureStopName(result.stop));
  const double n = std::max<double>(1.0, static_cast<double>(result.frames.size()));
  double floor = 0.0;
  double reference = 0.0;
  double seconds = 0.0;
  double hit = 0.0;
  double clear = 0.0;
  double blind = 0.0;
  double feet = 0.0;
  for (const CaptureFrame& f : result.frames) {
    floor += f.floor_fraction;
    reference += f.reference_fraction;
    seconds += f.seconds;
    if (f.counts) {
      hit += f.counts->hit;
      clear += f.counts->clear;
      blind += f.counts->blind;
      feet += f.counts->feet;
    }
  }
  summary["mean_floor_fraction"] = RoundTo(floor / n, 4);
  summary["mean_reference_fraction"] = RoundTo(reference / n, 4);
  if (result.max_range_m) {
    summary["max_range_m"] = RoundTo(*result.max_range_m, 4);
    summary["mean_hit"] = RoundTo(hit / n, 1);
    summary["mean_clear"] = RoundTo(clear / n, 1);
    summary["mean_blind"] = RoundTo(blind / n, 1);
    summary["mean_feet"] = RoundTo(feet / n, 1);
  }
  summary["seconds_per_frame"] = RoundTo(seconds / n, 5);
  summary["wall_time_s"] = RoundTo(result.wall_time_s, 3);
  summary["out"] = request.out_dir;
  return JsonText(summary, 2);
}

}  // namespace pirouette::tools
