// The whole per-frame perception pipeline as the robot runs it, against the
// straightforward OpenCV chain, on the same rendered frames, one thread.
//
//   build/release/bench/pirouette_bench --benchmark_filter='perceive/'
//
// perceive/pirouette/WxH: the default segmenter (on a working grid of cells
//   at most 160 wide: the frame reduced and corrected for vignetting in one
//   pass, floor appearance + edges, the boundary refined to the pixel) and
//   the profile through the inverse perspective map, both lookup tables
//   built once: vision::ProfileExtractor, which keeps per column where the
//   floor points end or leave the range (the same readings as
//   vision::ExtractProfile; profile/ below compares the two).
// perceive/pirouette-paper/WxH: the same with the paper's segmenter.
// perceive/opencv/WxH: cv::undistort of the whole image, cvtColor,
//   GaussianBlur, Canny, floodFill from the bottom centre, then in each column
//   the first non-floor pixel up from the bottom, mapped to the floor through
//   CameraModel::FloorPoint (per boundary pixel, no lookup table).
//
// The frames are one pirouette (12 views, 30° apart) rendered once in the
// soccer field; both sides start from the same BGR frames. The segmenters
// learn the floor online, so they see the pirouette once before timing, as
// the robot's first pirouette. The `hits` counter (columns read as hits, a
// frame) checks that both sides find the floor's edge. Names follow `<stage>/<who>/<size>`.
//
// profile/extract-profile/WxH and profile/profile-extractor/WxH: the profile
// stage alone on the default segmenter's masks of the same frames, by the
// free function (which walks every floor pixel's floor point) and by the
// extractor built once.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

#include "bench_worlds.h"
#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/io/image_io.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/vision/floor_segmenter.h"
#include "pirouette/vision/profile_extractor.h"

namespace {

using pirouette::camera::CameraModel;
using pirouette::core::Pose2;

constexpr int kViews = 12;

// One pirouette's raw BGR frames from the soccer field's camera scaled to
// width × height, rendered once per size.
const std::vector<cv::Mat3b>& Frames(int width, int height) {
  static std::map<std::pair<int, int>, std::vector<cv::Mat3b>> cache;
  auto [it, inserted] = cache.try_emplace({width, height});
  if (inserted) {
    const auto& world = pirouette::bench::SoccerField();
    pirouette::sim::Renderer renderer(
        world, pirouette::bench::Scaled(world.robot().camera, width, height), {});
    for (int i = 0; i < kViews; ++i) {
      const Pose2 pose(0.75, 0.65, pirouette::core::DegToRad(30.0 * i));
      it->second.emplace_back(pirouette::io::ToBgrMat(renderer.Render(pose)));
    }
  }
  return it->second;
}

// The columns read as hits: a check that both sides do comparable work.
long CountHits(const pirouette::core::ObstacleProfile& profile) {
  return std::count_if(profile.readings.begin(), profile.readings.end(),
                       [](const auto& r) { return r.kind == pirouette::core::ReadingKind::kHit; });
}

void PerceivePirouette(benchmark::State& state, pirouette::vision::SegmentationMethod method,
                       int width, int height) {
  cv::setNumThreads(1);
  const auto& frames = Frames(width, height);
  const CameraModel camera =
      pirouette::bench::Scaled(pirouette::bench::SoccerField().robot().camera, width, height);
  const pirouette::camera::InversePerspectiveMap ipm(camera);
  const double max_range_m = pirouette::camera::MaxRange(camera);
  const pirouette::vision::ProfileExtractor extractor(ipm, max_range_m);
  const auto segmenter = pirouette::vision::MakeFloorSegmenter(method, camera);
  for (const cv::Mat3b& frame : frames) benchmark::DoNotOptimize(segmenter->Segment(frame));
  std::size_t i = 0;
  long hits = 0;
  for (auto _ : state) {
    const cv::Mat1b mask = segmenter->Segment(frames[i++ % frames.size()]);
    const auto profile = extractor.Extract(mask);
    hits += CountHits(profile);
    benchmark::DoNotOptimize(profile);
  }
  state.counters["hits"] =
      benchmark::Counter(static_cast<double>(hits), benchmark::Counter::kAvgIterations);
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The straightforward chain. Its profile is (bearing, range) per column that
// finds a floor edge below the horizon, hits and clears by max_range_m.
void PerceiveOpenCv(benchmark::State& state, int width, int height) {
  cv::setNumThreads(1);
  const auto& frames = Frames(width, height);
  const CameraModel camera =
      pirouette::bench::Scaled(pirouette::bench::SoccerField().robot().camera, width, height);
  const double max_range_m = pirouette::camera::MaxRange(camera);
  const auto& k = camera.intrinsics();
  const auto& d = camera.distortion();
  const cv::Matx33d camera_matrix(k.fx, 0.0, k.cx, 0.0, k.fy, k.cy, 0.0, 0.0, 1.0);
  const cv::Matx<double, 1, 5> dist_coeffs(d.k1, d.k2, d.p1, d.p2, d.k3);
  constexpr std::uint8_t kFloor = 128;
  std::size_t i = 0;
  long hits = 0;
  for (auto _ : state) {
    const cv::Mat3b& raw = frames[i++ % frames.size()];
    cv::Mat undistorted, grey, blurred, edges;
    cv::undistort(raw, undistorted, camera_matrix, dist_coeffs);
    cv::cvtColor(undistorted, grey, cv::COLOR_BGR2GRAY);
    cv::GaussianBlur(grey, blurred, cv::Size(5, 5), 1.0);
    cv::Canny(blurred, edges, 50.0, 150.0);
    cv::floodFill(edges, cv::Point(width / 2, height - 1), cv::Scalar(kFloor));
    pirouette::core::ObstacleProfile profile;
    profile.readings.reserve(static_cast<std::size_t>(width));
    for (int u = 0; u < width; ++u) {
      int v = height - 1;
      if (edges.at<std::uint8_t>(v, u) != kFloor) continue;
      while (v > 0 && edges.at<std::uint8_t>(v - 1, u) == kFloor) --v;
      // The first non-floor pixel above, in the undistorted image, back to
      // the raw image for the camera model.
      const Eigen::Vector2d normalised((u - k.cx) / k.fx, (v - 1 - k.cy) / k.fy);
      const Eigen::Vector2d distorted = camera.Distort(normalised);
      const auto p_robot = camera.FloorPoint(
          Eigen::Vector2d(k.fx * distorted.x() + k.cx, k.fy * distorted.y() + k.cy));
      if (!p_robot) continue;
      const double range_m = p_robot->norm();
      pirouette::core::RangeReading reading;
      reading.bearing_rad = std::atan2(p_robot->y(), p_robot->x());
      reading.range_m = std::min(range_m, max_range_m);
      reading.kind = range_m <= max_range_m ? pirouette::core::ReadingKind::kHit
                                            : pirouette::core::ReadingKind::kClear;
      profile.readings.push_back(reading);
    }
    hits += CountHits(profile);
    benchmark::DoNotOptimize(profile);
  }
  state.counters["hits"] =
      benchmark::Counter(static_cast<double>(hits), benchmark::Counter::kAvgIterations);
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The profile stage alone: ExtractProfile per frame, or a ProfileExtractor.
void ExtractProfiles(benchmark::State& state, bool extractor_built_once, int width, int height) {
  cv::setNumThreads(1);
  const auto& frames = Frames(width, height);
  const CameraModel camera =
      pirouette::bench::Scaled(pirouette::bench::SoccerField().robot().camera, width, height);
  const pirouette::camera::InversePerspectiveMap ipm(camera);
  const double max_range_m = pirouette::camera::MaxRange(camera);
  const pirouette::vision::ProfileExtractor extractor(ipm, max_range_m);
  const auto segmenter = pirouette::vision::MakeFloorSegmenter(
      pirouette::vision::SegmentationMethod::kDefault, camera);
  std::vector<cv::Mat1b> masks;
  masks.reserve(frames.size());
  for (const cv::Mat3b& frame : frames) masks.push_back(segmenter->Segment(frame));
  std::size_t i = 0;
  long hits = 0;
  for (auto _ : state) {
    const cv::Mat1b& mask = masks[i++ % masks.size()];
    const auto profile = extractor_built_once
                             ? extractor.Extract(mask)
                             : pirouette::vision::ExtractProfile(mask, ipm, max_range_m);
    hits += CountHits(profile);
    benchmark::DoNotOptimize(profile);
  }
  state.counters["hits"] =
      benchmark::Counter(static_cast<double>(hits), benchmark::Counter::kAvgIterations);
}

using pirouette::vision::SegmentationMethod;

BENCHMARK_CAPTURE(PerceivePirouette, default_320x240, SegmentationMethod::kDefault, 320, 240)
    ->Name("perceive/pirouette/320x240")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(PerceivePirouette, paper_320x240, SegmentationMethod::kPaper, 320, 240)
    ->Name("perceive/pirouette-paper/320x240")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(PerceiveOpenCv, 320x240, 320, 240)
    ->Name("perceive/opencv/320x240")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(PerceivePirouette, default_640x480, SegmentationMethod::kDefault, 640, 480)
    ->Name("perceive/pirouette/640x480")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(PerceivePirouette, paper_640x480, SegmentationMethod::kPaper, 640, 480)
    ->Name("perceive/pirouette-paper/640x480")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(PerceiveOpenCv, 640x480, 640, 480)
    ->Name("perceive/opencv/640x480")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(ExtractProfiles, free_320x240, false, 320, 240)
    ->Name("profile/extract-profile/320x240")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(ExtractProfiles, extractor_320x240, true, 320, 240)
    ->Name("profile/profile-extractor/320x240")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(ExtractProfiles, free_640x480, false, 640, 480)
    ->Name("profile/extract-profile/640x480")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(ExtractProfiles, extractor_640x480, true, 640, 480)
    ->Name("profile/profile-extractor/640x480")
    ->Unit(benchmark::kMicrosecond);

}  // namespace
