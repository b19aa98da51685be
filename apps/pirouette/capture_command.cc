#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <opencv2/core/utils/logger.hpp>
#include <string>

#include "apps/pirouette/command.h"
#include "apps/pirouette/interrupt.h"
#include "apps/pirouette/options.h"
#include "pirouette/run/progress_line.h"
#include "pirouette/tools/capture.h"

namespace pirouette::cli {
namespace {

std::string ProgressText(const tools::LiveCaptureProgress& p) {
  std::string line =
      fmt::format("capture: {} frame{} (source frame {}), floor {:.0f}%, {:.0f} ms to segment",
                  p.frames, p.frames == 1 ? "" : "s", p.last->index, 100.0 * p.last->floor_fraction,
                  1000.0 * p.last->seconds);
  if (p.last->counts) {
    line += fmt::format(", hit {} clear {} blind {}", p.last->counts->hit, p.last->counts->clear,
                        p.last->counts->blind);
  }
  return line;
}

}  // namespace

Command AddCaptureCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::LiveCaptureRequest>();
  auto method = std::make_shared<std::string>("default");
  auto frames = std::make_shared<int>(0);
  auto quiet = std::make_shared<bool>(false);
  CLI::App* cmd = parent.add_subcommand(
      "capture",
      "Check a real camera and floor before a run: read frames from a camera device, a video "
      "file or a stream, find the floor in each (the floor model learns from the frames in "
      "order, as on the robot), and write OUT/NNNNNN.png (NNNNNN: the frame's number in the "
      "source) with the floor drawn over the frame and, with --camera, the obstacle profile "
      "(a mark a column where its reading lies: hit magenta, clear azure, blind amber; a "
      "magenta ring at the foot of an obstacle's side a column met above its base; and the ranges "
      "as bars below). OUT/profiles.jsonl holds a line a frame; a summary is printed "
      "as JSON on standard output. Ctrl-C stops and keeps what was written.\n"
      "Exit: 0 done (or stopped by Ctrl-C), 1 an output could not be written, 2 bad input (a "
      "missing file, a source that cannot be opened, frames not of the camera's size).\n"
      "  example: pirouette capture --source 0 --camera my_webcam.yaml --frames 50 --every 5\n"
      "  example: pirouette capture --source robot.avi --out capture");
  cmd->add_option("--source", request->source,
                  "a camera device number (0, 1, ...), a video file, or a stream URL "
                  "(rtsp://..., http://...)")
      ->required();
  AddCameraOption(cmd, request->camera_path,
                  "its size must be the frames'; without it: no correction and no profile");
  AddMethodOption(cmd, *method, kSegmentationMethods);
  AddOutFolderOption(cmd, request->out_dir);
  CLI::Option* frames_option =
      cmd->add_option("--frames", *frames,
                      "stop after this many frames used; 0: no limit (default: all of a file, " +
                          std::to_string(tools::kLiveDefaultFrames) + " of a device or stream)");
  cmd->add_option("--every", request->every,
                  "use every k-th frame of the source; the others are skipped unseen")
      ->capture_default_str();
  AddMaxRangeOption(cmd, request->max_range_m, "the camera's, by the paper's rule for 1 cm cells");
  AddQuietOption(cmd, *quiet);
  return {cmd, [request, method, frames, frames_option, quiet] {
            request->method = *vision::ParseSegmentationMethod(*method);
            if (frames_option->count() > 0) request->max_frames = *frames;
            // OpenCV's backends log every one they try and fail on a source that
            // does not open; the message below says what failed. Set
            // OPENCV_LOG_LEVEL (e.g. INFO) to see them.
            if (std::getenv("OPENCV_LOG_LEVEL") == nullptr) {
              cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
            }
            request->stop_requested = StopOnInterrupt();
            tools::LiveCaptureResult result;
            {
              run::ProgressLine progress(*quiet);
              const auto start = std::chrono::steady_clock::now();
              result = tools::RunLiveCapture(*request, [&](const tools::LiveCaptureProgress& p) {
                if (p.last == nullptr) return;
                const double elapsed =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                progress.Show(elapsed, [&] { return ProgressText(p); });
              });
            }
            std::fputs(tools::LiveCaptureSummaryJson(*request, result).c_str(), stdout);
            if (!*quiet) {
              std::fprintf(
                  stderr, "capture: %zu frames (%s) in %s/, summary in %s/profiles.jsonl\n",
                  result.frames.size(), std::string(tools::CaptureStopName(result.stop)).c_str(),
                  request->out_dir.c_str(), request->out_dir.c_str());
            }
          }};
}

}  // namespace pirouette::cli
