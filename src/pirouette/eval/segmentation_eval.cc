#include "pirouette/eval/segmentation_eval.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/draw/floor_overlay.h"
#include "pirouette/io/image_io.h"
#include "pirouette/io/world_file.h"
#include "pirouette/sim/ray_caster.h"
#include "pirouette/sim/renderer.h"

namespace pirouette::eval {

ImageScore ScoreMask(const cv::Mat1b& truth, const cv::Mat1b& floor_mask) {
  CV_Assert(truth.size() == floor_mask.size());
  double both = 0.0;
  double either = 0.0;
  double found = 0.0;
  double real = 0.0;
  for (int v = 0; v < truth.rows; ++v) {
    for (int u = 0; u < truth.cols; ++u) {
      const bool t = truth(v, u) != 0;
      const bool f = floor_mask(v, u) != 0;
      both += (t && f) ? 1.0 : 0.0;
      either += (t || f) ? 1.0 : 0.0;
      found += f ? 1.0 : 0.0;
      real += t ? 1.0 : 0.0;
    }
  }
  ImageScore score;
  score.iou = either > 0.0 ? both / either : 1.0;
  score.precision = found > 0.0 ? both / found : 1.0;
  score.recall = real > 0.0 ? both / real : 1.0;
  return score;
}

SegmentationEvalResult EvaluateSegmentation(const SegmentationEvalRequest& request) {
  if (request.first < 0 || request.last < request.first) {
    throw core::InputError("", 0, "first/last", "need 0 <= first <= last");
  }
  SegmentationEvalResult result;
  double sum = 0.0;
  for (int i = request.first; i <= request.last; ++i) {
    const std::filesystem::path dir(request.images_dir);
    const std::string photo_path = (dir / fmt::format("source_{}.bmp", i)).string();
    const std::string truth_path = (dir / fmt::format("gt_source_{}.bmp", i)).string();
    const cv::Mat3b bgr = io::ToBgrMat(io::ReadImage(photo_path));
    if (!std::filesystem::exists(truth_path)) {
      throw core::InputError(truth_path, 0, "", "no such file");
    }
    const cv::Mat grey = cv::imread(truth_path, cv::IMREAD_GRAYSCALE);
    if (grey.empty()) throw core::InputError(truth_path, 0, "", "not an image OpenCV can read");
    if (grey.size() != bgr.size()) {
      throw core::InputError(truth_path, 0, "", "the mask's size is not the photo's");
    }
    const cv::Mat1b truth = grey >= 128;
    auto segmenter = vision::MakeFloorSegmenter(request.method, std::nullopt);
    ImageScore score = ScoreMask(truth, segmenter->Segment(bgr));
    score.index = i;
    sum += score.iou;
    result.images.push_back(score);
  }
  result.mean_iou = sum / static_cast<double>(result.images.size());
  return result;
}

namespace {

// The row of the first pixel that is not floor, walking up column u from the bottom; -1 if none.
int BoundaryRow(const cv::Mat1b& mask, int u) {
  for (int v = mask.rows - 1; v >= 0; --v) {
    if (mask(v, u) == 0) return v;
  }
  return -1;
}

}  // namespace

SegmentationEvalResult EvaluateSimulatedSegmentation(const SimulatedEvalRequest& request) {
  if (request.stops < 0) throw core::InputError("", 0, "stops", "must be 0 or more");
  const sim::World world = io::LoadWorldFile(request.world_path);
  const camera::CameraModel& camera = world.robot().camera;
  sim::RenderOptions options;
  options.seed = request.seed;
  sim::Renderer renderer(world, camera, options);
  const sim::RayCaster caster(world, camera);
  auto segmenter = vision::MakeFloorSegmenter(request.method, camera);

  std::vector<Eigen::Vector2d> stops = {world.robot().start.translation()};
  double start_heading = world.robot().start.heading();
  cv::RNG rng(request.seed);
  const Eigen::Vector2d size = world.floor().size;
  for (int attempt = 0; attempt < 10000 && static_cast<int>(stops.size()) <= request.stops;
       ++attempt) {
    const Eigen::Vector2d p(rng.uniform(0.0, size.x()), rng.uniform(0.0, size.y()));
    if (world.DiscFits(p, world.robot().radius)) stops.push_back(p);
  }

  SegmentationEvalResult result;
  double sum = 0.0;
  std::vector<int> boundary_errors;
  std::vector<int> boundary_differences;
  for (const Eigen::Vector2d& stop : stops) {
    for (int turn = 0; turn < 12; ++turn) {
      const core::Pose2 world_T_robot(stop.x(), stop.y(),
                                      start_heading + core::DegToRad(30.0 * turn));
      const cv::Mat3b bgr = io::ToBgrMat(renderer.Render(world_T_robot));
      std::vector<std::uint8_t> truth_data = caster.FloorMask(world_T_robot);
      const cv::Mat1b truth(camera.height(), camera.width(), truth_data.data());
      const cv::Mat1b floor_mask = segmenter->Segment(bgr);
      ImageScore score = ScoreMask(truth, floor_mask);
      for (int u = 0; u < truth.cols; ++u) {
        const int difference = BoundaryRow(floor_mask, u) - BoundaryRow(truth, u);
        boundary_errors.push_back(std::abs(difference));
        boundary_differences.push_back(difference);
      }
      if (!request.frames_dir.empty()) {
        const std::filesystem::path dir(request.frames_dir);
        const std::size_t n = result.images.size();
        io::WritePng((dir / fmt::format("frame_{}.png", n)).string(),
                     draw::DrawFloorOverlay(bgr, floor_mask));
        io::WritePng((dir / fmt::format("truth_{}.png", n)).string(), truth);
      }
      score.index = static_cast<int>(result.images.size());
      sum += score.iou;
      result.images.push_back(score);
    }
  }
  result.mean_iou = sum / static_cast<double>(result.images.size());
  std::sort(boundary_errors.begin(), boundary_errors.end());
  const auto at = [&](double q) {
    return static_cast<double>(boundary_errors[static_cast<std::size_t>(
        q * static_cast<double>(boundary_errors.size() - 1))]);
  };
  result.boundary_error_median_px = at(0.5);
  result.boundary_error_p95_px = at(0.95);
  std::nth_element(boundary_differences.begin(),
                   boundary_differences.begin() + boundary_differences.size() / 2,
                   boundary_differences.end());
  result.boundary_bias_median_px = boundary_differences[boundary_differences.size() / 2];
  return result;
}

}  // namespace pirouette::eval
