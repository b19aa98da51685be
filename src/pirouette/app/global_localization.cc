#include "pirouette/app/global_localization.h"

#include <fmt/format.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>

#include "pirouette/app/exploration.h"
#include "pirouette/app/place_recognition.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/colour_map_file.h"
#include "pirouette/io/map_file.h"
#include "pirouette/io/place_table_file.h"
#include "pirouette/io/world_file.h"
#include "pirouette/mapping/radial_profile.h"
#include "pirouette/run/progress_line.h"
#include "pirouette/run/stage_timer.h"
#include "pirouette/sim/simulated_pirouette.h"

namespace pirouette::app {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kBins = mapping::kRadialProfileBins;
constexpr double kBinRad = 2.0 * std::numbers::pi / kBins;

int Wrap(int b) { return ((b % kBins) + kBins) % kBins; }

// The table place's stored view, as a MapView (blind = unknown).
MapView EntryMapView(const localize::PlaceEntry& e) {
  MapView v;
  v.ranges_m = e.view.ranges_m;
  v.kinds.resize(v.ranges_m.size(), MapRayKind::kHit);
  v.colours = e.view.colours;
  for (std::size_t b = 0; b < e.kinds.size() && b < v.kinds.size(); ++b) {
    v.kinds[b] = e.kinds[b] == core::ReadingKind::kHit     ? MapRayKind::kHit
                 : e.kinds[b] == core::ReadingKind::kClear ? MapRayKind::kClear
                                                           : MapRayKind::kUnknown;
  }
  return v;
}

// Agreement at integer shift `shift` (query bin b against map bin b + shift).
MapAgreement AgreementAtShift(const localize::PlaceView& query,
                              const std::vector<core::ReadingKind>& kinds, const MapView& map_view,
                              int shift, double sigma_floor_m) {
  double sum = 0.0;
  double weight = 0.0;
  int compared = 0;
  for (int b = 0; b < kBins; ++b) {
    const int m = Wrap(b + shift);
    const MapRayKind mk = map_view.kinds[static_cast<std::size_t>(m)];
    if (mk == MapRayKind::kUnknown) continue;
    const double rq = query.ranges_m[static_cast<std::size_t>(b)];
    const double rm = map_view.ranges_m[static_cast<std::size_t>(m)];
    const double sigma = std::max(sigma_floor_m, kAgreementSigmaFraction * rq);
    const double d = rm - rq;
    const core::ReadingKind qk = kinds[static_cast<std::size_t>(b)];
    const bool colour_mismatch =
        !query.colours.empty() && !map_view.colours.empty() &&
        query.colours[static_cast<std::size_t>(b)] != core::ColourClass::kNone &&
        map_view.colours[static_cast<std::size_t>(m)] != core::ColourClass::kNone &&
        query.colours[static_cast<std::size_t>(b)] != map_view.colours[static_cast<std::size_t>(m)];
    // Floor seen clear where the map is clear says little (most bearings of
    // an open floor): such bins weigh kClearWeight.
    const double w =
        qk == core::ReadingKind::kClear && mk == MapRayKind::kClear ? kClearWeight : 1.0;
    double a = 0.0;
    if (qk == core::ReadingKind::kBlind) {
      a = d <= 2.0 * sigma
              ? 1.0
              : std::exp(-0.5 * (d - 2.0 * sigma) * (d - 2.0 * sigma) / (sigma * sigma));
    } else {
      a = std::exp(-0.5 * d * d / (sigma * sigma));
    }
    if (colour_mismatch) a *= kColourMismatchFactor;
    sum += w * a;
    weight += w;
    ++compared;
  }
  return {weight > 0.0 ? sum / weight : 0.0, compared};
}

// The best integer shift in [lo, hi] (degrees) and its parabola-refined heading.
struct ShiftFit {
  double heading_rad = 0.0;
  MapAgreement agreement;
};

ShiftFit BestShift(const localize::PlaceView& query, const std::vector<core::ReadingKind>& kinds,
                   const MapView& map_view, int lo, int hi, double sigma_floor_m) {
  std::vector<double> scores;
  ShiftFit best;
  best.agreement.score = -1.0;
  int best_shift = lo;
  for (int s = lo; s <= hi; ++s) {
    const MapAgreement a = AgreementAtShift(query, kinds, map_view, s, sigma_floor_m);
    scores.push_back(a.score);
    if (a.score > best.agreement.score) {
      best.agreement = a;
      best_shift = s;
    }
  }
  double frac = 0.0;
  const int i = best_shift - lo;
  if (i > 0 && i + 1 < static_cast<int>(scores.size())) {
    const double l = scores[static_cast<std::size_t>(i) - 1];
    const double c = scores[static_cast<std::size_t>(i)];
    const double r = scores[static_cast<std::size_t>(i) + 1];
    const double den = l - 2.0 * c + r;
    if (den < 0.0) frac = std::clamp(0.5 * (l - r) / den, -0.5, 0.5);
  }
  best.heading_rad = core::NormalizeAngle((best_shift + frac) * kBinRad);
  return best;
}

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

std::uint64_t Fnv(std::uint64_t h, const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

}  // namespace

MapView CastMapView(const mapping::TrinaryMap& map, const Eigen::Vector2d& origin_m,
                    double max_range_m, const localize::ColourMap& colours) {
  const core::GridGeometry& g = map.geometry;
  const double step = 0.25 * g.resolution();
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

mapping::TrinaryMap FillPinholes(const mapping::TrinaryMap& map, int max_cells) {
  const core::GridGeometry& g = map.geometry;
  cv::Mat unknown(g.height(), g.width(), CV_8U, cv::Scalar(0));
  cv::Mat occupied(g.height(), g.width(), CV_8U, cv::Scalar(0));
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const mapping::CellState s = map.At({x, y});
      unknown.at<std::uint8_t>(y, x) = s == mapping::CellState::kUnknown ? 255 : 0;
      occupied.at<std::uint8_t>(y, x) = s == mapping::CellState::kOccupied ? 255 : 0;
    }
  }
  cv::Mat labels;
  cv::Mat stats;
  cv::Mat centroids;
  const int n = cv::connectedComponentsWithStats(unknown, labels, stats, centroids, 4, CV_32S);
  // A group touches an obstacle when an occupied cell is among its cells' 8
  // neighbours: when the occupied cells grown by one cell overlap it.
  cv::Mat near_occupied;
  cv::dilate(occupied, near_occupied, cv::Mat::ones(3, 3, CV_8U));
  std::vector<bool> fill(static_cast<std::size_t>(n), false);
  for (int i = 1; i < n; ++i) {
    fill[static_cast<std::size_t>(i)] = stats.at<int>(i, cv::CC_STAT_AREA) <= max_cells;
  }
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (near_occupied.at<std::uint8_t>(y, x) != 0) {
        fill[static_cast<std::size_t>(labels.at<int>(y, x))] = false;
      }
    }
  }
  mapping::TrinaryMap out = map;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (fill[static_cast<std::size_t>(labels.at<int>(y, x))]) {
        out.cells[g.Flat({x, y})] = mapping::CellState::kFree;
      }
    }
  }
  return out;
}

bool DiscFreeOnMap(const mapping::TrinaryMap& map, const Eigen::Vector2d& p_m, double radius_m) {
  const core::GridGeometry& g = map.geometry;
  const core::CellIndex lo = g.CellOf(p_m - Eigen::Vector2d(radius_m, radius_m));
  const core::CellIndex hi = g.CellOf(p_m + Eigen::Vector2d(radius_m, radius_m));
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const core::CellIndex c{x, y};
      if ((g.CellCentre(c) - p_m).norm() > radius_m) continue;
      if (!g.Contains(c) || map.At(c) != mapping::CellState::kFree) return false;
    }
  }
  return true;
}

std::string MapTableName(const mapping::TrinaryMap& map, const localize::ColourMap& colours,
                         double robot_radius_m, double spacing_m, double max_range_m) {
  std::uint64_t h = 1469598103934665603ULL;
  const double geo[3] = {map.geometry.resolution(), map.geometry.origin().x(),
                         map.geometry.origin().y()};
  const int size[2] = {map.geometry.width(), map.geometry.height()};
  h = Fnv(h, geo, sizeof(geo));
  h = Fnv(h, size, sizeof(size));
  h = Fnv(h, map.cells.data(), map.cells.size() * sizeof(mapping::CellState));
  // A map without a colour layer keeps the name it had before there were any.
  if (!colours.empty()) {
    h = Fnv(h, colours.cells().data(), colours.cells().size() * sizeof(core::ColourClass));
  }
  // "rays 2": CastMapView meets an obstacle through a gap in its outline (a
  // table made before that is not reused).
  return fmt::format("map {:016x} radius {:.4f} spacing {:.4f} range {:.4f} rays 2", h,
                     robot_radius_m, spacing_m, max_range_m);
}

localize::PlaceTable BuildMapPlaceTable(const mapping::TrinaryMap& map,
                                        const localize::ColourMap& colours, double robot_radius_m,
                                        double spacing_m, double max_range_m) {
  const core::GridGeometry& g = map.geometry;
  const Eigen::Vector2d lo = g.origin();
  const Eigen::Vector2d hi =
      lo + Eigen::Vector2d(g.width() * g.resolution(), g.height() * g.resolution());
  std::vector<localize::PlaceEntry> entries;
  for (double y = lo.y() + 0.5 * spacing_m; y < hi.y(); y += spacing_m) {
    for (double x = lo.x() + 0.5 * spacing_m; x < hi.x(); x += spacing_m) {
      if (!DiscFreeOnMap(map, {x, y}, robot_radius_m)) continue;
      const MapView v = CastMapView(map, {x, y}, max_range_m, colours);
      localize::PlaceEntry e{x, y, 0.0, {v.ranges_m, v.colours}, {}};
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

LocateAnswer Locate(const mapping::TrinaryMap& map, const localize::ColourMap& colours,
                    const localize::PlaceTable& table, const localize::PlaceView& query,
                    const std::vector<core::ReadingKind>& kinds, double spacing_m,
                    double coarse_cell_m, const LocateOptions& options) {
  LocateAnswer answer;
  for (const core::ReadingKind k : kinds) answer.seen_bins += k != core::ReadingKind::kClear;
  const double cell = map.geometry.resolution();
  const double fine_sigma = std::max(kAgreementSigmaFloorM, cell);
  // Coarse: every place, every heading, with a σ as wide as the parallax of
  // being half a spacing away.
  const double coarse_sigma = std::max(fine_sigma, 0.5 * spacing_m);
  struct Coarse {
    int entry;
    double heading_rad;
    double score;
  };
  std::vector<Coarse> coarse;
  for (std::size_t i = 0; i < table.entries().size(); ++i) {
    const ShiftFit f =
        BestShift(query, kinds, EntryMapView(table.entries()[i]), 0, kBins - 1, coarse_sigma);
    // Few compared bins make a score unreliable: weight by coverage.
    const double coverage = std::min(1.0, f.agreement.compared / double(kBins));
    coarse.push_back({static_cast<int>(i), f.heading_rad, f.agreement.score * coverage});
  }
  std::sort(coarse.begin(), coarse.end(),
            [](const Coarse& a, const Coarse& b) { return a.score > b.score; });
  // The best. (The table's places lie a spacing apart, on BuildMapPlaceTable's
  // grid, so they need no spreading.)
  if (static_cast<int>(coarse.size()) > options.candidates) {
    coarse.resize(static_cast<std::size_t>(std::max(0, options.candidates)));
  }
  // Fine: a pattern search of position, the full heading search at each.
  const double max_range = table.max_range_m();
  for (const Coarse& c : coarse) {
    const localize::PlaceEntry& e = table.entries()[static_cast<std::size_t>(c.entry)];
    Eigen::Vector2d best_p(e.x_m, e.y_m);
    auto eval = [&](const Eigen::Vector2d& p) {
      const MapView v = CastMapView(map, p, max_range, colours);
      return BestShift(query, kinds, v, 0, kBins - 1, fine_sigma);
    };
    ShiftFit best = eval(best_p);
    for (double step = 0.5 * spacing_m; step >= 0.75 * cell; step *= 0.5) {
      for (int iter = 0; iter < 4; ++iter) {
        Eigen::Vector2d next = best_p;
        ShiftFit next_fit = best;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            const Eigen::Vector2d p = best_p + step * Eigen::Vector2d(dx, dy);
            const core::CellIndex ci = map.geometry.CellOf(p);
            if (!map.geometry.Contains(ci) || map.At(ci) != mapping::CellState::kFree) continue;
            const ShiftFit f = eval(p);
            if (f.agreement.score > next_fit.agreement.score) {
              next = p;
              next_fit = f;
            }
          }
        }
        if (next == best_p) break;
        best_p = next;
        best = next_fit;
      }
    }
    answer.candidates.push_back({core::Pose2(best_p.x(), best_p.y(), best.heading_rad),
                                 best.agreement.score, best.agreement.compared});
  }
  std::sort(answer.candidates.begin(), answer.candidates.end(),
            [](const LocateCandidate& a, const LocateCandidate& b) { return a.score > b.score; });
  // Searches that converged to the same pose are one candidate.
  std::vector<LocateCandidate> distinct;
  for (const LocateCandidate& c : answer.candidates) {
    bool same = false;
    for (const LocateCandidate& d : distinct) {
      same = same || ((c.world_T_robot.translation() - d.world_T_robot.translation()).norm() <=
                          0.5 * coarse_cell_m &&
                      std::abs(core::NormalizeAngle(c.world_T_robot.heading() -
                                                    d.world_T_robot.heading())) < 0.1);
    }
    if (!same) distinct.push_back(c);
  }
  answer.candidates = std::move(distinct);
  if (answer.candidates.empty()) {
    answer.reason = "the map has no place where the robot fits";
    return answer;
  }
  const LocateCandidate& top = answer.candidates.front();
  answer.world_T_robot = top.world_T_robot;
  answer.agreement = top.score;
  answer.compared = top.compared;
  for (const LocateCandidate& c : answer.candidates) {
    if ((c.world_T_robot.translation() - top.world_T_robot.translation()).norm() > coarse_cell_m) {
      answer.runner_up = std::max(answer.runner_up, c.score);
    }
  }
  if (answer.seen_bins < options.min_seen) {
    answer.reason = fmt::format("the pirouette saw too little ({} of {} bearings hit something)",
                                answer.seen_bins, kBins);
  } else if (top.compared < options.min_compared) {
    answer.reason = fmt::format(
        "too little of the view can be compared with the map ({} of {} "
        "bearings)",
        top.compared, kBins);
  } else if (top.score < options.min_agreement) {
    answer.reason = fmt::format("no place of the map agrees well enough (best {:.3f} < {:.3f})",
                                top.score, options.min_agreement);
  } else if (top.score - answer.runner_up < options.min_margin) {
    answer.reason = fmt::format(
        "ambiguous: a place more than a coarse cell away agrees nearly as well ({:.3f} vs {:.3f})",
        answer.runner_up, top.score);
  } else {
    answer.found = true;
  }
  return answer;
}

LocateResult RunLocate(const LocateRequest& request) {
  if (!request.pose && request.random < 1) {
    throw core::InputError("", 0, "--pose", "give --pose X,Y,H or --random N (N >= 1)");
  }
  // Rays pass the map's pinholes (FillPinholes), here and in the table.
  mapping::TrinaryMap map = FillPinholes(io::ReadRosMap(request.map_path), kPinholeCells);
  const sim::World world = io::LoadWorldFile(request.world_path);
  LocateResult result;
  result.coarse_cell_m = CoarseCellSize(world);
  result.spacing_m = DefaultTableSpacing(world);
  result.max_range_m = PlaceMaxRange(world, request.range_factor);
  result.table_path =
      request.table_path.empty()
          ? (std::filesystem::path(request.map_path).parent_path() / "places.yaml").string()
          : request.table_path;
  if (request.pose) sim::PlaceRobot(world, *request.pose, "--pose");  // throws when it does not fit
  localize::ColourMap colours;
  if (request.use_colours) {
    result.colours_path = request.colours_path.empty() ? io::ColourMapPathFor(request.map_path)
                                                       : request.colours_path;
    if (!request.colours_path.empty() || std::filesystem::exists(result.colours_path)) {
      colours = io::ReadColourMap(result.colours_path, map.geometry);
    } else {
      result.colours_path.clear();
    }
  }

  const auto table_start = Clock::now();
  const std::string name =
      MapTableName(map, colours, world.robot().radius, result.spacing_m, result.max_range_m);
  localize::PlaceTable table;
  if (std::filesystem::exists(result.table_path)) {
    table = io::LoadPlaceTable(result.table_path);
    result.table_loaded = table.world() == name && !table.entries().empty();
    result.table_replaced = !result.table_loaded;
  }
  if (!result.table_loaded) {
    table = BuildMapPlaceTable(map, colours, world.robot().radius, result.spacing_m,
                               result.max_range_m);
    if (table.entries().empty()) {
      throw core::InputError(request.map_path, 0, "",
                             "the map has no free place where the robot fits");
    }
    io::SavePlaceTable(table, result.table_path);
  }
  result.table_s = run::Seconds(Clock::now() - table_start);
  result.table_places = static_cast<int>(table.entries().size());

  const std::vector<core::Pose2> truths =
      request.pose ? std::vector<core::Pose2>{*request.pose}
                   : sim::RandomRobotPoses(world, request.random, request.seed, request.world_path);

  PlaceObserver observer(world, request.method, result.max_range_m, request.seed);
  run::ProgressLine line(request.quiet);
  const auto start = Clock::now();
  double locate_s = 0.0;
  for (std::size_t q = 0; q < truths.size(); ++q) {
    const ObservedPlace seen = observer.Observe(truths[q], request.seed * 7919 + q);
    const auto t0 = Clock::now();
    LocateTrial trial;
    trial.truth = truths[q];
    trial.seen = seen;
    trial.answer = Locate(map, colours, table, seen.view, seen.kinds, result.spacing_m,
                          result.coarse_cell_m, request.options);
    locate_s += run::Seconds(Clock::now() - t0);
    trial.position_error_m =
        (trial.answer.world_T_robot.translation() - trial.truth.translation()).norm();
    trial.heading_error_deg = std::abs(core::RadToDeg(
        core::NormalizeAngle(trial.answer.world_T_robot.heading() - trial.truth.heading())));
    const bool close = trial.position_error_m <= result.coarse_cell_m &&
                       trial.heading_error_deg <= request.options.heading_tolerance_deg;
    trial.right = trial.answer.found && close;
    result.found_right += trial.right ? 1 : 0;
    result.cannot_tell += trial.answer.found ? 0 : 1;
    result.wrong += trial.answer.found && !close ? 1 : 0;
    result.trials.push_back(std::move(trial));
    line.Show(run::Seconds(Clock::now() - start), [&] {
      return fmt::format("locate {}: {}/{} pirouettes, {} found right, {} cannot tell, {} wrong",
                         world.name(), q + 1, truths.size(), result.found_right, result.cannot_tell,
                         result.wrong);
    });
  }
  result.mean_locate_s = truths.empty() ? 0.0 : locate_s / truths.size();
  result.map = std::move(map);
  return result;
}

nlohmann::json LocateJson(const LocateRequest& request, const LocateResult& result) {
  const auto pose = [](const core::Pose2& p) {
    return nlohmann::json{{"x", p.x()}, {"y", p.y()}, {"heading_deg", core::RadToDeg(p.heading())}};
  };
  nlohmann::json trials = nlohmann::json::array();
  for (const LocateTrial& t : result.trials) {
    nlohmann::json candidates = nlohmann::json::array();
    for (const LocateCandidate& c : t.answer.candidates) {
      nlohmann::json j = pose(c.world_T_robot);
      j["agreement"] = c.score;
      j["compared"] = c.compared;
      candidates.push_back(j);
    }
    nlohmann::json j{{"truth", pose(t.truth)},
                     {"found", t.answer.found},
                     {"best", pose(t.answer.world_T_robot)},
                     {"agreement", t.answer.agreement},
                     {"runner_up", t.answer.runner_up},
                     {"compared", t.answer.compared},
                     {"seen_bins", t.answer.seen_bins},
                     {"position_error_m", t.position_error_m},
                     {"heading_error_deg", t.heading_error_deg},
                     {"right", t.right},
                     {"candidates", candidates}};
    if (!t.answer.found) j["reason"] = t.answer.reason;
    trials.push_back(j);
  }
  return {{"format", "pirouette-locate-report/1"},
          {"map", request.map_path},
          {"world", request.world_path},
          {"seed", request.seed},
          {"table", result.table_path},
          {"table_loaded", result.table_loaded},
          {"colours", result.colours_path.empty() ? nlohmann::json(nullptr)
                                                  : nlohmann::json(result.colours_path)},
          {"table_places", result.table_places},
          {"spacing_m", result.spacing_m},
          {"coarse_cell_m", result.coarse_cell_m},
          {"max_range_m", result.max_range_m},
          {"queries", result.trials.size()},
          {"found_right", result.found_right},
          {"cannot_tell", result.cannot_tell},
          {"wrong", result.wrong},
          {"table_s", result.table_s},
          {"mean_locate_s", result.mean_locate_s},
          {"trials", trials}};
}

}  // namespace pirouette::app
