#include "pirouette/camera/distortion.h"

#include <Eigen/LU>
#include <cmath>
#include <numbers>

namespace pirouette::camera {
namespace {

// The fisheye's search for θ scans [0, 90°) in this many steps for the first
// one past θd, then refines inside it: a model that turns back within one
// step (0.35°) would be missed, no calibration of a real lens does.
constexpr int kThetaScanSteps = 256;
// Undistort's answers satisfy Distort(answer) = distorted to this, in
// normalised units (about 1e-10 px); Newton reaches it in a few steps.
constexpr double kUndistortTolerance = 1e-12;

Eigen::Vector2d DistortPlumbBob(const Distortion& d, const Eigen::Vector2d& undistorted) {
  const double x = undistorted.x();
  const double y = undistorted.y();
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  return {x * radial + 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x),
          y * radial + d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y};
}

Eigen::Vector2d UndistortPlumbBob(const Distortion& d, const Eigen::Vector2d& distorted) {
  // Newton's method on Distort(p) - distorted, from p = distorted.
  Eigen::Vector2d p = distorted;
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector2d residual = DistortPlumbBob(d, p) - distorted;
    if (residual.norm() < 1e-14) break;
    const double x = p.x();
    const double y = p.y();
    const double r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
    const double dradial_dr2 = d.k1 + r2 * (2.0 * d.k2 + 3.0 * r2 * d.k3);
    Eigen::Matrix2d jacobian;
    jacobian(0, 0) = radial + 2.0 * x * x * dradial_dr2 + 2.0 * d.p1 * y + 6.0 * d.p2 * x;
    jacobian(0, 1) = 2.0 * x * y * dradial_dr2 + 2.0 * d.p1 * x + 2.0 * d.p2 * y;
    jacobian(1, 0) = 2.0 * x * y * dradial_dr2 + 2.0 * d.p1 * x + 2.0 * d.p2 * y;
    jacobian(1, 1) = radial + 2.0 * y * y * dradial_dr2 + 6.0 * d.p1 * y + 2.0 * d.p2 * x;
    p -= jacobian.inverse() * residual;
  }
  return p;
}

// OpenCV's cv::projectPoints with (k1 k2 p1 p2 k3 k4 k5 k6), no thin prism.
Eigen::Vector2d DistortRational(const Distortion& d, const Eigen::Vector2d& undistorted) {
  const double x = undistorted.x();
  const double y = undistorted.y();
  const double r2 = x * x + y * y;
  const double numerator = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  const double denominator = 1.0 + r2 * (d.k4 + r2 * (d.k5 + r2 * d.k6));
  const double radial = numerator / denominator;
  return {x * radial + 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x),
          y * radial + d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y};
}

Eigen::Matrix2d RationalJacobian(const Distortion& d, const Eigen::Vector2d& p) {
  const double x = p.x();
  const double y = p.y();
  const double r2 = x * x + y * y;
  const double n = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  const double dn = d.k1 + r2 * (2.0 * d.k2 + 3.0 * r2 * d.k3);
  const double m = 1.0 + r2 * (d.k4 + r2 * (d.k5 + r2 * d.k6));
  const double dm = d.k4 + r2 * (2.0 * d.k5 + 3.0 * r2 * d.k6);
  const double radial = n / m;
  const double dradial_dr2 = (dn * m - n * dm) / (m * m);
  Eigen::Matrix2d jacobian;
  jacobian(0, 0) = radial + 2.0 * x * x * dradial_dr2 + 2.0 * d.p1 * y + 6.0 * d.p2 * x;
  jacobian(0, 1) = 2.0 * x * y * dradial_dr2 + 2.0 * d.p1 * x + 2.0 * d.p2 * y;
  jacobian(1, 0) = jacobian(0, 1);
  jacobian(1, 1) = radial + 2.0 * y * y * dradial_dr2 + 6.0 * d.p1 * y + 2.0 * d.p2 * x;
  return jacobian;
}

// Newton's method from p = distorted, each step halved until the residual
// shrinks (so a step never jumps past the nearest inverse).
std::optional<Eigen::Vector2d> UndistortRational(const Distortion& d,
                                                 const Eigen::Vector2d& distorted) {
  Eigen::Vector2d p = distorted;
  double error = (DistortRational(d, p) - distorted).norm();
  for (int i = 0; i < 100 && error >= 1e-14; ++i) {
    const Eigen::Vector2d residual = DistortRational(d, p) - distorted;
    const Eigen::FullPivLU<Eigen::Matrix2d> lu(RationalJacobian(d, p));
    if (!lu.isInvertible()) break;
    const Eigen::Vector2d step = lu.solve(residual);
    double scale = 1.0;
    bool improved = false;
    for (int halving = 0; halving < 40 && !improved; ++halving, scale *= 0.5) {
      const Eigen::Vector2d candidate = p - scale * step;
      const double candidate_error = (DistortRational(d, candidate) - distorted).norm();
      if (candidate_error < error) {
        p = candidate;
        error = candidate_error;
        improved = true;
      }
    }
    if (!improved) break;
  }
  if (!(error < kUndistortTolerance)) return std::nullopt;
  return p;
}

// θd(θ) of the fisheye model and its derivative.
double ThetaD(const Distortion& d, double theta) {
  const double t2 = theta * theta;
  return theta * (1.0 + t2 * (d.k1 + t2 * (d.k2 + t2 * (d.k3 + t2 * d.k4))));
}

double ThetaDSlope(const Distortion& d, double theta) {
  const double t2 = theta * theta;
  return 1.0 + t2 * (3.0 * d.k1 + t2 * (5.0 * d.k2 + t2 * (7.0 * d.k3 + t2 * 9.0 * d.k4)));
}

// cv::fisheye::projectPoints' distortion of a normalised point.
Eigen::Vector2d DistortEquidistant(const Distortion& d, const Eigen::Vector2d& undistorted) {
  const double r = undistorted.norm();
  if (!(r > 1e-8)) return undistorted;
  return (ThetaD(d, std::atan(r)) / r) * undistorted;
}

// The angle θ in [0, 90°) off the axis whose θd is `theta_d`, on the part of
// the model that increases from θ = 0; nullopt beyond it.
std::optional<double> EquidistantTheta(const Distortion& d, double theta_d) {
  const double step = (std::numbers::pi / 2.0) / kThetaScanSteps;
  double low = 0.0;
  double value_low = 0.0;
  for (int i = 1; i <= kThetaScanSteps; ++i) {
    const double high = i * step;
    const double value_high = ThetaD(d, high);
    if (!(value_high > value_low)) return std::nullopt;  // the model turns back first
    if (value_high >= theta_d) {
      // Newton's method kept inside [low, high] by bisection.
      double theta = low + (high - low) * (theta_d - value_low) / (value_high - value_low);
      double a = low;
      double b = high;
      for (int k = 0; k < 100; ++k) {
        const double f = ThetaD(d, theta) - theta_d;
        if (f == 0.0) break;
        (f < 0.0 ? a : b) = theta;
        const double slope = ThetaDSlope(d, theta);
        double next = slope > 0.0 ? theta - f / slope : 0.5 * (a + b);
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (std::abs(next - theta) < 1e-16) break;
        theta = next;
      }
      if (!(theta < std::numbers::pi / 2.0)) return std::nullopt;
      return theta;
    }
    low = high;
    value_low = value_high;
  }
  return std::nullopt;
}

}  // namespace

std::optional<Distortion> Distortion::FromCoefficients(Model model,
                                                       std::span<const double> coefficients) {
  Distortion d;
  d.model = model;
  const auto c = [&](std::size_t i) { return coefficients[i]; };
  switch (model) {
    case Model::kPlumbBob:
      if (coefficients.size() != 5) return std::nullopt;
      d.k1 = c(0), d.k2 = c(1), d.p1 = c(2), d.p2 = c(3), d.k3 = c(4);
      return d;
    case Model::kRationalPolynomial:
      if (coefficients.size() != 8) return std::nullopt;
      d.k1 = c(0), d.k2 = c(1), d.p1 = c(2), d.p2 = c(3), d.k3 = c(4);
      d.k4 = c(5), d.k5 = c(6), d.k6 = c(7);
      return d;
    case Model::kEquidistant:
      if (coefficients.size() != 4) return std::nullopt;
      d.k1 = c(0), d.k2 = c(1), d.k3 = c(2), d.k4 = c(3);
      return d;
  }
  return std::nullopt;
}

std::vector<double> Distortion::Coefficients() const {
  switch (model) {
    case Model::kPlumbBob:
      return {k1, k2, p1, p2, k3};
    case Model::kRationalPolynomial:
      return {k1, k2, p1, p2, k3, k4, k5, k6};
    case Model::kEquidistant:
      return {k1, k2, k3, k4};
  }
  return {};
}

Eigen::Vector2d Distortion::Distort(const Eigen::Vector2d& undistorted) const {
  switch (model) {
    case Model::kPlumbBob:
      return DistortPlumbBob(*this, undistorted);
    case Model::kRationalPolynomial:
      return DistortRational(*this, undistorted);
    case Model::kEquidistant:
      return DistortEquidistant(*this, undistorted);
  }
  return undistorted;
}

std::optional<Eigen::Vector2d> Distortion::Undistort(const Eigen::Vector2d& distorted) const {
  switch (model) {
    case Model::kPlumbBob:
      return UndistortPlumbBob(*this, distorted);
    case Model::kRationalPolynomial:
      return UndistortRational(*this, distorted);
    case Model::kEquidistant: {
      const double theta_d = distorted.norm();
      if (!(theta_d > 1e-8)) return distorted;
      const std::optional<double> theta = EquidistantTheta(*this, theta_d);
      if (!theta) return std::nullopt;
      return (std::tan(*theta) / theta_d) * distorted;
    }
  }
  return std::nullopt;
}

std::optional<Eigen::Vector3d> Distortion::Ray(const Eigen::Vector2d& distorted) const {
  if (model == Model::kEquidistant) {
    const double theta_d = distorted.norm();
    if (!(theta_d > 1e-8)) return Eigen::Vector3d(distorted.x(), distorted.y(), 1.0).normalized();
    const std::optional<double> theta = EquidistantTheta(*this, theta_d);
    if (!theta) return std::nullopt;
    const Eigen::Vector2d across = (std::sin(*theta) / theta_d) * distorted;
    return Eigen::Vector3d(across.x(), across.y(), std::cos(*theta));
  }
  const std::optional<Eigen::Vector2d> undistorted = Undistort(distorted);
  if (!undistorted) return std::nullopt;
  return Eigen::Vector3d(undistorted->x(), undistorted->y(), 1.0).normalized();
}

std::string_view ModelName(Distortion::Model model) {
  switch (model) {
    case Distortion::Model::kPlumbBob:
      return "plumb_bob";
    case Distortion::Model::kRationalPolynomial:
      return "rational_polynomial";
    case Distortion::Model::kEquidistant:
      return "equidistant";
  }
  return "";
}

std::optional<Distortion::Model> ModelNamed(std::string_view name) {
  for (const Distortion::Model model :
       {Distortion::Model::kPlumbBob, Distortion::Model::kRationalPolynomial,
        Distortion::Model::kEquidistant}) {
    if (ModelName(model) == name) return model;
  }
  return std::nullopt;
}

}  // namespace pirouette::camera
