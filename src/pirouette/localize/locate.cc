#include "pirouette/localize/locate.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pirouette/core/angle.h"
#include "pirouette/localize/map_view.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::localize {
namespace {

constexpr int kBins = mapping::kRadialProfileBins;
constexpr double kBinRad = 2.0 * std::numbers::pi / kBins;

// The pattern search of a candidate's position: steps from half a table
// spacing, halved down to kFinestStepCells map cells, at most kStepRounds
// moves at each step.
constexpr double kFinestStepCells = 0.75;
constexpr int kStepRounds = 4;
// Refined candidates within half a coarse cell and kSameHeadingRad of each
// other are one.
constexpr double kSameHeadingRad = 0.1;

int Wrap(int b) { return ((b % kBins) + kBins) % kBins; }

// The table place's stored view, as a MapView (blind = unknown).
MapView EntryMapView(const PlaceEntry& e) {
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
MapAgreement AgreementAtShift(const PlaceView& query, const std::vector<core::ReadingKind>& kinds,
                              const MapView& map_view, int shift, double sigma_floor_m) {
  double sum = 0.0;
  double weight = 0.0;
  int compared = 0;
  for (int b = 0; b < kBins; ++b) {
    const auto bq = static_cast<std::size_t>(b);
    const auto m = static_cast<std::size_t>(Wrap(b + shift));
    const MapRayKind mk = map_view.kinds[m];
    if (mk == MapRayKind::kUnknown) continue;
    const double rq = query.ranges_m[bq];
    const double rm = map_view.ranges_m[m];
    const double sigma = std::max(sigma_floor_m, kAgreementSigmaFraction * rq);
    const double d = rm - rq;
    const core::ReadingKind qk = kinds[bq];
    const bool colour_mismatch = !query.colours.empty() && !map_view.colours.empty() &&
                                 query.colours[bq] != core::ColourClass::kNone &&
                                 map_view.colours[m] != core::ColourClass::kNone &&
                                 query.colours[bq] != map_view.colours[m];
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

// The best integer shift of all (degrees) and its parabola-refined heading.
struct ShiftFit {
  double heading_rad = 0.0;
  MapAgreement agreement;
};

ShiftFit BestShift(const PlaceView& query, const std::vector<core::ReadingKind>& kinds,
                   const MapView& map_view, double sigma_floor_m) {
  std::vector<double> scores;
  ShiftFit best;
  best.agreement.score = -1.0;
  int best_shift = 0;
  for (int s = 0; s < kBins; ++s) {
    const MapAgreement a = AgreementAtShift(query, kinds, map_view, s, sigma_floor_m);
    scores.push_back(a.score);
    if (a.score > best.agreement.score) {
      best.agreement = a;
      best_shift = s;
    }
  }
  double frac = 0.0;
  const int i = best_shift;
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

// A table place and its best heading, scored coarsely.
struct CoarseMatch {
  int entry;
  double heading_rad;
  double score;
};

// Every place of the table at every heading, with a σ as wide as the
// parallax of being half a spacing away, weighted by the compared bins'
// coverage (few compared bins make a score unreliable); the best
// `candidates`, best first.
std::vector<CoarseMatch> CoarseMatches(const PlaceTable& table, const PlaceView& query,
                                       const std::vector<core::ReadingKind>& kinds,
                                       double coarse_sigma, int candidates) {
  std::vector<CoarseMatch> coarse;
  for (std::size_t i = 0; i < table.entries().size(); ++i) {
    const ShiftFit f = BestShift(query, kinds, EntryMapView(table.entries()[i]), coarse_sigma);
    const double coverage = std::min(1.0, f.agreement.compared / double(kBins));
    coarse.push_back({static_cast<int>(i), f.heading_rad, f.agreement.score * coverage});
  }
  std::sort(coarse.begin(), coarse.end(),
            [](const CoarseMatch& a, const CoarseMatch& b) { return a.score > b.score; });
  // The table's places lie a spacing apart, on BuildMapPlaceTable's grid, so
  // they need no spreading.
  if (static_cast<int>(coarse.size()) > candidates) {
    coarse.resize(static_cast<std::size_t>(std::max(0, candidates)));
  }
  return coarse;
}

// A pattern search of position from `start`, the full heading search at
// each, over the map's free cells.
LocateCandidate Refine(const mapping::TrinaryMap& map, const ColourMap& colours, double max_range_m,
                       const PlaceView& query, const std::vector<core::ReadingKind>& kinds,
                       const Eigen::Vector2d& start, double spacing_m, double fine_sigma) {
  const double cell = map.geometry.resolution();
  const auto fit = [&](const Eigen::Vector2d& p) {
    return BestShift(query, kinds, CastMapView(map, p, max_range_m, colours), fine_sigma);
  };
  Eigen::Vector2d best_p = start;
  ShiftFit best = fit(best_p);
  for (double step = 0.5 * spacing_m; step >= kFinestStepCells * cell; step *= 0.5) {
    for (int iter = 0; iter < kStepRounds; ++iter) {
      Eigen::Vector2d next = best_p;
      ShiftFit next_fit = best;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if (dx == 0 && dy == 0) continue;
          const Eigen::Vector2d p = best_p + step * Eigen::Vector2d(dx, dy);
          const core::CellIndex ci = map.geometry.CellOf(p);
          if (!map.geometry.Contains(ci) || map.At(ci) != mapping::CellState::kFree) continue;
          const ShiftFit f = fit(p);
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
  return {core::Pose2(best_p.x(), best_p.y(), best.heading_rad), best.agreement.score,
          best.agreement.compared};
}

// The candidates best first, those that converged to the same pose as a
// better one left out.
std::vector<LocateCandidate> Distinct(std::vector<LocateCandidate> candidates,
                                      double coarse_cell_m) {
  std::sort(candidates.begin(), candidates.end(),
            [](const LocateCandidate& a, const LocateCandidate& b) { return a.score > b.score; });
  std::vector<LocateCandidate> distinct;
  for (const LocateCandidate& c : candidates) {
    bool same = false;
    for (const LocateCandidate& d : distinct) {
      same = same || ((c.world_T_robot.translation() - d.world_T_robot.translation()).norm() <=
                          0.5 * coarse_cell_m &&
                      std::abs(core::NormalizeAngle(c.world_T_robot.heading() -
                                                    d.world_T_robot.heading())) < kSameHeadingRad);
    }
    if (!same) distinct.push_back(c);
  }
  return distinct;
}

// Fills the answer from its (distinct, best first, not empty) candidates and
// judges it against the options.
void Judge(LocateAnswer& answer, double coarse_cell_m, const LocateOptions& options) {
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
}

}  // namespace

LocateAnswer Locate(const mapping::TrinaryMap& map, const ColourMap& colours,
                    const PlaceTable& table, const PlaceView& query,
                    const std::vector<core::ReadingKind>& kinds, double spacing_m,
                    double coarse_cell_m, const LocateOptions& options) {
  LocateAnswer answer;
  for (const core::ReadingKind k : kinds) answer.seen_bins += k != core::ReadingKind::kClear;
  const double fine_sigma = std::max(kAgreementSigmaFloorM, map.geometry.resolution());
  const double coarse_sigma = std::max(fine_sigma, 0.5 * spacing_m);
  std::vector<LocateCandidate> refined;
  for (const CoarseMatch& c :
       CoarseMatches(table, query, kinds, coarse_sigma, options.candidates)) {
    const PlaceEntry& e = table.entries()[static_cast<std::size_t>(c.entry)];
    refined.push_back(Refine(map, colours, table.max_range_m(), query, kinds,
                             Eigen::Vector2d(e.x_m, e.y_m), spacing_m, fine_sigma));
  }
  answer.candidates = Distinct(std::move(refined), coarse_cell_m);
  if (answer.candidates.empty()) {
    answer.reason = "the map has no place where the robot fits";
    return answer;
  }
  Judge(answer, coarse_cell_m, options);
  return answer;
}

}  // namespace pirouette::localize
