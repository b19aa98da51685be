#include "pirouette/eval/map_evaluation.h"

#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "pirouette/draw/map_picture.h"
#include "pirouette/draw/palette.h"
#include "pirouette/eval/reachability.h"

namespace pirouette::eval {
namespace {

using mapping::CellState;

// Distances between cell centres are square roots of whole numbers; the
// slack keeps exactly kFalseOccupiedCells from counting as farther.
constexpr double kDistanceSlackCells = 1e-3;

// The map's cells counted and judged against the truth; each cell's verdict
// goes in `verdicts` where it is given.
MapEvaluation Judge(const mapping::TrinaryMap& map, const Reachability& truth,
                    const cv::Mat1f& distance_cells, std::vector<CellVerdict>* verdicts) {
  const core::GridGeometry& g = map.geometry;
  const TruthWindow& window = truth.window;
  MapEvaluation e;
  e.reachable = truth.ReachableCount();
  std::size_t covered = 0;
  std::size_t false_free = 0;
  std::size_t false_occupied = 0;
  double distance_sum_cells = 0.0;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const bool inside = window.Contains(x, y);
      const int a = static_cast<int>(x - window.x0);
      const int b = static_cast<int>(y - window.y0);
      const bool reachable = inside && truth.reachable[window.Flat(x, y)] != 0;
      CellVerdict verdict = CellVerdict::kUnknown;
      switch (map.At({x, y})) {
        case CellState::kFree:
          ++e.free;
          verdict = CellVerdict::kFree;
          if (!inside || truth.free[window.Flat(x, y)] == 0) {
            ++false_free;
            verdict = CellVerdict::kFalseFree;
          }
          if (reachable) ++covered;
          break;
        case CellState::kOccupied: {
          ++e.occupied;
          const double d = inside ? static_cast<double>(distance_cells(b, a)) : 0.0;
          distance_sum_cells += d;
          verdict = CellVerdict::kOccupied;
          if (d > kFalseOccupiedCells + kDistanceSlackCells) {
            ++false_occupied;
            verdict = CellVerdict::kFalseOccupied;
          }
          break;
        }
        case CellState::kUnknown:
          ++e.unknown;
          if (reachable) verdict = CellVerdict::kMissedFloor;
          break;
      }
      if (verdicts != nullptr) (*verdicts)[g.Flat({x, y})] = verdict;
    }
  }
  const auto fraction = [](std::size_t part, std::size_t whole) {
    return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
  };
  e.coverage = fraction(covered, e.reachable);
  e.false_free = fraction(false_free, e.free);
  e.false_occupied = fraction(false_occupied, e.occupied);
  e.wall_error_m =
      e.occupied == 0 ? 0.0 : distance_sum_cells * g.resolution() / static_cast<double>(e.occupied);
  return e;
}

// EvaluateMap, and each cell's verdict where `verdicts` is given.
MapEvaluation Evaluate(const mapping::TrinaryMap& map, const sim::World& world,
                       std::vector<CellVerdict>* verdicts) {
  const core::GridGeometry& g = map.geometry;
  if (map.cells.size() != g.CellCount()) {
    throw std::invalid_argument("EvaluateMap: the map's cells do not match its geometry");
  }
  if (verdicts != nullptr) verdicts->assign(g.CellCount(), CellVerdict::kUnknown);
  const Reachability truth = ReachableCells(world, g);
  // The truth's own bytes, read only.
  const cv::Mat1b truth_free(truth.window.height, truth.window.width,
                             const_cast<std::uint8_t*>(truth.free.data()));
  cv::Mat1f distance_cells;
  cv::distanceTransform(truth_free, distance_cells, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  return Judge(map, truth, distance_cells, verdicts);
}

}  // namespace

MapEvaluation EvaluateMap(const mapping::TrinaryMap& map, const sim::World& world) {
  return Evaluate(map, world, nullptr);
}

JudgedMap JudgeMap(const mapping::TrinaryMap& map, const sim::World& world) {
  JudgedMap judged;
  judged.evaluation = Evaluate(map, world, &judged.verdicts);
  return judged;
}

cv::Mat3b DrawJudgedMap(const mapping::TrinaryMap& map, const JudgedMap& judged,
                        int target_width_px) {
  if (judged.verdicts.size() != map.geometry.CellCount()) {
    throw std::invalid_argument("DrawJudgedMap: the verdicts do not match the map's geometry");
  }
  return draw::DrawMarkedMap(
      map,
      [&](const core::CellIndex& c) -> const cv::Vec3b* {
        switch (judged.verdicts[map.geometry.Flat(c)]) {
          case CellVerdict::kFalseFree:
            return &draw::kFalseFreeColour;
          case CellVerdict::kFalseOccupied:
            return &draw::kFalseOccupiedColour;
          case CellVerdict::kMissedFloor:
            return &draw::kMissedFloorColour;
          default:
            return nullptr;
        }
      },
      target_width_px);
}

nlohmann::json MapEvaluationToJson(const MapEvaluation& evaluation) {
  return {
      {"coverage", evaluation.coverage},
      {"false_free", evaluation.false_free},
      {"false_occupied", evaluation.false_occupied},
      {"wall_error_m", evaluation.wall_error_m},
      {"cells",
       {{"free", evaluation.free},
        {"occupied", evaluation.occupied},
        {"unknown", evaluation.unknown}}},
      {"reachable_cells", evaluation.reachable},
  };
}

std::string MapEvaluationJson(const MapEvaluation& evaluation) {
  return MapEvaluationToJson(evaluation).dump(2) + "\n";
}

}  // namespace pirouette::eval
