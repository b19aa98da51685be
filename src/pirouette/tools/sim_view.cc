#include "pirouette/tools/sim_view.h"

#include <algorithm>
#include <cmath>

#include "pirouette/io/image_io.h"
#include "pirouette/run/run_messages.h"

namespace pirouette::tools {

namespace {

// The truth map reaches this many cells past the floor and its walls.
constexpr int kMarginCells = 2;
constexpr double kMinCellM = 0.01;
constexpr double kMaxCellM = 0.05;

}  // namespace

mapping::TrinaryMap TruthMap(const sim::World& world, double cell_m) {
  const Eigen::Vector2d size = world.floor().size;
  const double wall = world.walls() ? world.walls()->thickness : cell_m;
  const double margin = wall + kMarginCells * cell_m;
  const Eigen::Vector2d origin(-margin, -margin);
  const int width = static_cast<int>(std::ceil((size.x() + 2 * margin) / cell_m));
  const int height = static_cast<int>(std::ceil((size.y() + 2 * margin) / cell_m));
  mapping::TrinaryMap map{core::GridGeometry(cell_m, origin, width, height), {}};
  map.cells.resize(map.geometry.CellCount(), mapping::CellState::kUnknown);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Eigen::Vector2d p = map.geometry.CellCentre({x, y});
      const bool near_floor =
          p.x() > -wall && p.y() > -wall && p.x() < size.x() + wall && p.y() < size.y() + wall;
      mapping::CellState& cell = map.cells[map.geometry.Flat({x, y})];
      if (world.OnFloor(p) && !world.IsOccupied(p)) {
        cell = mapping::CellState::kFree;
      } else if (near_floor) {
        cell = mapping::CellState::kOccupied;
      }
    }
  }
  return map;
}

double SimView::TruthCellM(const sim::World& world) {
  return std::clamp(world.robot().radius / 2.0, kMinCellM, kMaxCellM);
}

SimView::SimView(const sim::World& world, const run::LiveViewOptions& options)
    : publisher_(options) {
  publisher_.PublishMap(TruthMap(world, TruthCellM(world)));
  path_.push_back(world.robot().start);
  publisher_.PublishPath(path_);
  publisher_.PublishStatus(run::StatusJson("serving", 0, 0.0, "waiting for a client"));
}

void SimView::OnFrame(const core::ImageRgb8& image, const core::Pose2& world_T_robot) {
  ++frames_;
  const core::Pose2& last = path_.back();
  if (last.x() != world_T_robot.x() || last.y() != world_T_robot.y() ||
      last.heading() != world_T_robot.heading()) {
    path_.push_back(world_T_robot);
    publisher_.PublishPath(path_);
  }
  publisher_.PublishPicture(cv::Mat3b(io::ToBgrMat(image)));
  publisher_.PublishStatus(run::StatusJson("serving", frames_, 0.0, "frames served"));
}

}  // namespace pirouette::tools
