#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <numbers>
#include <unordered_set>
#include <vector>

namespace pirouette::localize {

struct ScanMatchOptions {
  // The reference's cells.
  double cell_m = 0.01;
  // A hit agrees with the nearest reference hit at distance d by
  // log(floor + exp(-d²/2σ²)): bounded below, so a hit where the reference
  // saw nothing (new ground, or a moved obstacle) costs the same at every
  // pose and cannot pull the match.
  double sigma_m = 0.02;
  double floor = 0.05;
  // The hits' errors are not independent (a wall reads off by the same
  // amount all along it): their summed log-likelihood is divided by this.
  // Of 2, 4 and 10 (docs/measurements.md, "Pose tracking"), 10 trusts the
  // prior too much, 2 and 4 track alike.
  double correlation = 4.0;
  // The search: ±window_sigmas × the prior's σ in position (between
  // min_window_m and max_window_m) and heading, on cell_m and step_rad.
  double window_sigmas = 3.0;
  double min_window_m = 0.03;
  double max_window_m = 0.25;
  double step_rad = 0.25 * std::numbers::pi / 180.0;
  // Fewer hits near reference hits than this at the prior's mean: no match.
  int min_overlap = 20;

  // Throws std::invalid_argument unless every field is in range.
  void Check() const;
};

// Obstacle points seen before (in the map's frame), kept once per cell.
class HitStore {
 public:
  explicit HitStore(double cell_m = 0.01);
  void Add(const Eigen::Vector2d& p_map);
  // The cell a point falls in, and a cell's key: what the store keeps.
  Eigen::Vector2i CellOf(const Eigen::Vector2d& p_map) const;
  static std::int64_t KeyOf(const Eigen::Vector2i& cell);
  // The stored points (cell centres) within the axis-aligned box.
  std::vector<Eigen::Vector2d> Within(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) const;
  std::size_t size() const { return cells_.size(); }
  double cell_m() const { return cell_m_; }

 private:
  double cell_m_;
  std::unordered_set<std::int64_t> cells_;
};

// A pose correction (dx, dy in the map's frame, dθ about the scan's origin)
// and how sure of it the match is.
struct ScanMatch {
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // the posterior's
  // The same moments of the likelihood alone (no prior): what the match
  // itself measured, for a pose graph's edge, whose other edges already carry
  // what the prior knew. A direction the hits do not pin spreads over the
  // whole window (a corridor's length: variance about window²/3).
  Eigen::Vector3d likelihood_offset = Eigen::Vector3d::Zero();
  Eigen::Matrix3d likelihood_covariance = Eigen::Matrix3d::Zero();
  int overlap = 0;  // hits near a reference hit at the prior's mean
  // The share of the hits within 2σ of a reference hit at the likelihood's
  // best correction (0 to 1): how well the scan fits the reference at all.
  double response = 0.0;
  bool accepted = false;  // else offset 0 and covariance the prior's
};

// Correlative scan matching (Olson 2009, "Real-time correlative scan
// matching"): a scan's hits, given as offsets from its origin in the map's
// orientation (hit = origin + offset), against the reference hits, over a
// grid of corrections around the prior (zero mean, covariance
// prior_covariance of dx, dy, dθ). Returns the posterior's mean and
// covariance over the grid, the likelihood being each hit's agreement with
// the nearest reference hit (ScanMatchOptions); a direction the hits do not
// pin (a corridor's length) keeps the prior's mean. Not accepted (no
// search) when fewer than min_overlap hits agree with the reference at the
// prior's mean. Throws std::invalid_argument for bad options, a prior that
// is not finite and positive definite, or a reference whose cells are not
// options.cell_m.
ScanMatch MatchScan(const HitStore& reference, const Eigen::Vector2d& origin,
                    const std::vector<Eigen::Vector2d>& hit_offsets,
                    const Eigen::Matrix3d& prior_covariance, const ScanMatchOptions& options = {});

}  // namespace pirouette::localize
