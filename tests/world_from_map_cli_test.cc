// `pirouette world from-map` as a user meets it (SPEC.md, "Worlds nobody drew
// by hand"): a map_server map becomes a world whose truth is the map's cells,
// free only where map_server serves 0; the start in the largest region, far
// from walls; narrow gaps sealed; bad input exits 2 naming the file and
// field. And the real maps of ../shared/realdata/maps (skipped where absent).

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "pirouette/io/map_file.h"
#include "pirouette/io/world_file.h"
#include "pirouette/sim/world.h"
#include "pirouette/testing/temp_dir.h"
#include "pirouette/tools/world_generate.h"
#include "run_pirouette.h"

namespace {

namespace fs = std::filesystem;

using pirouette::testing::RunPirouette;
using Result = pirouette::testing::RunResult;

const std::string kMapsDir = std::string(PIROUETTE_SHARED_DIR) + "/realdata/maps";

class WorldFromMapCliTest : public ::testing::Test {
 protected:
  std::string Path(const std::string& name) const { return dir_ / name; }

  // A 4 × 3 m map at 5 cm, origin (-2, -1): a room walled all round, split by
  // a wall at x = 2 m with a 10 cm gap (narrower than the robot) at the top
  // and a 60 cm door at the bottom; beyond the gap a pocket walled off from
  // the rest, reachable through the gap only; a speck in the left room; an
  // unknown band (205) along the top. Plain PGM, as a person might write one.
  std::string WriteMap() const {
    const int w = 80;
    const int h = 60;
    std::vector<int> v(static_cast<std::size_t>(w * h), 254);
    const auto set = [&](int x, int y, int value) {
      v[static_cast<std::size_t>((h - 1 - y) * w + x)] = value;
    };
    for (int x = 0; x < w; ++x) {
      for (int y = 0; y < h; ++y) {
        if (x < 2 || y < 2 || x >= w - 2 || y >= h - 6) set(x, y, 0);
        if (y >= h - 3) set(x, y, 205);
      }
    }
    for (int y = 0; y < h - 6; ++y) {
      if ((y >= 44 && y < 46) || (y >= 6 && y < 18)) continue;
      set(40, y, 0);
      set(41, y, 0);
    }
    // The pocket: x 42..50, y 40..50, walled except towards the gap.
    for (int x = 42; x <= 52; ++x) {
      set(x, 38, 0);
      set(x, 39, 0);
    }
    for (int y = 38; y < h - 6; ++y) {
      set(51, y, 0);
      set(52, y, 0);
    }
    set(20, 30, 0);  // the speck
    std::string pgm =
        "P2\n# a test map\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    for (int i = 0; i < w * h; ++i)
      pgm += std::to_string(v[static_cast<std::size_t>(i)]) + (i % w == w - 1 ? "\n" : " ");
    dir_.Write("maps/room.pgm", pgm);
    return dir_.Write("maps/room.yaml",
                      "image: room.pgm\nresolution: 0.05\norigin: [-2.0, -1.0, 0.0]\n"
                      "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  }

  pirouette::testing::TempDir dir_{"pirouette_world_from_map_cli_test"};
};

TEST_F(WorldFromMapCliTest, TheWorldsTruthIsTheMapsCellsWithTheNarrowGapSealed) {
  const std::string map_path = WriteMap();
  fs::create_directories(Path("worlds"));
  const std::string out = Path("worlds/room.yaml");
  const Result r =
      RunPirouette("world from-map --map " + map_path + " --out " + out + " --radius 0.1");
  ASSERT_EQ(r.exit_code, 0) << r.output();
  EXPECT_NE(r.stderr_only.find("wrote " + out), std::string::npos) << r.stderr_only;
  // The map named relative to the world file.
  EXPECT_NE(dir_.Read("worlds/room.yaml").find("map: \"../maps/room.yaml\""), std::string::npos)
      << dir_.Read("worlds/room.yaml");

  const pirouette::sim::World world = pirouette::io::LoadWorldFile(out);
  EXPECT_EQ(world.floor().size, Eigen::Vector2d(4.0, 3.0));
  const pirouette::io::MapServerMap map = pirouette::io::ReadMapServerMap(map_path);
  // Every cell map_server does not serve as free is occupied in the world;
  // of the free ones, only the gap and the pocket behind it are not.
  std::size_t sealed = 0;
  std::size_t sealed_elsewhere = 0;  // corner cells the disc cannot sweep
  for (int y = 0; y < 60; ++y) {
    for (int x = 0; x < 80; ++x) {
      const Eigen::Vector2d c((x + 0.5) * 0.05, (y + 0.5) * 0.05);
      const std::int8_t value = map.cells[map.geometry.Flat({x, y})];
      if (value != 0) {
        EXPECT_TRUE(world.IsOccupied(c)) << x << ", " << y;
      } else if (world.IsOccupied(c)) {
        ++sealed;
        if (!(x >= 40 && x <= 50 && y >= 40 && y <= 53)) ++sealed_elsewhere;
      }
    }
  }
  // The gap and the pocket behind it are sealed; the door is not.
  EXPECT_TRUE(world.IsOccupied({40.5 * 0.05, 44.5 * 0.05}));
  EXPECT_TRUE(world.IsOccupied({46.5 * 0.05, 45.5 * 0.05}));
  EXPECT_FALSE(world.IsOccupied({40.5 * 0.05, 12.5 * 0.05}));
  EXPECT_TRUE(world.IsOccupied({20.5 * 0.05, 30.5 * 0.05}));  // the speck stays
  EXPECT_GE(sealed - sealed_elsewhere, 9U * 14U);  // the pocket's 9 x 14 free cells, at least
  // Each concave corner loses the few cells the disc cannot sweep.
  EXPECT_LT(sealed_elsewhere, 80U);

  // Every cell the robot fits in is reachable, as eval reckons it.
  const pirouette::tools::WorldValidity validity = pirouette::tools::CheckWorld(world);
  EXPECT_TRUE(validity.start_fits);
  EXPECT_EQ(validity.unreachable_cells, 0U);
  EXPECT_GT(validity.reachable_cells, 1000U);
}

TEST_F(WorldFromMapCliTest, TheStartIsChosenFarFromWallsOrGivenInTheMapsFrame) {
  const std::string map_path = WriteMap();
  const Result r = RunPirouette("world from-map --map " + map_path + " --out " + Path("a.yaml") +
                                " --radius 0.1");
  ASSERT_EQ(r.exit_code, 0) << r.output();
  const Eigen::Vector2d start =
      pirouette::io::LoadWorldFile(Path("a.yaml")).robot().start.translation();
  // The rooms are 1.9 m wide and 2.5 m high inside: the farthest point from
  // their walls is about 0.95 m from them.
  EXPECT_GT(pirouette::io::LoadWorldFile(Path("a.yaml")).Clearance(start), 0.8);

  const Result given = RunPirouette("world from-map --map " + map_path + " --out " +
                                    Path("b.yaml") + " --radius 0.1 --start 1.0,0.5,90");
  ASSERT_EQ(given.exit_code, 0) << given.output();
  const pirouette::core::Pose2 s = pirouette::io::LoadWorldFile(Path("b.yaml")).robot().start;
  EXPECT_NEAR(s.x(), 3.0, 1e-9);  // 1.0 - (-2.0)
  EXPECT_NEAR(s.y(), 1.5, 1e-9);  // 0.5 - (-1.0)
  EXPECT_NEAR(s.heading(), M_PI / 2.0, 1e-9);
}

TEST_F(WorldFromMapCliTest, BadInputExitsTwoNamingTheFileOrOption) {
  const std::string map_path = WriteMap();
  const std::string out = " --out " + Path("x.yaml");
  const Result missing = RunPirouette("world from-map --map " + Path("none.yaml") + out);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.stderr_only.find("none.yaml"), std::string::npos) << missing.output();
  // A start on the wall, off the map; a disc that fits nowhere; a bad radius.
  const Result wall = RunPirouette("world from-map --map " + map_path + out + " --start 0.05,0.5");
  EXPECT_EQ(wall.exit_code, 2);
  EXPECT_NE(wall.stderr_only.find("--start"), std::string::npos) << wall.output();
  const Result off = RunPirouette("world from-map --map " + map_path + out + " --start 9,9");
  EXPECT_EQ(off.exit_code, 2);
  EXPECT_NE(off.stderr_only.find("off the map"), std::string::npos) << off.output();
  const Result huge = RunPirouette("world from-map --map " + map_path + out + " --radius 2");
  EXPECT_EQ(huge.exit_code, 2);
  EXPECT_NE(huge.stderr_only.find("fits nowhere"), std::string::npos) << huge.output();
  const Result radius = RunPirouette("world from-map --map " + map_path + out + " --radius -1");
  EXPECT_EQ(radius.exit_code, 2);
  EXPECT_NE(radius.stderr_only.find("--radius"), std::string::npos) << radius.output();
  // A rotated map.
  dir_.Write("maps/rotated.yaml",
             "image: room.pgm\nresolution: 0.05\norigin: [0, 0, 0.3]\nnegate: 0\n"
             "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const Result rotated = RunPirouette("world from-map --map " + Path("maps/rotated.yaml") + out);
  EXPECT_EQ(rotated.exit_code, 2);
  EXPECT_NE(rotated.stderr_only.find("rotated"), std::string::npos) << rotated.output();
  EXPECT_FALSE(fs::exists(Path("x.yaml")));
}

TEST_F(WorldFromMapCliTest, AWorldWhoseMapIsMissingNamesItsGridField) {
  const std::string map_path = WriteMap();
  ASSERT_EQ(RunPirouette("world from-map --map " + map_path + " --out " + Path("w.yaml")).exit_code,
            0);
  fs::remove(map_path);
  const Result r =
      RunPirouette("render --world " + Path("w.yaml") + " --pose 1,1,0 --out " + Path("v.png"));
  EXPECT_EQ(r.exit_code, 2) << r.output();
  EXPECT_NE(r.stderr_only.find("obstacles[0].grid.map"), std::string::npos) << r.output();
}

// The real and simulated buildings' maps: each a world whose start fits,
// whose every fitting cell is reachable, rendered by the camera.
TEST_F(WorldFromMapCliTest, RealMapsBecomeWorlds) {
  if (!fs::is_directory(kMapsDir)) GTEST_SKIP() << "no real maps at " << kMapsDir;
  int made = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kMapsDir)) {
    if (entry.path().extension() != ".yaml" || entry.path().stem() == "depot_speed") continue;
    const std::string name = entry.path().parent_path().filename().string();
    const std::string out = Path(name + ".yaml");
    const Result r =
        RunPirouette("world from-map --map " + entry.path().string() + " --out " + out);
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.output();
    const pirouette::sim::World world = pirouette::io::LoadWorldFile(out);
    const pirouette::tools::WorldValidity validity = pirouette::tools::CheckWorld(world);
    EXPECT_TRUE(validity.start_fits) << name;
    EXPECT_GT(validity.reachable_cells, 500U) << name;
    // Sealed: no cell the disc fits in is out of its reach (a cell or two at
    // the seams between the map's lattice and eval's may remain).
    EXPECT_LE(validity.unreachable_cells, validity.reachable_cells / 1000) << name;
    const pirouette::core::Pose2& s = world.robot().start;
    const Result view = RunPirouette(fmt::format("render --world {} --pose {},{},0 --out {}", out,
                                                 s.x(), s.y(), Path(name + ".png")));
    EXPECT_EQ(view.exit_code, 0) << name << ": " << view.output();
    ++made;
  }
  EXPECT_GE(made, 5);
}

// depot_speed is a speed mask in scale mode with thresholds 1.0 and 0.0:
// every opaque pixel v is rint(100 (1 - v / 255)), worked here from the
// PGM's bytes (P5, maxval 255, top row first) apart from our reader.
TEST_F(WorldFromMapCliTest, AScaleModeSpeedMaskReadsAsMapServerServesIt) {
  const std::string mask = kMapsDir + "/sim_nav2_depot/depot_speed.yaml";
  if (!fs::exists(mask)) GTEST_SKIP() << "no " << mask;
  const pirouette::io::MapServerMap map = pirouette::io::ReadMapServerMap(mask);
  EXPECT_EQ(map.mode, pirouette::io::MapMode::kScale);
  std::ifstream in(kMapsDir + "/sim_nav2_depot/depot_speed.pgm", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const int w = map.geometry.width();
  const int h = map.geometry.height();
  const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  ASSERT_GE(bytes.size(), pixels);
  const std::size_t start = bytes.size() - pixels;  // the pixels end the file
  int differ = 0;
  for (int row = 0; row < h; ++row) {
    for (int x = 0; x < w; ++x) {
      const auto v =
          static_cast<unsigned char>(bytes[start + static_cast<std::size_t>(row * w + x)]);
      const int expected = static_cast<int>(std::rint(100.0 * (1.0 - v / 255.0)));
      if (map.cells[map.geometry.Flat({x, h - 1 - row})] != expected) ++differ;
    }
  }
  EXPECT_EQ(differ, 0);
}

}  // namespace
