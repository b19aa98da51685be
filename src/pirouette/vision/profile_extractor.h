#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <vector>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/core/obstacle_profile.h"

namespace pirouette::vision {

// The rows at the bottom of a column that are searched for floor before the
// column is called blind: a segmenter may leave the image's last rows out.
inline constexpr int kBlindSearchRows = 3;

// The obstacle profile of one frame (Taylor, Geva & Boles 2005, §3): the
// floor's edge in each image column read as a range through the inverse
// perspective mapping.
//
// For each column of `floor_mask` (255 floor, 0 not, the IPM's size), from
// the lowest floor pixel among the bottom kBlindSearchRows rows upward, the
// first pixel that is not floor ends the floor. The edge lies between that
// pixel's centre and the one below; it is read half-way, as the mid-point of
// the two pixels' floor points (the floor point below when the pixel above
// sees no floor). In the robot frame, the reading's bearing is atan2(y, x) of
// that point and its range the point's distance from the robot's centre:
//   kHit   when that range is at most max_range_m;
//   kClear when it is farther, or when the floor goes on past max_range_m (or
//          past the horizon, or to the top row) with no edge: range_m =
//          max_range_m, bearing of the first floor point beyond max_range_m;
//   kBlind when the bottom kBlindSearchRows rows hold no floor: range and
//          bearing of the bottom pixel's floor point.
// Where `unresolved` (empty, or the mask's size: FloorSegmenter::Unresolved)
// marks the pixel that ends the floor, the floor may go on there unresolved:
// the reading is kClear at the edge's range (less than max_range_m), seen
// free to there and not beyond, instead of kHit.
// Pure: the same mask gives the same profile.
core::ObstacleProfile ExtractProfile(const cv::Mat1b& floor_mask,
                                     const camera::InversePerspectiveMap& ipm, double max_range_m,
                                     const cv::Mat1b& unresolved = cv::Mat1b());

// ExtractProfile for a stream of masks of one camera: the same profiles, with
// what depends on the camera and the range alone found once. For each column
// and each row a search may start at, the first row up from it whose floor
// point is missing or beyond max_range_m is kept, so that a mask costs a scan
// of its rows from the bottom, all columns at once, until each column has met
// the floor's edge (or that row), and at most three floor points a column,
// instead of a floor point and a range for every floor pixel.
class ProfileExtractor {
 public:
  ProfileExtractor(const camera::InversePerspectiveMap& ipm, double max_range_m);

  double max_range_m() const { return max_range_m_; }
  // ExtractProfile(floor_mask, ipm, max_range_m, unresolved).
  core::ObstacleProfile Extract(const cv::Mat1b& floor_mask,
                                const cv::Mat1b& unresolved = cv::Mat1b()) const;

 private:
  core::RangeReading ColumnReading(const cv::Mat1b& mask, const cv::Mat1b& unresolved, int u,
                                   int start, int fail, int end) const;

  camera::InversePerspectiveMap ipm_;
  double max_range_m_;
  // Per column and start row bottom - k (k < kBlindSearchRows): -2 if that row
  // itself fails (no floor point or beyond range), else the first failing row
  // above it (-1 if none).
  std::vector<std::array<int, kBlindSearchRows>> first_fail_;
};

}  // namespace pirouette::vision
