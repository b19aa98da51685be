#include "pirouette/localize/scan_matcher.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace pirouette::localize {

void ScanMatchOptions::Check() const {
  if (!(cell_m > 0.0) || !(sigma_m > 0.0) || !(floor > 0.0) || !(correlation >= 1.0) ||
      !(window_sigmas > 0.0) || !(min_window_m >= 0.0) || !(max_window_m >= min_window_m) ||
      !(step_rad > 0.0) || min_overlap < 0) {
    throw std::invalid_argument(
        "ScanMatchOptions: cell_m, sigma_m, floor, window_sigmas and step_rad must be > 0, "
        "correlation >= 1, 0 <= min_window_m <= max_window_m, min_overlap >= 0");
  }
}

namespace {

std::int64_t Key(std::int64_t ix, std::int64_t iy) { return (ix << 32) ^ (iy & 0xffffffffLL); }

}  // namespace

HitStore::HitStore(double cell_m) : cell_m_(cell_m) {
  if (!(cell_m > 0.0)) throw std::invalid_argument("HitStore: cell_m must be > 0");
}

void HitStore::Add(const Eigen::Vector2d& p_map) {
  cells_.insert(Key(static_cast<std::int64_t>(std::floor(p_map.x() / cell_m_)),
                    static_cast<std::int64_t>(std::floor(p_map.y() / cell_m_))));
}

std::vector<Eigen::Vector2d> HitStore::Within(const Eigen::Vector2d& lo,
                                              const Eigen::Vector2d& hi) const {
  std::vector<Eigen::Vector2d> out;
  for (const std::int64_t key : cells_) {
    const auto ix = static_cast<std::int32_t>(key >> 32);
    const auto iy = static_cast<std::int32_t>(key & 0xffffffffLL);
    const Eigen::Vector2d p((ix + 0.5) * cell_m_, (iy + 0.5) * cell_m_);
    if (p.x() >= lo.x() && p.y() >= lo.y() && p.x() <= hi.x() && p.y() <= hi.y()) {
      out.push_back(p);
    }
  }
  return out;
}

ScanMatch MatchScan(const HitStore& reference, const Eigen::Vector2d& origin,
                    const std::vector<Eigen::Vector2d>& hit_offsets,
                    const Eigen::Matrix3d& prior_covariance, const ScanMatchOptions& options) {
  options.Check();
  ScanMatch result;
  result.covariance = prior_covariance;
  if (!prior_covariance.allFinite() || prior_covariance(0, 0) <= 0.0 ||
      prior_covariance(1, 1) <= 0.0 || prior_covariance(2, 2) <= 0.0 ||
      prior_covariance.llt().info() != Eigen::Success) {
    throw std::invalid_argument(
        "MatchScan: the prior covariance must be finite and positive "
        "definite");
  }
  if (reference.cell_m() != options.cell_m) {
    throw std::invalid_argument("MatchScan: the reference's cells must be options.cell_m");
  }
  if (hit_offsets.empty() || reference.size() == 0) return result;

  const double cell = options.cell_m;
  const double sigma = options.sigma_m;
  const auto window = [&](double variance) {
    return std::clamp(options.window_sigmas * std::sqrt(variance), options.min_window_m,
                      options.max_window_m);
  };
  const int nx = static_cast<int>(std::round(window(prior_covariance(0, 0)) / cell));
  const int ny = static_cast<int>(std::round(window(prior_covariance(1, 1)) / cell));
  // Never past a half turn either way.
  const int nt = static_cast<int>(std::min(
      std::ceil(options.window_sigmas * std::sqrt(prior_covariance(2, 2)) / options.step_rad),
      std::floor(std::numbers::pi / options.step_rad)));

  // The agreement of a point with the reference, on a local grid around the
  // scan, wide enough for every hit at every correction.
  double reach = 0.0;
  for (const Eigen::Vector2d& q : hit_offsets) reach = std::max(reach, q.norm());
  const int kernel = static_cast<int>(std::ceil(3.0 * sigma / cell));
  const double margin = reach + std::max(nx, ny) * cell + (kernel + 2) * cell;
  // On the reference's cells, so that a hit at a reference hit falls in its
  // cell and the field is not biased by a fraction of a cell.
  const Eigen::Vector2d lo =
      ((origin - Eigen::Vector2d(margin, margin)) / cell).array().floor().matrix() * cell;
  const auto size = static_cast<std::ptrdiff_t>(std::ceil(2.0 * margin / cell)) + 1;
  const auto log_floor = static_cast<float>(std::log(options.floor));
  std::vector<float> field(static_cast<std::size_t>(size * size), log_floor);
  const std::vector<Eigen::Vector2d> near =
      reference.Within(lo, lo + Eigen::Vector2d(size * cell, size * cell));
  if (near.empty()) return result;
  for (const Eigen::Vector2d& p : near) {
    const auto cx = static_cast<std::ptrdiff_t>(std::floor((p.x() - lo.x()) / cell));
    const auto cy = static_cast<std::ptrdiff_t>(std::floor((p.y() - lo.y()) / cell));
    for (std::ptrdiff_t dy = -kernel; dy <= kernel; ++dy) {
      const std::ptrdiff_t y = cy + dy;
      if (y < 0 || y >= size) continue;
      for (std::ptrdiff_t dx = -kernel; dx <= kernel; ++dx) {
        const std::ptrdiff_t x = cx + dx;
        if (x < 0 || x >= size) continue;
        const Eigen::Vector2d centre = lo + Eigen::Vector2d((x + 0.5) * cell, (y + 0.5) * cell);
        const double d2 = (centre - p).squaredNorm();
        const auto v =
            static_cast<float>(std::log(options.floor + std::exp(-d2 / (2.0 * sigma * sigma))));
        float& f = field[static_cast<std::size_t>(y * size + x)];
        f = std::max(f, v);
      }
    }
  }

  // The hits' cells in the field, turned by theta about the origin.
  std::vector<std::ptrdiff_t> cells(hit_offsets.size());
  const auto place = [&](double theta) {
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    for (std::size_t i = 0; i < hit_offsets.size(); ++i) {
      const Eigen::Vector2d& q = hit_offsets[i];
      const Eigen::Vector2d p =
          origin + Eigen::Vector2d(c * q.x() - s * q.y(), s * q.x() + c * q.y());
      const auto x = static_cast<std::ptrdiff_t>(std::floor((p.x() - lo.x()) / cell));
      const auto y = static_cast<std::ptrdiff_t>(std::floor((p.y() - lo.y()) / cell));
      cells[i] = y * size + x;
    }
  };
  // The overlap at the prior's mean: hits within 2σ of a reference hit (and
  // half a cell, so that a cell right at 2σ counts whatever the rounding).
  place(0.0);
  const double half_cell_past = 2.0 * sigma + 0.5 * cell;
  const auto agree = static_cast<float>(
      std::log(options.floor + std::exp(-half_cell_past * half_cell_past / (2.0 * sigma * sigma))));
  for (const std::ptrdiff_t index : cells) {
    if (field[static_cast<std::size_t>(index)] >= agree) ++result.overlap;
  }
  if (result.overlap < options.min_overlap) return result;

  // Each correction's log posterior.
  const Eigen::Matrix3d information = prior_covariance.inverse();
  struct Candidate {
    Eigen::Vector3d offset;
    double log_posterior;
  };
  std::vector<Candidate> candidates;
  candidates.reserve(static_cast<std::size_t>(2 * nx + 1) * static_cast<std::size_t>(2 * ny + 1) *
                     static_cast<std::size_t>(2 * nt + 1));
  for (int k = -nt; k <= nt; ++k) {
    const double theta = k * options.step_rad;
    place(theta);
    for (int iy = -ny; iy <= ny; ++iy) {
      for (int ix = -nx; ix <= nx; ++ix) {
        const std::ptrdiff_t shift = iy * size + ix;
        double sum = 0.0;
        for (const std::ptrdiff_t index : cells) {
          sum += field[static_cast<std::size_t>(index + shift)];
        }
        const Eigen::Vector3d offset(ix * cell, iy * cell, theta);
        candidates.push_back(
            {offset, sum / options.correlation - 0.5 * offset.dot(information * offset)});
      }
    }
  }

  double best = -std::numeric_limits<double>::infinity();
  for (const Candidate& c : candidates) best = std::max(best, c.log_posterior);
  double total = 0.0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Candidate& c : candidates) {
    const double w = std::exp(c.log_posterior - best);
    total += w;
    mean += w * c.offset;
  }
  mean /= total;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Candidate& c : candidates) {
    const double w = std::exp(c.log_posterior - best);
    const Eigen::Vector3d d = c.offset - mean;
    covariance += w * d * d.transpose();
  }
  result.offset = mean;
  result.covariance = covariance / total;
  result.accepted = true;
  return result;
}

}  // namespace pirouette::localize
