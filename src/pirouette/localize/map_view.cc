#include "pirouette/localize/map_view.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "pirouette/mapping/radial_profile.h"

namespace pirouette::localize {
namespace {

constexpr int kBins = mapping::kRadialProfileBins;
constexpr double kBinRad = 2.0 * std::numbers::pi / kBins;

// Whether `c` lies in a gap between obstacle cells: walking round its 8
// neighbours, the occupied ones form two or more separate runs (a hole in a
// wall, or the corner two diagonal cells of an outline leave open). A cell
// beside one obstacle's edge only (the unseen floor in its shadow) has one
// run. Returns one of the occupied neighbours when it does.
std::optional<core::CellIndex> GapBetweenObstacleCells(const mapping::TrinaryMap& map,
                                                       const core::CellIndex& c) {
  static constexpr int kRing[8][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                      {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  bool occupied[8];
  std::optional<core::CellIndex> any;
  for (int i = 0; i < 8; ++i) {
    const core::CellIndex n{c.x + kRing[i][0], c.y + kRing[i][1]};
    occupied[i] = map.geometry.Contains(n) && map.At(n) == mapping::CellState::kOccupied;
    if (occupied[i] && !any) any = n;
  }
  int runs = 0;
  for (int i = 0; i < 8; ++i) runs += occupied[i] && !occupied[(i + 7) % 8] ? 1 : 0;
  return runs >= 2 ? any : std::nullopt;
}

// FNV-1a (64 bit) over `n` bytes, continuing from `h`.
constexpr std::uint64_t kFnvOffsetBasis = 1469598103934665603ULL;
constexpr std::uint64_t kFnvPrime = 1099511628211ULL;
std::uint64_t Fnv(std::uint64_t h, const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= kFnvPrime;
  }
  return h;
}

}  // namespace

MapView CastMapView(const mapping::TrinaryMap& map, const Eigen::Vector2d& origin_m,
                    double max_range_m, const ColourMap& colours) {
  const core::GridGeometry& g = map.geometry;
  const double step = kMapRayStepCells * g.resolution();
  MapView v;
  v.ranges_m.assign(kBins, max_range_m);
  v.kinds.assign(kBins, MapRayKind::kClear);
  if (!colours.empty()) v.colours.assign(kBins, core::ColourClass::kNone);
  for (int b = 0; b < kBins; ++b) {
    const double a = (b + 0.5) * kBinRad;
    const Eigen::Vector2d dir(std::cos(a), std::sin(a));
    for (double t = step; t <= max_range_m; t += step) {
      core::CellIndex c = g.CellOf(origin_m + t * dir);
      mapping::CellState s = g.Contains(c) ? map.At(c) : mapping::CellState::kUnknown;
      if (s == mapping::CellState::kFree) continue;
      // An unknown cell in a gap between obstacle cells is a hole in an
      // obstacle's mapped outline (its inside is unseen): the ray has met
      // that obstacle.
      if (s == mapping::CellState::kUnknown) {
        if (const std::optional<core::CellIndex> o = GapBetweenObstacleCells(map, c)) {
          c = *o;
          s = mapping::CellState::kOccupied;
        }
      }
      v.ranges_m[static_cast<std::size_t>(b)] = t;
      v.kinds[static_cast<std::size_t>(b)] =
          s == mapping::CellState::kOccupied ? MapRayKind::kHit : MapRayKind::kUnknown;
      if (s == mapping::CellState::kOccupied && !colours.empty()) {
        v.colours[static_cast<std::size_t>(b)] = colours.At(c);
      }
      break;
    }
  }
  return v;
}

std::string MapTableName(const mapping::TrinaryMap& map, const ColourMap& colours,
                         double robot_radius_m, double spacing_m, double max_range_m) {
  std::uint64_t h = kFnvOffsetBasis;
  const double geo[3] = {map.geometry.resolution(), map.geometry.origin().x(),
                         map.geometry.origin().y()};
  const int size[2] = {map.geometry.width(), map.geometry.height()};
  h = Fnv(h, geo, sizeof(geo));
  h = Fnv(h, size, sizeof(size));
  h = Fnv(h, map.cells.data(), map.cells.size() * sizeof(mapping::CellState));
  if (!colours.empty()) {
    h = Fnv(h, colours.cells().data(), colours.cells().size() * sizeof(core::ColourClass));
  }
  return fmt::format("map {:016x} radius {:.4f} spacing {:.4f} range {:.4f} rays {}", h,
                     robot_radius_m, spacing_m, max_range_m, kMapRayVersion);
}

PlaceTable BuildMapPlaceTable(const mapping::TrinaryMap& map, const ColourMap& colours,
                              double robot_radius_m, double spacing_m, double max_range_m) {
  const core::GridGeometry& g = map.geometry;
  const Eigen::Vector2d lo = g.origin();
  const Eigen::Vector2d hi =
      lo + Eigen::Vector2d(g.width() * g.resolution(), g.height() * g.resolution());
  std::vector<PlaceEntry> entries;
  for (double y = lo.y() + 0.5 * spacing_m; y < hi.y(); y += spacing_m) {
    for (double x = lo.x() + 0.5 * spacing_m; x < hi.x(); x += spacing_m) {
      if (!mapping::DiscKnownFree(map, {x, y}, robot_radius_m)) continue;
      const MapView v = CastMapView(map, {x, y}, max_range_m, colours);
      PlaceEntry e{x, y, 0.0, {v.ranges_m, v.colours}, {}};
      for (const MapRayKind k : v.kinds) {
        e.kinds.push_back(k == MapRayKind::kHit     ? core::ReadingKind::kHit
                          : k == MapRayKind::kClear ? core::ReadingKind::kClear
                                                    : core::ReadingKind::kBlind);
      }
      entries.push_back(std::move(e));
    }
  }
  return {MapTableName(map, colours, robot_radius_m, spacing_m, max_range_m), max_range_m,
          std::move(entries)};
}

}  // namespace pirouette::localize
