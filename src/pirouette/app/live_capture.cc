#include "pirouette/app/live_capture.h"

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

#include "pirouette/app/segment_image.h"
#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/run/stage_timer.h"
#include "pirouette/vision/profile_extractor.h"

namespace pirouette::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// profiles.jsonl is rewritten at most this often while a capture runs, so that
// a capture that dies keeps the summary of most of its frames.
constexpr double kProfilesFlushSeconds = 5.0;

// Overlay colours (BGR).
const cv::Vec3b kHitColour(0, 230, 255);     // yellow
const cv::Vec3b kClearColour(255, 220, 0);   // cyan
const cv::Vec3b kBlindColour(255, 0, 255);   // magenta
const cv::Vec3b kPanelColour(32, 32, 32);    // the strip and caption background
const cv::Vec3b kTextColour(230, 230, 230);  // caption text

constexpr int kStripHeight = 48;    // the range bars, pixels
constexpr int kCaptionLine = 16;    // one caption line, pixels
constexpr double kFontScale = 0.9;  // cv::FONT_HERSHEY_PLAIN

const cv::Vec3b& KindColour(core::ReadingKind kind) {
  switch (kind) {
    case core::ReadingKind::kHit:
      return kHitColour;
    case core::ReadingKind::kClear:
      return kClearColour;
    case core::ReadingKind::kBlind:
      break;
  }
  return kBlindColour;
}

cv::VideoCapture OpenSource(const VideoSource& source) {
  cv::VideoCapture capture;
  if (source.device_index) {
    capture.open(*source.device_index);
    if (!capture.isOpened()) {
      throw core::InputError(source.name, 0, "",
                             fmt::format("camera device {} cannot be opened (is it plugged in, "
                                         "and not in use?)",
                                         *source.device_index));
    }
    return capture;
  }
  if (!source.is_stream) {
    std::error_code error;
    if (!fs::exists(source.name, error)) throw core::InputError(source.name, 0, "", "no such file");
    if (fs::is_directory(source.name, error)) {
      throw core::InputError(source.name, 0, "", "is a folder, not a video");
    }
  }
  capture.open(source.name);
  if (!capture.isOpened()) {
    throw core::InputError(source.name, 0, "",
                           source.is_stream
                               ? "the stream cannot be opened (unreachable, or not a video stream "
                                 "OpenCV can read)"
                               : "cannot be opened as a video (not a video OpenCV can read)");
  }
  return capture;
}

// The frame as 8-bit BGR; throws core::InputError for a depth we do not read.
cv::Mat3b ToBgr(const cv::Mat& raw, const std::string& source) {
  if (raw.depth() != CV_8U) {
    throw core::InputError(source, 0, "", "frames that are not 8 bits a channel are not supported");
  }
  cv::Mat3b bgr;
  switch (raw.channels()) {
    case 1:
      cv::cvtColor(raw, bgr, cv::COLOR_GRAY2BGR);
      break;
    case 3:
      bgr = raw;
      break;
    case 4:
      cv::cvtColor(raw, bgr, cv::COLOR_BGRA2BGR);
      break;
    default:
      throw core::InputError(
          source, 0, "", fmt::format("frames with {} channels are not supported", raw.channels()));
  }
  return bgr;
}

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

// Writes `text` from `x` on the caption line whose baseline is `y`; returns
// the x after it.
int PutText(cv::Mat3b& image, const std::string& text, int x, int y, const cv::Vec3b& colour) {
  cv::putText(image, text, cv::Point(x, y), cv::FONT_HERSHEY_PLAIN, kFontScale,
              cv::Scalar(colour[0], colour[1], colour[2]), 1, cv::LINE_AA);
  int baseline = 0;
  return x + cv::getTextSize(text, cv::FONT_HERSHEY_PLAIN, kFontScale, 1, &baseline).width;
}

// `v` to `digits` decimals, as the nearest double (so that it prints short).
double Round(double v, int digits) {
  const double scale = std::pow(10.0, digits);
  return std::round(v * scale) / scale;
}

}  // namespace

VideoSource ParseVideoSource(std::string_view source) {
  if (source.empty()) throw core::InputError("", 0, "source", "is empty");
  VideoSource parsed;
  parsed.name = std::string(source);
  const bool digits = source.size() <= 6 && std::all_of(source.begin(), source.end(), [](char c) {
                        return c >= '0' && c <= '9';
                      });
  if (digits) {
    parsed.device_index = std::stoi(parsed.name);
  } else {
    const std::size_t scheme = source.find("://");
    if (scheme != std::string_view::npos && scheme > 0) {
      const std::string_view name = source.substr(0, scheme);
      parsed.is_stream = std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalpha(static_cast<unsigned char>(c)) != 0;
      });
    }
  }
  return parsed;
}

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

ProfileCounts CountReadings(const core::ObstacleProfile& profile) {
  ProfileCounts counts;
  for (const core::RangeReading& r : profile.readings) {
    switch (r.kind) {
      case core::ReadingKind::kHit:
        ++counts.hit;
        if (!counts.nearest_hit_m || r.range_m < *counts.nearest_hit_m) {
          counts.nearest_hit_m = r.range_m;
        }
        break;
      case core::ReadingKind::kClear:
        ++counts.clear;
        break;
      case core::ReadingKind::kBlind:
        ++counts.blind;
        break;
    }
  }
  return counts;
}

LiveCaptureResult RunLiveCapture(const LiveCaptureRequest& request,
                                 const std::function<void(const LiveCaptureProgress&)>& on_frame) {
  const Clock::time_point start = Clock::now();
  if (request.every < 1) throw core::InputError("", 0, "every", "must be 1 or more");
  if (request.max_frames && *request.max_frames < 0) {
    throw core::InputError("", 0, "frames", "must be 0 (no limit) or more");
  }
  if (request.max_range_m && !(*request.max_range_m > 0.0)) {
    throw core::InputError("", 0, "max-range", "must be a positive number of metres");
  }
  const VideoSource source = ParseVideoSource(request.source);
  std::optional<camera::CameraModel> camera;
  std::optional<vision::ProfileExtractor> extractor;
  LiveCaptureResult result;
  if (!request.camera_path.empty()) {
    camera = io::LoadCameraFile(request.camera_path);
    result.max_range_m = request.max_range_m.value_or(camera::MaxRange(*camera, 0.01));
    extractor.emplace(camera::InversePerspectiveMap(*camera), *result.max_range_m);
  }
  cv::VideoCapture capture = OpenSource(source);
  bool out_ready = false;  // the folder is made before the first write: not for refused input
  const auto prepare_out = [&] {
    if (!out_ready) PrepareOutDir(request.out_dir);
    out_ready = true;
  };

  const int limit = request.max_frames.value_or(source.live() ? kLiveDefaultFrames : 0);
  const std::unique_ptr<vision::FloorSegmenter> segmenter =
      vision::MakeFloorSegmenter(request.method, camera);
  cv::Mat1b reference;  // the reference region of the current frame size
  Clock::time_point last_flush = start;
  cv::Mat raw;
  for (int index = 0;; ++index) {
    if (limit > 0 && static_cast<int>(result.frames.size()) >= limit) {
      result.stop = CaptureStop::kFrameLimit;
      break;
    }
    if (request.stop_requested != nullptr && request.stop_requested->load()) {
      result.stop = CaptureStop::kInterrupted;
      break;
    }
    if (!capture.grab()) break;
    ++result.frames_read;
    if (index % request.every != 0) continue;
    if (!capture.retrieve(raw) || raw.empty()) break;
    const cv::Mat3b bgr = ToBgr(raw, source.name);
    if (result.frames.empty()) result.frame_size = bgr.size();
    if (camera && (bgr.cols != camera->width() || bgr.rows != camera->height())) {
      if (!result.frames.empty()) WriteProfiles(request.out_dir, result.frames);
      throw core::InputError(
          source.name, 0, "",
          fmt::format("frame {} is {}×{} but the camera {} is {}×{}", index, bgr.cols, bgr.rows,
                      request.camera_path, camera->width(), camera->height()));
    }
    if (reference.size() != bgr.size()) {
      reference = vision::ReferenceRegionMask(bgr.size(), vision::ReferenceRegion{});
    }

    const Clock::time_point t0 = Clock::now();
    const cv::Mat1b mask = segmenter->Segment(bgr);
    std::optional<core::ObstacleProfile> profile;
    if (extractor) profile = extractor->Extract(mask);
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
    if (profile) frame.counts = CountReadings(*profile);

    const std::vector<int> rows = profile ? ReadingRows(*profile, *camera) : std::vector<int>();
    prepare_out();
    io::WritePng((fs::path(request.out_dir) / frame.image).string(),
                 DrawCaptureOverlay(bgr, mask, frame, profile, rows));
    result.frames.push_back(std::move(frame));
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
  prepare_out();
  WriteProfiles(request.out_dir, result.frames);
  result.wall_time_s = run::Seconds(Clock::now() - start);
  return result;
}

std::vector<int> ReadingRows(const core::ObstacleProfile& profile,
                             const camera::CameraModel& camera) {
  const Eigen::Isometry3d camera_T_robot = camera.robot_T_camera().inverse();
  std::vector<int> rows;
  rows.reserve(profile.readings.size());
  for (const core::RangeReading& r : profile.readings) {
    const Eigen::Vector3d p_robot(r.range_m * std::cos(r.bearing_rad),
                                  r.range_m * std::sin(r.bearing_rad), 0.0);
    const std::optional<Eigen::Vector2d> pixel = camera.Project(camera_T_robot * p_robot);
    if (!pixel) {
      rows.push_back(-1);
      continue;
    }
    const long row = std::lround(pixel->y());
    rows.push_back(static_cast<int>(std::clamp<long>(row, 0, camera.height() - 1)));
  }
  return rows;
}

cv::Mat3b DrawCaptureOverlay(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask,
                             const CaptureFrame& frame,
                             const std::optional<core::ObstacleProfile>& profile,
                             const std::vector<int>& reading_rows) {
  CV_Assert(!profile || (profile->readings.size() == static_cast<std::size_t>(bgr.cols) &&
                         reading_rows.size() == profile->readings.size()));
  const int scale = std::max(1, (kMinOverlayWidth + bgr.cols - 1) / bgr.cols);
  cv::Mat3b view;
  cv::resize(DrawFloorOverlay(bgr, floor_mask), view, cv::Size(), scale, scale, cv::INTER_NEAREST);
  const int width = view.cols;
  const int strip = profile ? kStripHeight : 0;
  const int caption = 2 * kCaptionLine + 4;
  cv::Mat3b out(view.rows + strip + caption, width, kPanelColour);
  view.copyTo(out(cv::Rect(0, 0, width, view.rows)));

  if (profile) {
    const int bottom = bgr.rows - 1;
    for (int u = 0; u < bgr.cols; ++u) {
      const core::RangeReading& r = profile->readings[u];
      const int row = r.kind == core::ReadingKind::kBlind ? bottom : reading_rows[u];
      if (row < 0) continue;
      // A mark two frame pixels high, centred on the reading's row.
      const int y0 = std::clamp(row * scale - scale / 2, 0, view.rows - 2 * scale);
      out(cv::Rect(u * scale, y0, scale, 2 * scale)).setTo(KindColour(r.kind));
    }
    // The range strip: a bar a column, full height at the maximum range.
    const int top = view.rows;
    const int bar_max = kStripHeight - 4;
    for (int u = 0; u < bgr.cols; ++u) {
      const core::RangeReading& r = profile->readings[u];
      const double fraction = std::clamp(r.range_m / profile->max_range_m, 0.0, 1.0);
      const int h = static_cast<int>(std::lround(fraction * bar_max));
      if (h <= 0) continue;
      out(cv::Rect(u * scale, top + kStripHeight - h, scale, h)).setTo(KindColour(r.kind));
    }
    out(cv::Rect(0, top + kStripHeight - bar_max - 1, width, 1)).setTo(cv::Vec3b(90, 90, 90));
    PutText(out, fmt::format("{:.2f} m", profile->max_range_m), 2, top + 12, kTextColour);
  }

  const int line1 = view.rows + strip + kCaptionLine;
  const int line2 = line1 + kCaptionLine;
  PutText(out,
          fmt::format("#{:06d} floor {:.0f}% ref {:.0f}%", frame.index,
                      100.0 * frame.floor_fraction, 100.0 * frame.reference_fraction),
          2, line1, kTextColour);
  if (frame.counts) {
    int x = PutText(out, fmt::format("hit {}", frame.counts->hit), 2, line2, kHitColour);
    x = PutText(out, fmt::format(" clear {}", frame.counts->clear), x, line2, kClearColour);
    x = PutText(out, fmt::format(" blind {}", frame.counts->blind), x, line2, kBlindColour);
    if (frame.counts->nearest_hit_m) {
      PutText(out, fmt::format(" near {:.2f} m", *frame.counts->nearest_hit_m), x, line2,
              kTextColour);
    }
  } else {
    PutText(out, "no camera: no profile", 2, line2, kTextColour);
  }
  return out;
}

std::string CaptureFrameJson(const CaptureFrame& frame) {
  nlohmann::ordered_json line;
  line["frame"] = frame.index;
  line["image"] = frame.image;
  line["floor_fraction"] = Round(frame.floor_fraction, 4);
  line["reference_fraction"] = Round(frame.reference_fraction, 4);
  if (frame.counts) {
    line["hit"] = frame.counts->hit;
    line["clear"] = frame.counts->clear;
    line["blind"] = frame.counts->blind;
    line["nearest_hit_m"] = frame.counts->nearest_hit_m
                                ? nlohmann::ordered_json(Round(*frame.counts->nearest_hit_m, 4))
                                : nlohmann::ordered_json(nullptr);
  }
  line["seconds"] = Round(frame.seconds, 5);
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
  for (const CaptureFrame& f : result.frames) {
    floor += f.floor_fraction;
    reference += f.reference_fraction;
    seconds += f.seconds;
    if (f.counts) {
      hit += f.counts->hit;
      clear += f.counts->clear;
      blind += f.counts->blind;
    }
  }
  summary["mean_floor_fraction"] = Round(floor / n, 4);
  summary["mean_reference_fraction"] = Round(reference / n, 4);
  if (result.max_range_m) {
    summary["max_range_m"] = Round(*result.max_range_m, 4);
    summary["mean_hit"] = Round(hit / n, 1);
    summary["mean_clear"] = Round(clear / n, 1);
    summary["mean_blind"] = Round(blind / n, 1);
  }
  summary["seconds_per_frame"] = Round(seconds / n, 5);
  summary["wall_time_s"] = Round(result.wall_time_s, 3);
  summary["out"] = request.out_dir;
  return summary.dump(2) + "\n";
}

}  // namespace pirouette::app
