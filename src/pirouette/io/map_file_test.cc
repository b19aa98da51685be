#include "pirouette/io/map_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "pirouette/core/input_error.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::io {
namespace {

namespace fs = std::filesystem;
using mapping::CellState;
using mapping::TrinaryMap;

// A 3 × 2 map: the top row (y = 1) is occupied, free, unknown; the bottom row
// (y = 0) is free, free, occupied.
TrinaryMap SmallMap() {
  TrinaryMap map{core::GridGeometry(0.05, {-1.25, 0.5}, 3, 2), {}};
  map.cells = {CellState::kFree,     CellState::kFree, CellState::kOccupied,
               CellState::kOccupied, CellState::kFree, CellState::kUnknown};
  return map;
}

// Cells of a pattern that mixes all three states without symmetry.
TrinaryMap PatternMap(double resolution, Eigen::Vector2d origin, int width, int height) {
  TrinaryMap map{core::GridGeometry(resolution, std::move(origin), width, height), {}};
  for (std::size_t i = 0; i < map.geometry.CellCount(); ++i) {
    const std::size_t k = (i * 7 + i / 5) % 3;
    map.cells.push_back(k == 0 ? CellState::kFree
                               : (k == 1 ? CellState::kOccupied : CellState::kUnknown));
  }
  return map;
}

class MapFileTest : public ::testing::Test {
 protected:
  testing::TempDir temp_{"pirouette_map_file"};
  fs::path dir_ = temp_.path();

  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  std::string Write(const std::string& name, const std::string& bytes) const {
    std::ofstream(Path(name), std::ios::binary) << bytes;
    return Path(name);
  }
  static std::string ReadAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // A map.yaml for `image` with the fields map_server needs, `extra` appended.
  std::string Yaml(const std::string& image, const std::string& extra = "") const {
    return Write("map.yaml", "image: " + image +
                                 "\nresolution: 0.1\norigin: [1.0, 2.0, 0.0]\nnegate: 0\n"
                                 "occupied_thresh: 0.65\nfree_thresh: 0.196\n" +
                                 extra);
  }
};

// The InputError that `read` throws, or a failure.
template <typename F>
core::InputError ErrorOf(F read) {
  try {
    read();
  } catch (const core::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return {"", 0, "", ""};
}

TEST(RosMapPgmTest, HeaderThenTopRowFirst) {
  const std::string pgm = RosMapPgm(SmallMap());
  const std::string header = "P5\n3 2\n255\n";
  ASSERT_EQ(pgm.size(), header.size() + 6);
  EXPECT_EQ(pgm.substr(0, header.size()), header);
  const std::vector<unsigned char> pixels(pgm.begin() + static_cast<long>(header.size()),
                                          pgm.end());
  EXPECT_EQ(pixels, (std::vector<unsigned char>{0, 254, 205, 254, 254, 0}));
}

TEST(RosMapPgmTest, RefusesCellsThatDoNotMatchTheGeometry) {
  TrinaryMap map = SmallMap();
  map.cells.pop_back();
  EXPECT_THROW(RosMapPgm(map), std::invalid_argument);
}

TEST(RosMapYamlTest, HasMapServersFields) {
  EXPECT_EQ(RosMapYaml(SmallMap(), "map.pgm"),
            "image: map.pgm\nmode: trinary\nresolution: 0.05\norigin: [-1.25, 0.5, 0]\n"
            "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
}

TEST(RosMapYamlTest, QuotesAnAwkwardImageName) {
  EXPECT_NE(RosMapYaml(SmallMap(), "my map: \"1\".pgm").find("image: \"my map: \\\"1\\\".pgm\"\n"),
            std::string::npos);
}

TEST_F(MapFileTest, RoundTripKeepsEverything) {
  // Awkward numbers must come back as the same doubles.
  const TrinaryMap map = PatternMap(0.1 / 3.0, {-1.2345678901234567, 3.3e-7}, 17, 11);
  WriteRosMap(map, Path("map.yaml"));
  const TrinaryMap read = ReadRosMap(Path("map.yaml"));
  EXPECT_EQ(read.geometry, map.geometry);
  EXPECT_EQ(read.geometry.resolution(), map.geometry.resolution());
  EXPECT_EQ(read.geometry.origin(), map.geometry.origin());
  EXPECT_EQ(read.cells, map.cells);
}

TEST_F(MapFileTest, WritesBothFilesAndNothingElse) {
  const TrinaryMap map = SmallMap();
  WriteRosMap(map, Path("room.yaml"));
  EXPECT_EQ(ReadAll(Path("room.pgm")), RosMapPgm(map));
  EXPECT_EQ(ReadAll(Path("room.yaml")), RosMapYaml(map, "room.pgm"));
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"room.pgm", "room.yaml"}));
  // Written again over the old files: still just the two.
  WriteRosMap(PatternMap(0.05, {0, 0}, 4, 4), Path("room.yaml"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 2);
  EXPECT_EQ(ReadRosMap(Path("room.yaml")).geometry.width(), 4);
}

TEST_F(MapFileTest, RefusesAYamlPathThatIsThePgms) {
  EXPECT_THROW(WriteRosMap(SmallMap(), Path("map.pgm")), std::invalid_argument);
  EXPECT_THROW(WriteRosMap(SmallMap(), Path("nowhere/map.yaml")), std::runtime_error);
}

TEST_F(MapFileTest, ThresholdsAsMapServerReadsThem) {
  // p = (255 - v) / 255: occupied above 0.65, free below 0.196.
  // v:        0    80   89   90   100  204  205  206  254  255
  // p:        1   .686 .651 .647 .608 .2   .196 .192 .004  0
  const std::string values = "0 80 89 90 100 204 205 206 254 255";
  Write("map.pgm", "P2\n10 1\n255\n" + values + "\n");
  const TrinaryMap map = ReadRosMap(Yaml("map.pgm"));
  const auto o = CellState::kOccupied;
  const auto f = CellState::kFree;
  const auto u = CellState::kUnknown;
  EXPECT_EQ(map.cells, (std::vector<CellState>{o, o, o, u, u, u, u, f, f, f}));

  // Negated, p = v / 255.
  Write("negated.yaml",
        "image: map.pgm\nresolution: 0.1\norigin: [1.0, 2.0, 0.0]\nnegate: 1\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const TrinaryMap negated = ReadRosMap(Path("negated.yaml"));
  EXPECT_EQ(negated.cells, (std::vector<CellState>{f, u, u, u, u, o, o, o, o, o}));
  // nav2 writes negate as a boolean too.
  Write("negated.yaml",
        "image: map.pgm\nresolution: 0.1\norigin: [1.0, 2.0, 0.0]\nnegate: true\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  EXPECT_EQ(ReadRosMap(Path("negated.yaml")).cells, negated.cells);
}

TEST_F(MapFileTest, ReadsPlainPgmWithCommentsAndSixteenBitPgm) {
  Write("plain.pgm",
        "P2\n# a comment\n2 # width\n2\n# maxval next\n255\n0 254\n# row 2\n205 254\n");
  const TrinaryMap plain = ReadRosMap(Yaml("plain.pgm"));
  EXPECT_EQ(plain.geometry, core::GridGeometry(0.1, {1.0, 2.0}, 2, 2));
  // Top row first: (0, 1) occupied, (1, 1) free; (0, 0) unknown, (1, 0) free.
  EXPECT_EQ(plain.cells, (std::vector<CellState>{CellState::kUnknown, CellState::kFree,
                                                 CellState::kOccupied, CellState::kFree}));

  // maxval 65535: two bytes a pixel, most significant first.
  std::string wide = "P5\n3 1\n65535\n";
  wide += std::string("\x00\x00", 2) + std::string("\xFF\xFE", 2) + std::string("\xCD\xCD", 2);
  Write("wide.pgm", wide);
  EXPECT_EQ(ReadRosMap(Yaml("wide.pgm")).cells,
            (std::vector<CellState>{CellState::kOccupied, CellState::kFree, CellState::kUnknown}));
}

TEST_F(MapFileTest, ReadsPngThroughOpenCv) {
  cv::Mat3b image(2, 2);
  image(0, 0) = {0, 0, 0};
  image(0, 1) = {254, 254, 254};
  image(1, 0) = {205, 205, 205};
  image(1, 1) = {250, 255, 255};  // channels averaged: 253.3, free
  ASSERT_TRUE(cv::imwrite(Path("map.png"), image));
  const TrinaryMap map = ReadRosMap(Yaml("map.png", "mode: trinary\n"));
  EXPECT_EQ(map.cells, (std::vector<CellState>{CellState::kUnknown, CellState::kFree,
                                               CellState::kOccupied, CellState::kFree}));
}

// The modes, each value worked by hand from nav2's map_io (loadMapFromFile).
TEST_F(MapFileTest, ScaleModeAsMapServerReadsIt) {
  // occ = 1 - v/255; thresholds 0.65 and 0.196: between them
  // rint(100 (occ - 0.196) / (0.65 - 0.196)).
  // v:   0 -> occ 1 (100); 100 -> .6078 (91); 180 -> .2941 (22); 204 -> .2 (1);
  //      206 -> .1922 (0); 255 -> 0 (0).
  Write("map.pgm", "P2\n6 1\n255\n0 100 180 204 206 255\n");
  const MapServerMap map = ReadMapServerMap(Yaml("map.pgm", "mode: scale\n"));
  EXPECT_EQ(map.mode, MapMode::kScale);
  EXPECT_EQ(map.cells, (std::vector<std::int8_t>{100, 91, 22, 1, 0, 0}));
}

TEST_F(MapFileTest, ScaleModeMakesEveryPixelNotOpaqueUnknown) {
  cv::Mat4b image(1, 3);
  image(0, 0) = {0, 0, 0, 255};        // opaque black: occupied
  image(0, 1) = {255, 255, 255, 254};  // nearly opaque white: unknown
  image(0, 2) = {255, 255, 255, 255};  // opaque white: free
  ASSERT_TRUE(cv::imwrite(Path("map.png"), image));
  EXPECT_EQ(ReadMapServerMap(Yaml("map.png", "mode: scale\n")).cells,
            (std::vector<std::int8_t>{100, -1, 0}));
}

TEST_F(MapFileTest, TrinaryModeAveragesTheAlphaIn) {
  // (3 v + alpha) / 4: black opaque (63.75, occ .75) occupied; white fully
  // transparent (191.25, occ .25) unknown; white opaque free; grey 100 with
  // alpha 0 (75, occ .706) occupied, though opaque it would be unknown.
  cv::Mat4b image(1, 4);
  image(0, 0) = {0, 0, 0, 255};
  image(0, 1) = {255, 255, 255, 0};
  image(0, 2) = {255, 255, 255, 255};
  image(0, 3) = {100, 100, 100, 0};
  ASSERT_TRUE(cv::imwrite(Path("map.png"), image));
  EXPECT_EQ(ReadMapServerMap(Yaml("map.png")).cells, (std::vector<std::int8_t>{100, -1, 0, 100}));
}

TEST_F(MapFileTest, RawModeTakesTheValuesAsTheyAre) {
  // round(255 · v / 255) = v where 0..100, else unknown; negate plays no part.
  Write("map.pgm", "P2\n5 1\n255\n0 1 57 100 101\n");
  const std::vector<std::int8_t> expected{0, 1, 57, 100, -1};
  EXPECT_EQ(ReadMapServerMap(Yaml("map.pgm", "mode: raw\n")).cells, expected);
  Write("negated.yaml",
        "image: map.pgm\nmode: raw\nresolution: 0.1\norigin: [1.0, 2.0, 0.0]\nnegate: 1\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  EXPECT_EQ(ReadMapServerMap(Path("negated.yaml")).cells, expected);
}

TEST_F(MapFileTest, ReadRosMapRefusesScaleAndRawNamingTheMode) {
  Write("map.pgm", "P2\n1 1\n255\n0\n");
  for (const std::string mode : {"scale", "raw"}) {
    const core::InputError e =
        ErrorOf([&] { ReadRosMap(Yaml("map.pgm", "mode: " + mode + "\n")); });
    EXPECT_EQ(e.field(), "mode") << mode;
    EXPECT_NE(std::string(e.what()).find(mode), std::string::npos) << e.what();
  }
}

TEST_F(MapFileTest, ImagePathIsRelativeToTheYaml) {
  fs::create_directories(dir_ / "maps");
  WriteRosMap(SmallMap(), Path("maps/map.yaml"));
  EXPECT_EQ(ReadRosMap(Path("maps/map.yaml")).cells, SmallMap().cells);
  // And an absolute path stays as it is.
  Yaml(Path("maps/map.pgm"));
  EXPECT_EQ(ReadRosMap(Path("map.yaml")).cells, SmallMap().cells);
}

TEST_F(MapFileTest, MissingYamlNamesTheFile) {
  const core::InputError e = ErrorOf([&] { ReadRosMap(Path("none.yaml")); });
  EXPECT_EQ(e.file(), Path("none.yaml"));
  EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
}

TEST_F(MapFileTest, MalformedYamlNamesTheLine) {
  Write("bad.yaml", "image: map.pgm\nresolution: [0.1\n");
  const core::InputError e = ErrorOf([&] { ReadRosMap(Path("bad.yaml")); });
  EXPECT_EQ(e.file(), Path("bad.yaml"));
  EXPECT_GT(e.line(), 0);
}

struct BadYaml {
  const char* what;
  const char* yaml;
  const char* field;
  int line;
};

// map_server's fields with one thing wrong at a time (map.pgm exists).
const BadYaml kBadYamls[] = {
    {"no image",
     "resolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
     "free_thresh: 0.196\n",
     "image", 1},
    {"missing image file",
     "image: none.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
     "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "image", 1},
    {"no resolution",
     "image: map.pgm\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
     "free_thresh: 0.196\n",
     "resolution", 1},
    {"zero resolution",
     "image: map.pgm\nresolution: 0\norigin: [0, 0, 0]\nnegate: 0\n"
     "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "resolution", 2},
    {"negative resolution",
     "image: map.pgm\nresolution: -0.05\norigin: [0, 0, 0]\nnegate: 0\n"
     "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "resolution", 2},
    {"text resolution",
     "image: map.pgm\nresolution: fine\norigin: [0, 0, 0]\nnegate: 0\n"
     "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "resolution", 2},
    {"two-number origin",
     "image: map.pgm\nresolution: 0.1\norigin: [0, 0]\nnegate: 0\n"
     "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "origin", 3},
    {"rotated origin",
     "image: map.pgm\nresolution: 0.1\norigin: [0, 0, 0.5]\nnegate: 0\n"
     "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "origin", 3},
    {"scale mode",
     "image: map.pgm\nmode: scale\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
     "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "mode", 2},
    {"unknown mode",
     "image: map.pgm\nmode: fancy\nresolution: 0.1\norigin: [0, 0, 0]\n"
     "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "mode", 2},
    {"negate 2",
     "image: map.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 2\n"
     "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "negate", 4},
    {"no negate",
     "image: map.pgm\nresolution: 0.1\norigin: [0, 0, 0]\n"
     "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
     "negate", 1},
    {"threshold above 1",
     "image: map.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
     "occupied_thresh: 1.5\nfree_thresh: 0.196\n",
     "occupied_thresh", 5},
    {"thresholds crossed",
     "image: map.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
     "occupied_thresh: 0.1\nfree_thresh: 0.196\n",
     "free_thresh", 6},
};

TEST_F(MapFileTest, BadFieldsAreNamed) {
  Write("map.pgm", RosMapPgm(SmallMap()));
  for (const BadYaml& bad : kBadYamls) {
    SCOPED_TRACE(bad.what);
    const std::string path = Write("bad.yaml", bad.yaml);
    const core::InputError e = ErrorOf([&] { ReadRosMap(path); });
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.field(), bad.field) << e.what();
    EXPECT_EQ(e.line(), bad.line) << e.what();
  }
}

struct BadPgm {
  const char* what;
  std::string bytes;
  const char* field;
};

TEST_F(MapFileTest, MalformedImagesAreNamed) {
  const BadPgm bad_pgms[] = {
      {"empty", "", ""},
      {"not an image", "hello, world\n", ""},
      {"no width", "P5\n", "width"},
      {"zero width", "P5\n0 2\n255\n", "width"},
      {"text height", "P5\n2 x\n255\n", "height"},
      {"zero maxval", "P5\n2 2\n0\n", "maxval"},
      {"huge maxval", "P5\n2 2\n65536\n", "maxval"},
      {"no space after maxval", "P5\n2 2\n255", "maxval"},
      {"truncated", "P5\n2 2\n255\n" + std::string(3, '\xFE'), "pixels"},
      {"pixel above maxval", "P5\n2 2\n100\n" + std::string(4, '\x65'), "pixels"},
      {"plain, truncated", "P2\n2 2\n255\n0 0 0\n", "pixels"},
      {"plain, not a number", "P2\n2 2\n255\n0 0 zero 0\n", "pixels"},
  };
  for (const BadPgm& bad : bad_pgms) {
    SCOPED_TRACE(bad.what);
    const std::string pgm = Write("bad.pgm", bad.bytes);
    const std::string yaml = Yaml("bad.pgm");
    const core::InputError e = ErrorOf([&] { ReadRosMap(yaml); });
    EXPECT_EQ(e.file(), pgm) << e.what();
    EXPECT_EQ(e.field(), bad.field) << e.what();
  }
}

TEST_F(MapFileTest, ImageThatIsAFolderIsNamed) {
  fs::create_directories(dir_ / "folder.pgm");
  const std::string yaml = Yaml("folder.pgm");
  const core::InputError e = ErrorOf([&] { ReadRosMap(yaml); });
  EXPECT_EQ(e.file(), yaml);
  EXPECT_EQ(e.field(), "image");
}

TEST_F(MapFileTest, IgnoresKeysMapServerIgnores) {
  Write("map.pgm", RosMapPgm(SmallMap()));
  EXPECT_EQ(ReadRosMap(Yaml("map.pgm", "comment: made by hand\n")).cells, SmallMap().cells);
}

}  // namespace
}  // namespace pirouette::io
