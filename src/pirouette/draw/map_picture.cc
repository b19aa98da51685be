#include "pirouette/draw/map_picture.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "pirouette/draw/palette.h"

namespace pirouette::draw {
namespace {

constexpr int kShift = MapCanvas::kShift;

const cv::Scalar kPath = Scalar(kPathColour);
const cv::Scalar kStop = Scalar(kStopColour);
const cv::Scalar kStart = Scalar(kStartColour);
const cv::Scalar kRobot = Scalar(kRobotColour);

}  // namespace

MapCanvas MapCanvas::Of(const core::GridGeometry& geometry,
                        const std::function<std::uint8_t(const core::CellIndex&)>& grey,
                        int target_width_px) {
  MapCanvas canvas{{}, geometry, std::max(1, target_width_px / std::max(1, geometry.width()))};
  cv::Mat3b cells(geometry.height(), geometry.width());
  for (int y = 0; y < geometry.height(); ++y) {
    for (int x = 0; x < geometry.width(); ++x) {
      const std::uint8_t v = grey({x, y});
      cells(geometry.height() - 1 - y, x) = cv::Vec3b(v, v, v);
    }
  }
  cv::resize(cells, canvas.image, {}, canvas.scale, canvas.scale, cv::INTER_NEAREST);
  return canvas;
}

MapCanvas MapCanvas::OfTrinary(const mapping::TrinaryMap& map, int target_width_px) {
  return Of(
      map.geometry,
      [&map](const core::CellIndex& c) -> std::uint8_t {
        switch (map.At(c)) {
          case mapping::CellState::kFree:
            return 255;
          case mapping::CellState::kOccupied:
            return 0;
          case mapping::CellState::kUnknown:
            break;
        }
        return kUnknownGrey;
      },
      target_width_px);
}

cv::Mat3b DrawMarkedMap(const mapping::TrinaryMap& map,
                        const std::function<const cv::Vec3b*(const core::CellIndex&)>& mark,
                        int target_width_px) {
  const MapCanvas canvas = MapCanvas::OfTrinary(map, target_width_px);
  const core::GridGeometry& g = map.geometry;
  cv::Mat3b image = canvas.image;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const cv::Vec3b* colour = mark({x, y});
      if (colour == nullptr) continue;
      const int row = (g.height() - 1 - y) * canvas.scale;
      image(cv::Rect(x * canvas.scale, row, canvas.scale, canvas.scale)).setTo(*colour);
    }
  }
  return image;
}

cv::Point MapCanvas::Pixel(const Eigen::Vector2d& p_m) const {
  const double u = (p_m.x() - geometry.origin().x()) / geometry.resolution() * scale;
  const double v =
      (geometry.height() - (p_m.y() - geometry.origin().y()) / geometry.resolution()) * scale;
  return {static_cast<int>(std::lround(u * (1 << kShift))),
          static_cast<int>(std::lround(v * (1 << kShift)))};
}

int MapCanvas::Fixed(double pixels) {
  return static_cast<int>(std::lround(pixels * (1 << kShift)));
}

cv::Mat3b DrawMapPicture(const mapping::OccupancyGrid& grid, const std::vector<core::Pose2>& path,
                         const std::vector<core::Pose2>& stops, int target_width_px,
                         const localize::PoseGraph* graph) {
  const core::GridGeometry& g = grid.geometry();
  MapCanvas canvas = MapCanvas::Of(
      g,
      [&](const core::CellIndex& c) {
        // Free seen from one place only is unknown in the map of record.
        const bool unknown = !grid.Known(c) || (grid.State(c) == mapping::CellState::kFree &&
                                                !grid.FreeFromTwoPlaces(c));
        return unknown
                   ? kUnknownGrey
                   : static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - grid.Probability(c))));
      },
      target_width_px);
  cv::Mat3b& image = canvas.image;
  const int scale = canvas.scale;
  const auto pixel = [&](const Eigen::Vector2d& p) { return canvas.Pixel(p); };
  const int thickness = std::max(1, scale / 2);
  // The graph's edges of one kind, `width` pixels wide.
  const auto draw_edges = [&](localize::EdgeKind kind, const cv::Vec3b& colour, int width) {
    if (graph == nullptr) return;
    const std::vector<core::Pose2>& nodes = graph->poses();
    for (const localize::PoseGraphEdge& edge : graph->edges()) {
      if (edge.kind != kind) continue;
      cv::line(image, pixel(nodes[edge.from].translation()), pixel(nodes[edge.to].translation()),
               Scalar(colour), width, cv::LINE_AA, kShift);
    }
  };
  draw_edges(localize::EdgeKind::kOdometry, kOdometryEdgeColour, thickness);
  draw_edges(localize::EdgeKind::kScanMatch, kMatchEdgeColour, thickness);
  for (std::size_t i = 1; i < path.size(); ++i) {
    cv::line(image, pixel(path[i - 1].translation()), pixel(path[i].translation()), kPath,
             thickness, cv::LINE_AA, kShift);
  }
  draw_edges(localize::EdgeKind::kLoopClosure, kLoopClosureColour, thickness + 1);
  const int dot = std::max(3, 2 * scale);
  for (const core::Pose2& stop : stops) {
    cv::circle(image, pixel(stop.translation()), MapCanvas::Fixed(dot), kStop, cv::FILLED,
               cv::LINE_AA, kShift);
  }
  if (!path.empty()) {
    cv::circle(image, pixel(path.front().translation()), MapCanvas::Fixed(dot + 2), kStart, 2,
               cv::LINE_AA, kShift);
    const core::Pose2& last = path.back();
    const double arrow_m = 3.0 * dot * g.resolution() / scale;
    cv::circle(image, pixel(last.translation()), MapCanvas::Fixed(dot + 1), kRobot, cv::FILLED,
               cv::LINE_AA, kShift);
    cv::line(image, pixel(last.translation()),
             pixel(last.translation() + arrow_m * last.Direction()), kRobot, thickness + 1,
             cv::LINE_AA, kShift);
  }
  return image;
}

}  // namespace pirouette::draw
