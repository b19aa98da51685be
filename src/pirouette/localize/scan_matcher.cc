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

void HitStore::Add(const Eigen::Vector2d& p_map) { cells_.insert(KeyOf(CellOf(p_map))); }

Eigen::Vector2i HitStore::CellOf(const Eigen::Vector2d& p_map) const {
  return {static_cast<int>(std::floor(p_map.x() / cell_m_)),
          static_cast<int>(std::floor(p_map.y() / cell_m_))};
}

std::int64_t HitStore::KeyOf(const Eigen::Vector2i& cell) { return Key(cell.x(), cell.y()); }

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

namespace {

void CheckMatchInputs(const HitStore& reference, const Eigen::Matrix3d& prior_covariance,
                      const ScanMatchOptions& options) {
  options.Check();
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
}

// The search's half-widths: cells in x and y, heading steps.
struct SearchWindow {
  int nx = 0;
  int ny = 0;
  int nt = 0;
};

SearchWindow WindowOf(const Eigen::Matrix3d& prior_covariance, const ScanMatchOptions& options) {
  const auto window = [&](double variance) {
    return std::clamp(options.window_sigmas * std::sqrt(variance), options.min_window_m,
                      options.max_window_m);
  };
  SearchWindow w;
  w.nx = static_cast<int>(std::round(window(prior_covariance(0, 0)) / options.cell_m));
  w.ny = static_cast<int>(std::round(window(prior_covariance(1, 1)) / options.cell_m));
  // Never past a half turn either way.
  w.nt = static_cast<int>(std::min(
      std::ceil(options.window_sigmas * std::sqrt(prior_covariance(2, 2)) / options.step_rad),
      std::floor(std::numbers::pi / options.step_rad)));
  return w;
}

// The agreement of a point with the reference (log(floor + exp(-d²/2σ²)) to
// the nearest reference hit within 3σ), on a square local grid of `size`
// cells from `lo`, on the reference's cells so that a hit at a reference hit
// falls in its cell and the field is not biased by a fraction of a cell.
struct LikelihoodField {
  Eigen::Vector2d lo;
  std::ptrdiff_t size = 0;
  std::vector<float> values;  // row-major
  bool empty = true;          // no reference hit in reach
};

LikelihoodField FieldAround(const HitStore& reference, const Eigen::Vector2d& origin,
                            const std::vector<Eigen::Vector2d>& hit_offsets,
                            const SearchWindow& window, const ScanMatchOptions& options) {
  const double cell = options.cell_m;
  const double sigma = options.sigma_m;
  double reach = 0.0;
  for (const Eigen::Vector2d& q : hit_offsets) reach = std::max(reach, q.norm());
  const int kernel = static_cast<int>(std::ceil(3.0 * sigma / cell));
  const double margin = reach + std::max(window.nx, window.ny) * cell + (kernel + 2) * cell;
  LikelihoodField field;
  field.lo = ((origin - Eigen::Vector2d(margin, margin)) / cell).array().floor().matrix() * cell;
  field.size = static_cast<std::ptrdiff_t>(std::ceil(2.0 * margin / cell)) + 1;
  const std::ptrdiff_t size = field.size;
  const Eigen::Vector2d& lo = field.lo;
  field.values.assign(static_cast<std::size_t>(size * size),
                      static_cast<float>(std::log(options.floor)));
  const std::vector<Eigen::Vector2d> near =
      reference.Within(lo, lo + Eigen::Vector2d(size * cell, size * cell));
  field.empty = near.empty();
  // The reference's points are cell centres on the field's own lattice (lo
  // is a whole number of cells), so a cell's agreement with a point depends
  // only on how many cells apart they are: one table for every point, not a
  // log and an exp a cell and point (which took most of a match's time).
  const std::ptrdiff_t span = 2 * kernel + 1;
  std::vector<float> table(static_cast<std::size_t>(span * span));
  for (std::ptrdiff_t dy = -kernel; dy <= kernel; ++dy) {
    for (std::ptrdiff_t dx = -kernel; dx <= kernel; ++dx) {
      const double d2 = static_cast<double>(dx * dx + dy * dy) * cell * cell;
      table[static_cast<std::size_t>((dy + kernel) * span + dx + kernel)] =
          static_cast<float>(std::log(options.floor + std::exp(-d2 / (2.0 * sigma * sigma))));
    }
  }
  for (const Eigen::Vector2d& p : near) {
    const auto cx = static_cast<std::ptrdiff_t>(std::floor((p.x() - lo.x()) / cell));
    const auto cy = static_cast<std::ptrdiff_t>(std::floor((p.y() - lo.y()) / cell));
    for (std::ptrdiff_t dy = -kernel; dy <= kernel; ++dy) {
      const std::ptrdiff_t y = cy + dy;
      if (y < 0 || y >= size) continue;
      const float* row = &table[static_cast<std::size_t>((dy + kernel) * span + kernel)];
      for (std::ptrdiff_t dx = -kernel; dx <= kernel; ++dx) {
        const std::ptrdiff_t x = cx + dx;
        if (x < 0 || x >= size) continue;
        float& f = field.values[static_cast<std::size_t>(y * size + x)];
        f = std::max(f, row[dx]);
      }
    }
  }
  return field;
}

// The hits' cells in the field, turned by theta about the origin.
void PlaceHits(const LikelihoodField& field, const Eigen::Vector2d& origin,
               const std::vector<Eigen::Vector2d>& hit_offsets, double cell, double theta,
               std::vector<std::ptrdiff_t>& cells) {
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  for (std::size_t i = 0; i < hit_offsets.size(); ++i) {
    const Eigen::Vector2d& q = hit_offsets[i];
    const Eigen::Vector2d p =
        origin + Eigen::Vector2d(c * q.x() - s * q.y(), s * q.x() + c * q.y());
    const auto x = static_cast<std::ptrdiff_t>(std::floor((p.x() - field.lo.x()) / cell));
    const auto y = static_cast<std::ptrdiff_t>(std::floor((p.y() - field.lo.y()) / cell));
    cells[i] = y * field.size + x;
  }
}

// The hits (at `cells`) within 2σ of a reference hit, and half a cell, so that
// a cell right at 2σ counts whatever the rounding.
int Overlap(const LikelihoodField& field, const std::vector<std::ptrdiff_t>& cells,
            const ScanMatchOptions& options) {
  const double sigma = options.sigma_m;
  const double half_cell_past = 2.0 * sigma + 0.5 * options.cell_m;
  const auto agree = static_cast<float>(
      std::log(options.floor + std::exp(-half_cell_past * half_cell_past / (2.0 * sigma * sigma))));
  int overlap = 0;
  for (const std::ptrdiff_t index : cells) {
    if (field.values[static_cast<std::size_t>(index)] >= agree) ++overlap;
  }
  return overlap;
}

struct Candidate {
  Eigen::Vector3d offset;
  double log_likelihood;  // the hits' summed agreement over options.correlation
  double log_prior;       // less the prior's Mahalanobis term
};

// Every correction of the window with its log posterior: the hits' summed
// agreement over options.correlation, less the prior's Mahalanobis term.
std::vector<Candidate> ScoreCandidates(const LikelihoodField& field, const Eigen::Vector2d& origin,
                                       const std::vector<Eigen::Vector2d>& hit_offsets,
                                       const SearchWindow& w,
                                       const Eigen::Matrix3d& prior_covariance,
                                       const ScanMatchOptions& options) {
  const double cell = options.cell_m;
  const Eigen::Matrix3d information = prior_covariance.inverse();
  std::vector<std::ptrdiff_t> cells(hit_offsets.size());
  std::vector<Candidate> candidates;
  candidates.reserve(static_cast<std::size_t>(2 * w.nx + 1) *
                     static_cast<std::size_t>(2 * w.ny + 1) *
                     static_cast<std::size_t>(2 * w.nt + 1));
  for (int k = -w.nt; k <= w.nt; ++k) {
    const double theta = k * options.step_rad;
    PlaceHits(field, origin, hit_offsets, cell, theta, cells);
    for (int iy = -w.ny; iy <= w.ny; ++iy) {
      for (int ix = -w.nx; ix <= w.nx; ++ix) {
        const std::ptrdiff_t shift = iy * field.size + ix;
        double sum = 0.0;
        for (const std::ptrdiff_t index : cells) {
          sum += field.values[static_cast<std::size_t>(index + shift)];
        }
        const Eigen::Vector3d offset(ix * cell, iy * cell, theta);
        candidates.push_back(
            {offset, sum / options.correlation, -0.5 * offset.dot(information * offset)});
      }
    }
  }
  return candidates;
}

// The mean and covariance over the candidates of the posterior (with_prior)
// or of the likelihood alone (Olson 2009, as Karto computes the match's
// covariance from its response surface); `best` is set to the most likely
// candidate's offset.
void Moments(const std::vector<Candidate>& candidates, bool with_prior, Eigen::Vector3d& mean,
             Eigen::Matrix3d& covariance, Eigen::Vector3d& best) {
  const auto score = [with_prior](const Candidate& c) {
    return with_prior ? c.log_likelihood + c.log_prior : c.log_likelihood;
  };
  double top = -std::numeric_limits<double>::infinity();
  for (const Candidate& c : candidates) {
    if (score(c) > top) {
      top = score(c);
      best = c.offset;
    }
  }
  double total = 0.0;
  mean = Eigen::Vector3d::Zero();
  std::vector<double> weights(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const double w = std::exp(score(candidates[i]) - top);
    weights[i] = w;
    total += w;
    mean += w * candidates[i].offset;
  }
  mean /= total;
  covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Eigen::Vector3d d = candidates[i].offset - mean;
    covariance += weights[i] * d * d.transpose();
  }
  covariance /= total;
}

}  // namespace

ScanMatch MatchScan(const HitStore& reference, const Eigen::Vector2d& origin,
                    const std::vector<Eigen::Vector2d>& hit_offsets,
                    const Eigen::Matrix3d& prior_covariance, const ScanMatchOptions& options) {
  CheckMatchInputs(reference, prior_covariance, options);
  ScanMatch result;
  result.covariance = prior_covariance;
  if (hit_offsets.empty() || reference.size() == 0) return result;
  const SearchWindow window = WindowOf(prior_covariance, options);
  const LikelihoodField field = FieldAround(reference, origin, hit_offsets, window, options);
  if (field.empty) return result;
  std::vector<std::ptrdiff_t> cells(hit_offsets.size());
  PlaceHits(field, origin, hit_offsets, options.cell_m, 0.0, cells);
  result.overlap = Overlap(field, cells, options);
  if (result.overlap < options.min_overlap) return result;
  const std::vector<Candidate> candidates =
      ScoreCandidates(field, origin, hit_offsets, window, prior_covariance, options);
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  Moments(candidates, true, result.offset, result.covariance, best);
  Moments(candidates, false, result.likelihood_offset, result.likelihood_covariance, best);
  // The overlap at the likelihood's best: its heading, then its shift in cells.
  PlaceHits(field, origin, hit_offsets, options.cell_m, best.z(), cells);
  const std::ptrdiff_t shift =
      static_cast<std::ptrdiff_t>(std::lround(best.y() / options.cell_m)) * field.size +
      static_cast<std::ptrdiff_t>(std::lround(best.x() / options.cell_m));
  for (std::ptrdiff_t& c : cells) c += shift;
  result.response =
      static_cast<double>(Overlap(field, cells, options)) / static_cast<double>(hit_offsets.size());
  result.accepted = true;
  return result;
}

}  // namespace pirouette::localize
