#include "pirouette/sim/clearance_index.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pirouette::sim {
namespace {

// Buckets a floor side at most (so that a huge floor with a short reach
// keeps to a few million buckets; a longer side only lists more solids).
constexpr int kMaxBucketsASide = 2048;

// Solids this much farther than the reach are listed too: the rounding of a
// distance (~1e-16 m) can never make an unlisted solid the nearest.
constexpr double kListingSlackM = 1e-6;

}  // namespace

ClearanceIndex::ClearanceIndex(const World& world, double reach_m)
    : world_(world), reach_(reach_m) {
  if (!(reach_m > 0.0) || !std::isfinite(reach_m)) {
    throw std::invalid_argument("ClearanceIndex: the reach must be > 0");
  }
  const Eigen::Vector2d& size = world.floor().size;
  side_ = std::max({reach_m, size.x() / kMaxBucketsASide, size.y() / kMaxBucketsASide});
  columns_ = std::max(1, static_cast<int>(std::ceil(size.x() / side_)));
  rows_ = std::max(1, static_cast<int>(std::ceil(size.y() / side_)));
  buckets_.resize(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_));
  const double margin = reach_m + kListingSlackM;
  const std::vector<Solid>& solids = world.solids();
  for (std::size_t s = 0; s < solids.size(); ++s) {
    Eigen::Vector2d lo = solids[s].footprint.front();
    Eigen::Vector2d hi = lo;
    for (const Eigen::Vector2d& v : solids[s].footprint) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    if (const auto& circle = solids[s].circle) {
      lo = lo.cwiseMin(circle->centre - Eigen::Vector2d::Constant(circle->radius));
      hi = hi.cwiseMax(circle->centre + Eigen::Vector2d::Constant(circle->radius));
    }
    // Every bucket that the solid's box grown by the margin overlaps.
    const auto first = [&](double v, int n) {
      return std::clamp(static_cast<int>(std::floor((v - margin) / side_)), 0, n - 1);
    };
    const auto last = [&](double v, int n) {
      return std::clamp(static_cast<int>(std::floor((v + margin) / side_)), 0, n - 1);
    };
    if (hi.x() + margin < 0.0 || hi.y() + margin < 0.0 || lo.x() - margin > size.x() ||
        lo.y() - margin > size.y()) {
      continue;  // nowhere near the floor
    }
    for (int row = first(lo.y(), rows_); row <= last(hi.y(), rows_); ++row) {
      for (int column = first(lo.x(), columns_); column <= last(hi.x(), columns_); ++column) {
        buckets_[static_cast<std::size_t>(row) * columns_ + column].push_back(
            static_cast<std::int32_t>(s));
      }
    }
  }
}

const std::vector<std::int32_t>& ClearanceIndex::BucketOf(const Eigen::Vector2d& p) const {
  const int column = std::clamp(static_cast<int>(std::floor(p.x() / side_)), 0, columns_ - 1);
  const int row = std::clamp(static_cast<int>(std::floor(p.y() / side_)), 0, rows_ - 1);
  return buckets_[static_cast<std::size_t>(row) * columns_ + column];
}

// As World::Clearance: the floor's edges, then each solid in turn, 0 at the
// first that holds p. The bucket's solids are all those within reach of p;
// where the nearest of them is farther, every solid is asked.
double ClearanceIndex::Clearance(const Eigen::Vector2d& p) const {
  if (!world_.OnFloor(p)) return 0.0;
  const Eigen::Vector2d& size = world_.floor().size;
  double clearance = std::min({p.x(), size.x() - p.x(), p.y(), size.y() - p.y()});
  const std::vector<Solid>& solids = world_.solids();
  for (const std::int32_t s : BucketOf(p)) {
    clearance = std::min(clearance, solids[static_cast<std::size_t>(s)].SignedDistance(p));
    if (clearance <= 0.0) return 0.0;
  }
  if (clearance <= reach_) return clearance;
  return world_.Clearance(p);
}

bool ClearanceIndex::IsOccupied(const Eigen::Vector2d& p) const {
  if (!world_.OnFloor(p)) return true;
  const std::vector<Solid>& solids = world_.solids();
  const std::vector<std::int32_t>& bucket = BucketOf(p);
  return std::any_of(bucket.begin(), bucket.end(), [&](std::int32_t s) {
    return solids[static_cast<std::size_t>(s)].SignedDistance(p) <= kOnFaceM;
  });
}

}  // namespace pirouette::sim
