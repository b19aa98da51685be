#include "pirouette/vision/profile_extractor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/angle.h"

namespace pirouette::vision {
namespace {

// The paper's camera (worlds/yujin.yaml).
camera::CameraModel PaperCamera() {
  return camera::CameraModel("yujin", 320, 240, {277.13, 277.13, 159.5, 119.5},
                             {-0.20, 0.05, 0.0, 0.0, 0.0}, {0.11, core::DegToRad(30.0), 0.03},
                             {{0.35, 0.30, 0.40}});
}

TEST(ProfileExtractorTest, FloorBelowARowReadsTheRowsHalfWayPoint) {
  const camera::CameraModel camera = PaperCamera();
  const camera::InversePerspectiveMap ipm(camera);
  cv::Mat1b mask(240, 320, uchar{0});
  mask.rowRange(151, 240).setTo(255);  // rows 151.. floor: the edge at 150.5
  const core::ObstacleProfile profile = ExtractProfile(mask, ipm, 10.0);
  ASSERT_EQ(profile.readings.size(), 320u);
  EXPECT_EQ(profile.max_range_m, 10.0);
  for (int u = 0; u < 320; ++u) {
    const Eigen::Vector2d p = *camera.FloorPoint({u, 150.5});
    const core::RangeReading& r = profile.readings[static_cast<std::size_t>(u)];
    EXPECT_EQ(r.kind, core::ReadingKind::kHit);
    EXPECT_NEAR(r.range_m, p.norm(), 2e-4) << u;
    EXPECT_NEAR(r.bearing_rad, std::atan2(p.y(), p.x()), 1e-3) << u;
  }
  // Left to right, bearings decrease.
  EXPECT_GT(profile.readings.front().bearing_rad, 0.0);
  EXPECT_LT(profile.readings.back().bearing_rad, 0.0);
}

// A straight obstacle base across the view, 0.3 m ahead: each column reads
// 0.3 / cos(bearing), to within the half pixel a binary mask can resolve.
TEST(ProfileExtractorTest, StraightEdgeGivesTheAnalyticRanges) {
  const camera::CameraModel camera = PaperCamera();
  const camera::InversePerspectiveMap ipm(camera);
  constexpr double kAhead = 0.3;
  cv::Mat1b mask(240, 320, uchar{0});
  for (int v = 0; v < 240; ++v) {
    for (int u = 0; u < 320; ++u) {
      const std::optional<Eigen::Vector2f> p = ipm.At(u, v);
      if (p && p->x() < kAhead) mask(v, u) = 255;
    }
  }
  const double half_pixel = 0.5 * camera::RangeErrorAt(camera, kAhead)->worst_m();
  const core::ObstacleProfile profile = ExtractProfile(mask, ipm, 0.5);
  for (std::size_t u = 0; u < profile.readings.size(); ++u) {
    const core::RangeReading& r = profile.readings[u];
    ASSERT_EQ(r.kind, core::ReadingKind::kHit) << u;
    // Off-centre columns see the floor obliquely: allow twice the centre's half pixel.
    EXPECT_NEAR(r.range_m, kAhead / std::cos(r.bearing_rad), 2.0 * half_pixel) << u;
  }
  EXPECT_NEAR(profile.readings[160].range_m, kAhead, half_pixel);
}

TEST(ProfileExtractorTest, NoFloorIsBlindAndAllFloorIsClear) {
  const camera::CameraModel camera = PaperCamera();
  const camera::InversePerspectiveMap ipm(camera);
  const core::ObstacleProfile blind = ExtractProfile(cv::Mat1b(240, 320, uchar{0}), ipm, 0.4);
  for (int u = 0; u < 320; ++u) {
    const core::RangeReading& r = blind.readings[static_cast<std::size_t>(u)];
    EXPECT_EQ(r.kind, core::ReadingKind::kBlind);
    EXPECT_NEAR(r.range_m, ipm.At(u, 239)->norm(), 1e-6);
  }
  const core::ObstacleProfile clear = ExtractProfile(cv::Mat1b(240, 320, uchar{255}), ipm, 0.4);
  for (const core::RangeReading& r : clear.readings) {
    EXPECT_EQ(r.kind, core::ReadingKind::kClear);
    EXPECT_EQ(r.range_m, 0.4);
  }
  // Floor reaching past the maximum range with an edge beyond it is clear too.
  cv::Mat1b far(240, 320, uchar{0});
  far.rowRange(40, 240).setTo(255);
  for (const core::RangeReading& r : ExtractProfile(far, ipm, 0.4).readings) {
    EXPECT_EQ(r.kind, core::ReadingKind::kClear);
  }
}

TEST(ProfileExtractorTest, BottomRowsLeftOutAreNotBlind) {
  const camera::CameraModel camera = PaperCamera();
  const camera::InversePerspectiveMap ipm(camera);
  cv::Mat1b mask(240, 320, uchar{0});
  mask.rowRange(151, 238).setTo(255);  // the last two rows are not floor
  for (const core::RangeReading& r : ExtractProfile(mask, ipm, 10.0).readings) {
    EXPECT_EQ(r.kind, core::ReadingKind::kHit);
  }
}

void ExpectSameProfiles(const core::ObstacleProfile& a, const core::ObstacleProfile& b) {
  ASSERT_EQ(a.readings.size(), b.readings.size());
  EXPECT_EQ(a.max_range_m, b.max_range_m);
  for (std::size_t i = 0; i < a.readings.size(); ++i) {
    EXPECT_EQ(a.readings[i].kind, b.readings[i].kind) << "column " << i;
    EXPECT_EQ(a.readings[i].range_m, b.readings[i].range_m) << "column " << i;
    EXPECT_EQ(a.readings[i].bearing_rad, b.readings[i].bearing_rad) << "column " << i;
  }
  ASSERT_EQ(a.feet.size(), b.feet.size());
  for (std::size_t i = 0; i < a.feet.size(); ++i) {
    EXPECT_EQ(a.feet[i].kind, b.feet[i].kind) << "foot " << i;
    EXPECT_EQ(a.feet[i].range_m, b.feet[i].range_m) << "foot " << i;
    EXPECT_EQ(a.feet[i].bearing_rad, b.feet[i].bearing_rad) << "foot " << i;
  }
}

TEST(ProfileExtractorTest, TheExtractorGivesExtractProfilesReadings) {
  const camera::CameraModel camera = PaperCamera();
  const camera::InversePerspectiveMap ipm(camera);
  cv::RNG rng(3);
  const VerticalDirectionField vertical(camera);
  for (const double max_range : {0.2, 0.4068, 10.0}) {
    const ProfileExtractor extractor(ipm, max_range);
    const ProfileExtractor with_vertical(ipm, max_range, vertical);
    EXPECT_EQ(extractor.max_range_m(), max_range);
    for (int trial = 0; trial < 6; ++trial) {
      // Floor up to a random row per column, holes, blind columns, floor to
      // the top row: every case of the reading.
      cv::Mat1b mask(240, 320, uchar{0});
      for (int u = 0; u < 320; ++u) {
        const int top = rng.uniform(-5, 240);
        if (top >= 0) mask.col(u).rowRange(top, 240).setTo(255);
        if (rng.uniform(0, 10) == 0) mask.col(u).rowRange(237, 240).setTo(0);  // blind
        if (rng.uniform(0, 10) == 0) mask(239, u) = 0;                         // margin
      }
      for (int hole = 0; hole < 40 * trial; ++hole) {
        mask(rng.uniform(0, 240), rng.uniform(0, 320)) = 0;
      }
      ExpectSameProfiles(extractor.Extract(mask), ExtractProfile(mask, ipm, max_range));
      // With unresolved pixels here and there, too.
      cv::Mat1b unresolved(240, 320, uchar{0});
      for (int u = 0; u < 320; ++u) {
        if (rng.uniform(0, 2) == 0) unresolved.col(u).setTo(255);
      }
      ExpectSameProfiles(extractor.Extract(mask, unresolved),
                         ExtractProfile(mask, ipm, max_range, unresolved));
      // And with the camera's verticals.
      ExpectSameProfiles(with_vertical.Extract(mask, unresolved),
                         ExtractProfile(mask, ipm, max_range, unresolved, &vertical));
    }
  }
}

// Where the floor ends at an unresolved pixel (the floor may go on there,
// FloorSegmenter::Unresolved), the column is seen free to the edge and no
// farther: kClear at the edge's range, not a hit.
TEST(ProfileExtractorTest, AFloorEndingWhereItIsUnresolvedIsClearToThere) {
  const camera::CameraModel camera = PaperCamera();
  const camera::InversePerspectiveMap ipm(camera);
  cv::Mat1b mask(240, 320, uchar{0});
  mask.rowRange(151, 240).setTo(255);  // the edge at 150.5, as in the first test
  cv::Mat1b unresolved(240, 320, uchar{0});
  unresolved(cv::Rect(0, 100, 160, 51)).setTo(255);  // the left half, rows 100-150
  const ProfileExtractor extractor(ipm, 10.0);
  const core::ObstacleProfile plain = extractor.Extract(mask);
  const core::ObstacleProfile profile = extractor.Extract(mask, unresolved);
  for (int u = 0; u < 320; ++u) {
    const auto i = static_cast<std::size_t>(u);
    EXPECT_EQ(plain.readings[i].kind, core::ReadingKind::kHit) << u;
    EXPECT_EQ(profile.readings[i].kind,
              u < 160 ? core::ReadingKind::kClear : core::ReadingKind::kHit)
        << u;
    // The same range and bearing either way: the edge's.
    EXPECT_EQ(profile.readings[i].range_m, plain.readings[i].range_m) << u;
    EXPECT_EQ(profile.readings[i].bearing_rad, plain.readings[i].bearing_rad) << u;
    EXPECT_LT(profile.readings[i].range_m, 10.0) << u;
  }
  // Unresolved pixels where the floor does not end change nothing.
  cv::Mat1b elsewhere(240, 320, uchar{0});
  elsewhere.rowRange(0, 140).setTo(255);
  elsewhere.rowRange(152, 240).setTo(255);
  ExpectSameProfiles(extractor.Extract(mask, elsewhere), plain);
}

// A box standing on the floor (robot frame, metres): x and y extents, height.
struct Box {
  double x0, x1, y0, y1, height;
  // Its footprint's distance from a floor point (0 inside).
  double Distance(const Eigen::Vector2d& p) const {
    const double dx = std::max({x0 - p.x(), 0.0, p.x() - x1});
    const double dy = std::max({y0 - p.y(), 0.0, p.y() - y1});
    return std::hypot(dx, dy);
  }
  // Whether the segment a -> b passes through it (slabs).
  bool Crosses(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    const Eigen::Vector3d lo(x0, y0, 0.0);
    const Eigen::Vector3d hi(x1, y1, height);
    double t0 = 0.0;
    double t1 = 1.0;
    for (int i = 0; i < 3; ++i) {
      const double d = b[i] - a[i];
      if (std::abs(d) < 1e-12) {
        if (a[i] < lo[i] || a[i] > hi[i]) return false;
        continue;
      }
      const double ta = (lo[i] - a[i]) / d;
      const double tb = (hi[i] - a[i]) / d;
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
      if (t0 > t1) return false;
    }
    return true;
  }
};

// The true floor mask of the paper's camera looking at `box`: a pixel sees
// floor where its ray meets the floor before the box.
cv::Mat1b FloorMaskWith(const camera::CameraModel& camera, const Box& box) {
  const Eigen::Vector3d centre = camera.robot_T_camera().translation();
  cv::Mat1b mask(camera.height(), camera.width(), uchar{0});
  for (int v = 0; v < mask.rows; ++v) {
    for (int u = 0; u < mask.cols; ++u) {
      const std::optional<Eigen::Vector2d> p = camera.FloorPoint({u, v});
      if (p && !box.Crosses(centre, Eigen::Vector3d(p->x(), p->y(), 0.0))) mask(v, u) = 255;
    }
  }
  return mask;
}

// The largest distance of a hit (the feet among them) from the box, and the
// hits.
std::pair<double, int> FarthestHit(const core::ObstacleProfile& profile, const Box& box) {
  double farthest = 0.0;
  int hits = 0;
  for (const auto* readings : {&profile.readings, &profile.feet}) {
    for (const core::RangeReading& r : *readings) {
      if (r.kind != core::ReadingKind::kHit) continue;
      ++hits;
      const Eigen::Vector2d p =
          r.range_m * Eigen::Vector2d(std::cos(r.bearing_rad), std::sin(r.bearing_rad));
      farthest = std::max(farthest, box.Distance(p));
    }
  }
  return {farthest, hits};
}

// A post taller than the camera, its base in view: a column that passes
// from floor into the slanted image of one of its vertical sides, above the
// base, would put a hit on the open floor behind the post; with the
// camera's verticals such a column is clear to its edge and adds a hit at
// the foot of the side (the profile's feet), and every hit is at the post's
// base.
TEST(ProfileExtractorTest, APostsSidesAreReadAtItsBaseNotBehindIt) {
  const camera::CameraModel camera = PaperCamera();
  const camera::InversePerspectiveMap ipm(camera);
  const VerticalDirectionField vertical(camera);
  // Left and right of the view, where its verticals slant most.
  for (const Box& post : {Box{0.22, 0.25, 0.06, 0.09, 0.3}, Box{0.20, 0.24, -0.12, -0.08, 0.3}}) {
    const cv::Mat1b mask = FloorMaskWith(camera, post);
    const auto [column_farthest, column_hits] = FarthestHit(ExtractProfile(mask, ipm, 0.4), post);
    const core::ObstacleProfile profile = ExtractProfile(mask, ipm, 0.4, cv::Mat1b(), &vertical);
    const auto [base_farthest, base_hits] = FarthestHit(profile, post);
    EXPECT_FALSE(profile.feet.empty()) << post.x0 << "," << post.y0;
    // The column's reading does put hits behind the post: the case is real.
    EXPECT_GT(column_farthest, 0.02) << post.x0 << "," << post.y0;
    // A pixel is about 2 mm of floor there: within 5 mm of the post.
    EXPECT_LT(base_farthest, 0.005) << post.x0 << "," << post.y0;
    // The post's faces keep their hits.
    EXPECT_GT(base_hits, column_hits / 2) << post.x0 << "," << post.y0;
  }
}

// A wall's end nearer than the camera sees floor (its base below the view),
// the wall running from it across the view: the columns just past its end
// see floor and then the wall's end, leaning out of the view. They are
// seen free to there and no farther (kClear), never a hit on the floor
// beyond the wall's end (as a maze's corridor turning round the wall would
// be closed by).
TEST(ProfileExtractorTest, AWallsEndBelowTheViewIsNoHitBeyondIt) {
  const camera::CameraModel camera = PaperCamera();
  const camera::InversePerspectiveMap ipm(camera);
  const VerticalDirectionField vertical(camera);
  ASSERT_GT(camera::NearRange(ipm), 0.1);
  const Box wall{0.08, 0.09, -1.0, 0.03, 0.3};  // 8 cm ahead, its end 3 cm to the left
  const cv::Mat1b mask = FloorMaskWith(camera, wall);
  const auto [column_farthest, column_hits] = FarthestHit(ExtractProfile(mask, ipm, 0.4), wall);
  EXPECT_GT(column_farthest, 0.02);
  const core::ObstacleProfile profile = ExtractProfile(mask, ipm, 0.4, cv::Mat1b(), &vertical);
  const auto [base_farthest, base_hits] = FarthestHit(profile, wall);
  EXPECT_LT(base_farthest, 0.005);
  int clear_short = 0;
  for (const core::RangeReading& r : profile.readings) {
    clear_short += r.kind == core::ReadingKind::kClear && r.range_m < 0.4 ? 1 : 0;
  }
  EXPECT_GT(clear_short, 0);
}

}  // namespace
}  // namespace pirouette::vision
