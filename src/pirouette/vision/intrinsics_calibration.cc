#include "pirouette/vision/intrinsics_calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <stdexcept>

namespace pirouette::vision {
namespace {

struct Solution {
  cv::Mat camera_matrix;
  cv::Mat distortion;
  double rms_px = 0.0;
  std::vector<double> view_rms_px;
};

Solution Solve(const std::vector<const ChessboardView*>& views, cv::Size image_size,
               const IntrinsicsCalibrationOptions& options) {
  const std::vector<cv::Point3f> board = ChessboardObjectPoints(options.pattern, options.square_m);
  std::vector<std::vector<cv::Point3f>> object_points(views.size(), board);
  std::vector<std::vector<cv::Point2f>> image_points;
  image_points.reserve(views.size());
  for (const ChessboardView* view : views) image_points.push_back(view->corners);
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-12);
  const bool fisheye = options.model == camera::Distortion::Model::kEquidistant;
  Solution s;
  std::vector<cv::Mat> rvecs;
  std::vector<cv::Mat> tvecs;
  if (fisheye) {
    s.distortion = cv::Mat::zeros(1, 4, CV_64F);
    s.camera_matrix = cv::Mat::eye(3, 3, CV_64F);
    s.rms_px = cv::fisheye::calibrate(
        object_points, image_points, image_size, s.camera_matrix, s.distortion, rvecs, tvecs,
        cv::fisheye::CALIB_RECOMPUTE_EXTRINSIC | cv::fisheye::CALIB_FIX_SKEW, criteria);
  } else {
    int flags = 0;
    if (options.model == camera::Distortion::Model::kRationalPolynomial) {
      flags |= cv::CALIB_RATIONAL_MODEL;
      s.distortion = cv::Mat::zeros(1, 8, CV_64F);
    } else {
      if (options.radial_coefficients == 2) flags |= cv::CALIB_FIX_K3;
      s.distortion = cv::Mat::zeros(1, 5, CV_64F);
    }
    s.rms_px = cv::calibrateCamera(object_points, image_points, image_size, s.camera_matrix,
                                   s.distortion, rvecs, tvecs, flags, criteria);
  }
  for (std::size_t i = 0; i < views.size(); ++i) {
    std::vector<cv::Point2f> projected;
    if (fisheye) {
      cv::fisheye::projectPoints(board, projected, rvecs[i], tvecs[i], s.camera_matrix,
                                 s.distortion);
    } else {
      cv::projectPoints(board, rvecs[i], tvecs[i], s.camera_matrix, s.distortion, projected);
    }
    double sum = 0.0;
    for (std::size_t j = 0; j < projected.size(); ++j) {
      const cv::Point2f d = projected[j] - image_points[i][j];
      sum += d.dot(d);
    }
    s.view_rms_px.push_back(std::sqrt(sum / static_cast<double>(projected.size())));
  }
  return s;
}

double Median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

std::vector<cv::Point3f> ChessboardObjectPoints(cv::Size pattern, double square_m) {
  std::vector<cv::Point3f> points;
  points.reserve(static_cast<std::size_t>(pattern.area()));
  for (int r = 0; r < pattern.height; ++r) {
    for (int c = 0; c < pattern.width; ++c) {
      points.emplace_back(static_cast<float>((c - (pattern.width - 1) / 2.0) * square_m),
                          static_cast<float>((r - (pattern.height - 1) / 2.0) * square_m), 0.0f);
    }
  }
  return points;
}

IntrinsicsCalibration CalibrateIntrinsics(const std::vector<ChessboardView>& views,
                                          cv::Size image_size,
                                          const IntrinsicsCalibrationOptions& options) {
  if (options.pattern.width < 2 || options.pattern.height < 2 || !(options.square_m > 0.0) ||
      (options.radial_coefficients != 2 && options.radial_coefficients != 3) ||
      image_size.width <= 0 || image_size.height <= 0) {
    throw std::invalid_argument("CalibrateIntrinsics: bad pattern, square, image size or options");
  }
  if (static_cast<int>(views.size()) < kMinCalibrationViews) {
    throw std::invalid_argument("CalibrateIntrinsics: too few views");
  }
  std::vector<const ChessboardView*> kept;
  for (const ChessboardView& view : views) {
    if (view.corners.size() != static_cast<std::size_t>(options.pattern.area())) {
      throw std::invalid_argument("CalibrateIntrinsics: view '" + view.name +
                                  "' has the wrong number of corners");
    }
    kept.push_back(&view);
  }

  IntrinsicsCalibration result;
  Solution s = Solve(kept, image_size, options);
  // Drop the views far above the rest, worst first, keeping the minimum.
  const double limit =
      std::max(options.outlier_factor * Median(s.view_rms_px), options.outlier_floor_px);
  std::vector<std::size_t> order(kept.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&s](std::size_t a, std::size_t b) { return s.view_rms_px[a] > s.view_rms_px[b]; });
  std::vector<bool> drop(kept.size(), false);
  std::size_t left = kept.size();
  for (const std::size_t i : order) {
    if (!(s.view_rms_px[i] > limit) || left <= static_cast<std::size_t>(kMinCalibrationViews)) {
      break;
    }
    drop[i] = true;
    --left;
  }
  if (left < kept.size()) {
    std::vector<const ChessboardView*> remaining;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (drop[i]) {
        result.dropped.push_back({kept[i]->name, s.view_rms_px[i]});
      } else {
        remaining.push_back(kept[i]);
      }
    }
    kept = std::move(remaining);
    s = Solve(kept, image_size, options);
  }

  const cv::Mat& k = s.camera_matrix;
  result.intrinsics = {k.at<double>(0, 0), k.at<double>(1, 1), k.at<double>(0, 2),
                       k.at<double>(1, 2)};
  const cv::Mat d = s.distortion.reshape(1, 1);
  // OpenCV may return more coefficients than the model has (with zeros for
  // the thin prism and tilt terms it did not fit): the model's come first.
  std::vector<double> coefficients(d.begin<double>(), d.end<double>());
  camera::Distortion of_model;
  of_model.model = options.model;
  const std::size_t count = of_model.Coefficients().size();
  if (coefficients.size() < count) {
    throw std::logic_error("CalibrateIntrinsics: too few coefficients");
  }
  coefficients.resize(count);
  result.distortion = *camera::Distortion::FromCoefficients(options.model, coefficients);
  result.rms_px = s.rms_px;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    result.used.push_back({kept[i]->name, s.view_rms_px[i]});
  }
  return result;
}

}  // namespace pirouette::vision
