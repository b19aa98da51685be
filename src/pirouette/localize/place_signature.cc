#include "pirouette/localize/place_signature.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <unsupported/Eigen/FFT>

#include "pirouette/core/angle.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::localize {
namespace {

double BinBearing(int bin, int bins) { return (bin + 0.5) * 2.0 * std::numbers::pi / bins; }

double LogScaled(double h) {
  if (std::abs(h) < 1e-30) return 0.0;
  return std::copysign(std::log10(std::abs(h)), h);
}

bool Coloured(const core::ColourClass c) { return c != core::ColourClass::kNone; }

// Whether two colour classes disagree: a hue against no hue, or hues more
// than one class apart. Black, white and grey agree (light and shading move a
// white wall between them), as do neighbouring hues (shading moves a hue by
// a class).
bool Disagree(core::ColourClass a, core::ColourClass b) {
  const int ia = static_cast<int>(a);
  const int ib = static_cast<int>(b);
  const bool hue_a = ia < core::kHueClasses;
  const bool hue_b = ib < core::kHueClasses;
  if (hue_a != hue_b) return true;
  if (!hue_a) return false;
  const int d = std::abs(ia - ib);
  return std::min(d, core::kHueClasses - d) > 1;
}

}  // namespace

std::string_view SignatureKindName(SignatureKind kind) {
  switch (kind) {
    case SignatureKind::kDct:
      return "dct";
    case SignatureKind::kHu:
      return "hu";
    case SignatureKind::kFourier:
      return "fourier";
    case SignatureKind::kColour:
      return "colour";
  }
  return "dct";
}

bool SignatureGivesHeading(SignatureKind kind) {
  return kind == SignatureKind::kFourier || kind == SignatureKind::kColour;
}

std::vector<double> DctSignature(const std::vector<double>& ranges_m, int keep) {
  std::vector<double> c = mapping::Dct(ranges_m);
  c.resize(std::min(c.size(), static_cast<std::size_t>(std::max(keep, 0))));
  return c;
}

std::array<double, 7> RawHuMoments(const std::vector<double>& ranges_m) {
  const int n = static_cast<int>(ranges_m.size());
  // Raw area moments by Green's theorem over the polygon's edges (as OpenCV's
  // contour moments).
  double a00 = 0, a10 = 0, a01 = 0, a20 = 0, a11 = 0, a02 = 0, a30 = 0, a21 = 0, a12 = 0, a03 = 0;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const double x0 = ranges_m[i] * std::cos(BinBearing(i, n));
    const double y0 = ranges_m[i] * std::sin(BinBearing(i, n));
    const double x1 = ranges_m[j] * std::cos(BinBearing(j, n));
    const double y1 = ranges_m[j] * std::sin(BinBearing(j, n));
    const double dxy = x0 * y1 - x1 * y0;
    const double xs = x0 + x1;
    const double ys = y0 + y1;
    a00 += dxy;
    a10 += dxy * xs;
    a01 += dxy * ys;
    a20 += dxy * (x0 * xs + x1 * x1);
    a11 += dxy * (x0 * (ys + y0) + x1 * (ys + y1));
    a02 += dxy * (y0 * ys + y1 * y1);
    a30 += dxy * xs * (x0 * x0 + x1 * x1);
    a03 += dxy * ys * (y0 * y0 + y1 * y1);
    a21 += dxy * (x0 * x0 * (3 * y0 + y1) + 2 * x0 * x1 * ys + x1 * x1 * (y0 + 3 * y1));
    a12 += dxy * (y0 * y0 * (3 * x0 + x1) + 2 * y0 * y1 * xs + y1 * y1 * (x0 + 3 * x1));
  }
  const double m00 = a00 / 2.0;
  std::array<double, 7> hu{};
  if (!(std::abs(m00) > 1e-12)) return hu;
  const double m10 = a10 / 6.0, m01 = a01 / 6.0;
  const double m20 = a20 / 12.0, m11 = a11 / 24.0, m02 = a02 / 12.0;
  const double m30 = a30 / 20.0, m21 = a21 / 60.0, m12 = a12 / 60.0, m03 = a03 / 20.0;
  const double cx = m10 / m00, cy = m01 / m00;
  const double mu20 = m20 - cx * m10, mu11 = m11 - cx * m01, mu02 = m02 - cy * m01;
  const double mu30 = m30 - 3 * cx * m20 + 2 * cx * cx * m10;
  const double mu21 = m21 - 2 * cx * m11 - cy * m20 + 2 * cx * cx * m01;
  const double mu12 = m12 - 2 * cy * m11 - cx * m02 + 2 * cy * cy * m10;
  const double mu03 = m03 - 3 * cy * m02 + 2 * cy * cy * m01;
  const double s2 = m00 * m00, s3 = std::pow(std::abs(m00), 2.5);
  const double n20 = mu20 / s2, n11 = mu11 / s2, n02 = mu02 / s2;
  const double n30 = mu30 / s3, n21 = mu21 / s3, n12 = mu12 / s3, n03 = mu03 / s3;
  const double p = n30 + n12, q = n21 + n03;
  const double a = n30 - 3 * n12, b = 3 * n21 - n03;
  hu[0] = n20 + n02;
  hu[1] = (n20 - n02) * (n20 - n02) + 4 * n11 * n11;
  hu[2] = a * a + b * b;
  hu[3] = p * p + q * q;
  hu[4] = a * p * (p * p - 3 * q * q) + b * q * (3 * p * p - q * q);
  hu[5] = (n20 - n02) * (p * p - q * q) + 4 * n11 * p * q;
  hu[6] = b * p * (p * p - 3 * q * q) - a * q * (3 * p * p - q * q);
  return hu;
}

HuSignature HuMoments(const std::vector<double>& ranges_m) {
  HuSignature out = RawHuMoments(ranges_m);
  for (double& h : out) h = LogScaled(h);
  return out;
}

std::vector<double> FourierSignature(const std::vector<double>& ranges_m, int keep) {
  const std::size_t n = ranges_m.size();
  if (n == 0) return {};
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, ranges_m);
  std::vector<double> out;
  const std::size_t k = std::min(spectrum.size(), static_cast<std::size_t>(std::max(keep, 0)));
  out.reserve(k);
  for (std::size_t i = 0; i < k; ++i) out.push_back(std::abs(spectrum[i]) / static_cast<double>(n));
  return out;
}

ColourSignature MakeColourSignature(const PlaceView& view) {
  ColourSignature s;
  s.fourier = FourierSignature(view.ranges_m);
  if (view.colours.empty()) return s;
  for (const core::ColourClass c : view.colours) {
    if (Coloured(c)) s.histogram[static_cast<std::size_t>(c)] += 1.0;
  }
  for (double& h : s.histogram) h /= static_cast<double>(view.colours.size());
  return s;
}

double SignatureDistance(const std::vector<double>& a, const std::vector<double>& b) {
  assert(a.size() == b.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum);
}

double HuDistance(const HuSignature& a, const HuSignature& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(a[i] - b[i]);
  return sum;
}

double ColourSignatureDistance(const ColourSignature& a, const ColourSignature& b) {
  double l1 = 0.0;
  for (std::size_t i = 0; i < a.histogram.size(); ++i) {
    l1 += std::abs(a.histogram[i] - b.histogram[i]);
  }
  const double mean =
      std::max(a.fourier.empty() ? 0.0 : a.fourier[0], b.fourier.empty() ? 0.0 : b.fourier[0]);
  return SignatureDistance(a.fourier, b.fourier) + kColourHistogramWeight * l1 * mean;
}

Alignment AlignProfiles(const PlaceView& query, const PlaceView& reference, bool use_colour) {
  const int n = static_cast<int>(query.ranges_m.size());
  if (n == 0 || n != static_cast<int>(reference.ranges_m.size())) {
    throw std::invalid_argument(
        "AlignProfiles: the profiles must have the same number of bins, > 0");
  }
  double max_range = 0.0;
  for (int i = 0; i < n; ++i) {
    max_range = std::max({max_range, query.ranges_m[i], reference.ranges_m[i]});
  }
  const double scale = max_range > 0.0 ? 1.0 / (max_range * max_range) : 1.0;
  const bool colour = use_colour && static_cast<int>(query.colours.size()) == n &&
                      static_cast<int>(reference.colours.size()) == n;
  std::vector<double> cost(static_cast<std::size_t>(n));
  for (int s = 0; s < n; ++s) {
    double sum = 0.0;
    int both = 0;
    int differ = 0;
    for (int b = 0; b < n; ++b) {
      const int r = (b + s) % n;
      const double d = query.ranges_m[b] - reference.ranges_m[r];
      sum += d * d;
      if (colour) {
        const core::ColourClass qc = query.colours[b];
        const core::ColourClass rc = reference.colours[r];
        if (Coloured(qc) && Coloured(rc)) {
          ++both;
          differ += Disagree(qc, rc) ? 1 : 0;
        }
      }
    }
    double c = sum * scale / n;
    if (both > 0) c += kColourMismatchWeight * differ / static_cast<double>(both);
    cost[static_cast<std::size_t>(s)] = c;
  }
  const int best = static_cast<int>(std::min_element(cost.begin(), cost.end()) - cost.begin());
  const double c0 = cost[static_cast<std::size_t>((best + n - 1) % n)];
  const double c1 = cost[static_cast<std::size_t>(best)];
  const double c2 = cost[static_cast<std::size_t>((best + 1) % n)];
  const double curvature = c0 - 2.0 * c1 + c2;
  const double offset =
      curvature > 1e-15 ? std::clamp(0.5 * (c0 - c2) / curvature, -0.5, 0.5) : 0.0;
  const double bin_rad = 2.0 * std::numbers::pi / n;
  return {core::NormalizeAngle((best + offset) * bin_rad), c1};
}

PlaceView Reproject(const PlaceView& view, const Eigen::Vector2d& origin_m, double max_range_m) {
  const int n = static_cast<int>(view.ranges_m.size());
  const bool coloured = static_cast<int>(view.colours.size()) == n;
  PlaceView out;
  out.ranges_m.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  if (coloured) out.colours.assign(static_cast<std::size_t>(n), core::ColourClass::kNone);
  const double bins_per_rad = n / (2.0 * std::numbers::pi);
  for (int b = 0; b < n; ++b) {
    const double r = view.ranges_m[b];
    if (!(r < max_range_m * 0.999)) continue;
    const double a = BinBearing(b, n);
    const Eigen::Vector2d p = r * Eigen::Vector2d(std::cos(a), std::sin(a)) - origin_m;
    double bearing = std::atan2(p.y(), p.x());
    if (bearing < 0.0) bearing += 2.0 * std::numbers::pi;
    const int nb = std::clamp(static_cast<int>(bearing * bins_per_rad), 0, n - 1);
    const double range = p.norm();
    if (range < out.ranges_m[nb]) {
      out.ranges_m[nb] = range;
      if (coloured) out.colours[nb] = view.colours[b];
    }
  }
  // Fill short gaps between filled bins; the rest is clear.
  std::vector<int> filled;
  for (int b = 0; b < n; ++b) {
    if (std::isfinite(out.ranges_m[b])) filled.push_back(b);
  }
  std::vector<double> ranges = out.ranges_m;
  std::vector<core::ColourClass> colours = out.colours;
  for (std::size_t i = 0; i < filled.size(); ++i) {
    const int a = filled[i];
    const int b = filled[(i + 1) % filled.size()];
    const int gap = ((b - a) % n + n) % n;
    if (gap <= 1 || gap > kReprojectGapBins + 1) continue;
    for (int k = 1; k < gap; ++k) {
      const int bin = (a + k) % n;
      const double t = static_cast<double>(k) / gap;
      ranges[bin] = (1.0 - t) * out.ranges_m[a] + t * out.ranges_m[b];
      if (coloured) colours[bin] = t < 0.5 ? out.colours[a] : out.colours[b];
    }
  }
  for (double& r : ranges) r = std::isfinite(r) ? std::min(r, max_range_m) : max_range_m;
  out.ranges_m = std::move(ranges);
  out.colours = std::move(colours);
  return out;
}

PoseAlignment AlignPose(const PlaceView& query, const PlaceView& reference, double max_range_m,
                        double search_radius_m, double min_step_m, bool use_colour) {
  PoseAlignment best;
  {
    const Alignment a = AlignProfiles(
        query, Reproject(reference, Eigen::Vector2d::Zero(), max_range_m), use_colour);
    best = {Eigen::Vector2d::Zero(), a.heading_rad, a.cost};
  }
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double step = search_radius_m / 2.0;
  int half = 2;
  while (step >= min_step_m * 0.999 && step > 0.0) {
    const Eigen::Vector2d around = centre;
    for (int i = -half; i <= half; ++i) {
      for (int j = -half; j <= half; ++j) {
        if (i == 0 && j == 0) continue;
        const Eigen::Vector2d o = around + step * Eigen::Vector2d(i, j);
        const Alignment a = AlignProfiles(query, Reproject(reference, o, max_range_m), use_colour);
        if (a.cost < best.cost) best = {o, a.heading_rad, a.cost};
      }
    }
    centre = best.position_m;
    step /= 2.0;
    half = 1;
  }
  return best;
}

}  // namespace pirouette::localize
