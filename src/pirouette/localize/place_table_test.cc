#include "pirouette/localize/place_table.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::localize {
namespace {

namespace fs = std::filesystem;
constexpr int kBins = mapping::kRadialProfileBins;

// A robot at (px, py) facing heading_deg in a 2 × 1.4 m room with a blue
// block on the left wall.
PlaceView View(double px, double py, double heading_deg) {
  const double w = 2.0, h = 1.4;
  PlaceView view;
  for (int b = 0; b < kBins; ++b) {
    const double a = core::DegToRad(heading_deg + b + 0.5);
    const double c = std::cos(a), s = std::sin(a);
    double t = 1e9;
    if (c > 1e-12) t = std::min(t, (w - px) / c);
    if (c < -1e-12) t = std::min(t, -px / c);
    if (s > 1e-12) t = std::min(t, (h - py) / s);
    if (s < -1e-12) t = std::min(t, -py / s);
    view.ranges_m.push_back(std::min(t, 1.5));
    const double hy = py + t * s;
    const bool blue = c < -1e-12 && std::abs(px + t * c) < 1e-6 && hy > 0.3 && hy < 0.7;
    view.colours.push_back(t > 1.5 ? ColourClass::kNone
                                   : (blue ? ColourClass::kHue8 : ColourClass::kGrey));
  }
  return view;
}

PlaceTable Grid() {
  std::vector<PlaceEntry> entries;
  for (double x = 0.2; x < 1.9; x += 0.3) {
    for (double y = 0.2; y < 1.3; y += 0.3) {
      PlaceEntry e;
      e.x_m = x;
      e.y_m = y;
      e.heading_rad = 0.0;
      e.view = View(x, y, 0.0);
      e.kinds.assign(kBins, core::ReadingKind::kHit);
      entries.push_back(std::move(e));
    }
  }
  return {"room", 1.5, std::move(entries)};
}

fs::path Temp(const std::string& name) {
  return fs::temp_directory_path() /
         ("pirouette_place_table_" + std::to_string(::getpid()) + "_" + name);
}

TEST(PlaceTableTest, ARotatedQueryFindsItsPlaceAndHeading) {
  const PlaceTable table = Grid();
  const int truth = 9;
  const PlaceEntry& e = table.entries()[truth];
  for (double heading_deg : {0.0, 33.0, 147.0, -100.0}) {
    const PlaceView query = View(e.x_m, e.y_m, heading_deg);
    for (SignatureKind kind : {SignatureKind::kFourier, SignatureKind::kColour}) {
      const std::vector<PlaceMatch> best = table.Nearest(query, kind, 3);
      ASSERT_EQ(best.size(), 3u);
      EXPECT_EQ(best[0].entry, truth) << SignatureKindName(kind) << " " << heading_deg;
      ASSERT_TRUE(best[0].heading_rad.has_value());
      EXPECT_LT(std::abs(core::NormalizeAngle(*best[0].heading_rad - core::DegToRad(heading_deg))),
                core::DegToRad(1.0))
          << SignatureKindName(kind) << " " << heading_deg;
      EXPECT_LE(best[0].distance, best[1].distance);
    }
    EXPECT_EQ(table.Nearest(query, SignatureKind::kHu, 1)[0].entry, truth);
  }
  // The DCT only knows the place at the heading it was stored with.
  const std::vector<PlaceMatch> dct = table.Nearest(View(e.x_m, e.y_m, 0.0), SignatureKind::kDct);
  ASSERT_EQ(dct.size(), 1u);
  EXPECT_EQ(dct[0].entry, truth);
  EXPECT_NEAR(dct[0].distance, 0.0, 1e-12);
  EXPECT_FALSE(dct[0].heading_rad.has_value());
}

TEST(PlaceTableTest, APoseSearchGivesTheQueryPositionBetweenPlaces) {
  const PlaceTable table = Grid();
  const PlaceView query = View(1.0, 0.65, -60.0);  // between the grid's places
  const std::vector<PlaceMatch> best =
      table.Nearest(query, SignatureKind::kColour, 1, PoseSearch{0.25, 0.005});
  ASSERT_EQ(best.size(), 1u);
  ASSERT_TRUE(best[0].position_m.has_value());
  EXPECT_NEAR(best[0].position_m->x(), 1.0, 0.02);
  EXPECT_NEAR(best[0].position_m->y(), 0.65, 0.02);
  EXPECT_LT(std::abs(core::NormalizeAngle(*best[0].heading_rad - core::DegToRad(-60.0))),
            core::DegToRad(2.0));
  // The ranges alone cannot tell the pose from its mirror through the room's
  // centre (1.0, 0.7); the colour signature can.
  const std::vector<PlaceMatch> ranges =
      table.Nearest(query, SignatureKind::kFourier, 1, PoseSearch{0.25, 0.005});
  ASSERT_TRUE(ranges[0].position_m.has_value());
  const double off = std::min((*ranges[0].position_m - Eigen::Vector2d(1.0, 0.65)).norm(),
                              (*ranges[0].position_m - Eigen::Vector2d(1.0, 0.75)).norm());
  EXPECT_LT(off, 0.03);
}

TEST(PlaceTableTest, SaveAndLoadRoundTrip) {
  const PlaceTable table = Grid();
  const fs::path path = Temp("round_trip.yaml");
  SavePlaceTable(table, path.string());
  const PlaceTable loaded = LoadPlaceTable(path.string());
  EXPECT_EQ(loaded.world(), "room");
  EXPECT_DOUBLE_EQ(loaded.max_range_m(), 1.5);
  ASSERT_EQ(loaded.entries().size(), table.entries().size());
  for (std::size_t i = 0; i < table.entries().size(); ++i) {
    const PlaceEntry& a = table.entries()[i];
    const PlaceEntry& b = loaded.entries()[i];
    EXPECT_NEAR(a.x_m, b.x_m, 1e-4);
    EXPECT_NEAR(a.y_m, b.y_m, 1e-4);
    EXPECT_NEAR(a.heading_rad, b.heading_rad, 1e-4);
    ASSERT_EQ(b.view.ranges_m.size(), a.view.ranges_m.size());
    for (int k = 0; k < kBins; ++k) EXPECT_NEAR(a.view.ranges_m[k], b.view.ranges_m[k], 1e-4);
    EXPECT_EQ(a.view.colours, b.view.colours);
    EXPECT_EQ(a.kinds, b.kinds);
  }
  // No temporary file is left beside it.
  int files = 0;
  for ([[maybe_unused]] const auto& f : fs::directory_iterator(path.parent_path())) {
    if (f.path().filename().string().rfind(path.filename().string(), 0) == 0) ++files;
  }
  EXPECT_EQ(files, 1);
  const PlaceView query = View(1.1, 0.8, 70.0);
  EXPECT_EQ(loaded.Nearest(query, SignatureKind::kColour)[0].entry,
            table.Nearest(query, SignatureKind::kColour)[0].entry);
  fs::remove(path);
}

TEST(PlaceTableTest, MalformedFilesNameTheField) {
  const fs::path path = Temp("bad.yaml");
  SavePlaceTable(Grid(), path.string());
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // The first place's x is not a number.
  const std::string bad = text.substr(0, text.find("{x: ") + 4) + "abc" +
                          text.substr(text.find(',', text.find("{x: ")));
  {
    std::ofstream out(path);
    out << bad;
  }
  try {
    LoadPlaceTable(path.string());
    FAIL() << "loaded a malformed table";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.field(), "places[0].x");
    EXPECT_EQ(e.file(), path.string());
    EXPECT_GT(e.line(), 0);
  }
  {
    std::ofstream out(path);
    out << "format: pirouette-places/2\nworld: x\nmax_range_m: 1\nplaces: []\n";
  }
  try {
    LoadPlaceTable(path.string());
    FAIL() << "loaded another format";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.field(), "format");
  }
  {
    std::ofstream out(path);
    out << "format: pirouette-places/1\nworld: x\nmax_range_m: 1\n"
           "places:\n  - {x: 1, y: 1, heading_deg: 0, ranges: [1, 2], colours: '', kinds: ''}\n";
  }
  try {
    LoadPlaceTable(path.string());
    FAIL() << "loaded a short profile";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.field(), "places[0].ranges");
  }
  EXPECT_THROW(LoadPlaceTable(Temp("missing.yaml").string()), core::InputError);
  fs::remove(path);
}

}  // namespace
}  // namespace pirouette::localize
