#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/vision/vertical_direction_field.h"

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
// With `vertical` (the camera's VerticalDirectionField, the mask's size), a
// column whose edge pixel has pixels that are not floor for 3 rows or more
// below it, down the world's vertical through it, is kClear at the edge's
// range (seen free to there, nothing said beyond) instead of a hit, and the
// foot of that walk (where it meets the floor, read half-way like an edge)
// is added to the profile's `feet` as a hit when within max_range_m: the
// column met what ends its floor above where that stands on the floor, so
// the edge's floor point is not where it stands, the foot is (Taylor, Geva
// & Boles 2005, §5.2: in a tilted camera an obstacle's vertical side slants
// across the columns). Past a wall's end the edge's point lies on open
// floor: a phantom hit, which in a maze's corridor closes the way round the
// wall. The walk allows a pixel either side of the vertical, so a wall
// seen nearly edge-on (its base line within half a pixel a row of the
// vertical in the image) looks the same in the mask: its column reads clear
// to the edge, and the walk's foot is a nearer point of the same wall.
// Pure: the same mask gives the same profile.
core::ObstacleProfile ExtractProfile(const cv::Mat1b& floor_mask,
                                     const camera::InversePerspectiveMap& ipm, double max_range_m,
                                     const cv::Mat1b& unresolved = cv::Mat1b(),
                                     const VerticalDirectionField* vertical = nullptr);

// ExtractProfile for a stream of masks of one camera: the same profiles, with
// what depends on the camera and the range alone found once. For each column
// and each row a search may start at, the first row up from it whose floor
// point is missing or beyond max_range_m is kept, so that a mask costs a scan
// of its rows from the bottom, all columns at once, until each column has met
// the floor's edge (or that row), and at most three floor points a column,
// instead of a floor point and a range for every floor pixel.
class ProfileExtractor {
 public:
  ProfileExtractor(const camera::InversePerspectiveMap& ipm, double max_range_m,
                   std::optional<VerticalDirectionField> vertical = std::nullopt);

  double max_range_m() const { return max_range_m_; }
  const std::optional<VerticalDirectionField>& vertical() const { return vertical_; }
  // ExtractProfile(floor_mask, ipm, max_range_m, unresolved, vertical).
  core::ObstacleProfile Extract(const cv::Mat1b& floor_mask,
                                const cv::Mat1b& unresolved = cv::Mat1b()) const;

 private:
  core::RangeReading ColumnReading(const cv::Mat1b& mask, const cv::Mat1b& unresolved, int u,
                                   int start, int fail, int end,
                                   std::vector<core::RangeReading>& feet) const;

  camera::InversePerspectiveMap ipm_;
  double max_range_m_;
  std::optional<VerticalDirectionField> vertical_;
  // Per column and start row bottom - k (k < kBlindSearchRows): -2 if that row
  // itself fails (no floor point or beyond range), else the first failing row
  // above it (-1 if none).
  std::vector<std::array<int, kBlindSearchRows>> first_fail_;
};

}  // namespace pirouette::vision
