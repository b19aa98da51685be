#include "pirouette/io/place_table_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/mapping/radial_profile.h"
#include "pirouette/testing/temp_dir.h"
#include "pirouette/testing/test_places.h"

namespace pirouette::io {
namespace {

namespace fs = std::filesystem;
using localize::PlaceEntry;
using localize::PlaceTable;
using localize::PlaceView;
using localize::SignatureKind;
using testing::Grid;
using testing::kBins;
using testing::View;

TEST(PlaceTableFileTest, SaveAndLoadRoundTrip) {
  const PlaceTable table = Grid();
  const testing::TempDir temp("pirouette_place_table");
  const fs::path path = temp.path() / "round_trip.yaml";
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
}

TEST(PlaceTableFileTest, MalformedFilesNameTheField) {
  const testing::TempDir temp("pirouette_place_table");
  const fs::path path = temp.path() / "bad.yaml";
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
  EXPECT_THROW(LoadPlaceTable((temp.path() / "missing.yaml").string()), core::InputError);
}

}  // namespace
}  // namespace pirouette::io
