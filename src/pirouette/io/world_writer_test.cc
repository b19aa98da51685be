#include "pirouette/io/world_writer.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "pirouette/core/angle.h"
#include "pirouette/io/world_file.h"
#include "pirouette/sim/world_generator.h"
#include "pirouette/testing/same_world.h"
#include "pirouette/testing/temp_dir.h"

// Its own namespace: the unit tests compile together (unity batches).
namespace pirouette::io::world_writer_test {
namespace {

using testing::SameWorld;
using testing::TempDir;

camera::CameraModel Camera() {
  return camera::CameraModel("test cam", 320, 240, {277.13, 276.5, 159.5, 119.25},
                             {-0.2, 0.05, 0.001, -0.002, 0.0}, {0.11, core::DegToRad(30.0), 0.03},
                             {{0.35, 0.3, 0.4}});
}

// Every shape, walls, light, odometry noise, awkward numbers and a name that needs quotes.
sim::WorldSpec EverySpec() {
  sim::WorldSpec spec{"7: \"odd\" name",
                      "a comment\n\nof three lines",
                      sim::Floor{{2.0, 1.5}, {25, 30, 35}, 0.03},
                      sim::BoundaryWalls{0.1, 0.02, {235, 236, 237}},
                      {},
                      sim::Light{0.5, {0.1, -0.2, -1.0}, 0.7},
                      {{0.2, 0.3}, 45.0, 0.04, Camera(), {0.01, 0.02, 0.1, -0.05}}};
  spec.obstacles = {{sim::BoxSpec{{0.4, 0.9}, {0.1, 0.2}, 30.0}, 0.08, {200, 40, 40}},
                    {sim::BoxSpec{{1.0 / 3.0, 0.6}, {0.1, 0.1}, 0.0}, 0.07, {1, 2, 3}},
                    {sim::CylinderSpec{{1.1, 0.3}, 0.05}, 0.1, {40, 160, 40}},
                    {sim::WallSpec{{0.0, 0.65}, {0.8, 0.65}, 0.02}, 0.12, {230, 230, 230}},
                    // Clockwise: the reader turns it round, as BuildWorld does.
                    {sim::PrismSpec{{{1.0, 1.0}, {1.1, 1.2}, {1.2, 1.0}}}, 0.06, {40, 40, 200}}};
  return spec;
}

TEST(WorldFileTextTest, ReadsBackToTheSameWorldFromAnyFolder) {
  const TempDir dir;
  const sim::WorldSpec spec = EverySpec();
  const std::string path = dir.Write("deep/er/world.yaml", WorldFileText(spec));
  EXPECT_TRUE(SameWorld(LoadWorldFile(path), sim::BuildWorld(spec)));
}

TEST(WorldFileTextTest, LeavesOutWhatIsNot) {
  sim::WorldSpec spec = EverySpec();
  spec.walls.reset();
  spec.obstacles.clear();
  spec.robot.odometry_noise = {};
  spec.comment.clear();
  const std::string text = WorldFileText(spec);
  EXPECT_EQ(text.find("walls:"), std::string::npos);
  EXPECT_EQ(text.find("obstacles:"), std::string::npos);
  EXPECT_EQ(text.find("odometry_noise"), std::string::npos);
  EXPECT_EQ(text.rfind("format: pirouette-world/1\n", 0), 0u) << "no comment, no comment lines";
  const TempDir dir;
  EXPECT_TRUE(SameWorld(LoadWorldFile(dir.Write("w.yaml", text)), sim::BuildWorld(spec)));
}

TEST(WorldFileTextTest, WritesTheFileAsTheShippedWorldsAreWritten) {
  sim::WorldSpec spec = EverySpec();
  spec.name = "small";
  spec.comment = "two\nlines";
  spec.obstacles.resize(1);
  spec.robot.odometry_noise = {};
  const std::string text = WorldFileText(spec);
  const std::string head =
      "# two\n"
      "# lines\n"
      "format: pirouette-world/1\n"
      "name: \"small\"\n"
      "floor:\n"
      "  size: [2, 1.5]\n"
      "  colour: [25, 30, 35]\n"
      "  texture: 0.03\n"
      "walls:\n"
      "  height: 0.1\n"
      "  thickness: 0.02\n"
      "  colour: [235, 236, 237]\n"
      "obstacles:\n"
      "  - box: {centre: [0.4, 0.9], size: [0.1, 0.2], yaw: 30, height: 0.08, colour: [200, 40, "
      "40]}\n"
      "light:\n"
      "  ambient: 0.5\n"
      "  direction: [0.1, -0.2, -1]\n"
      "  intensity: 0.7\n"
      "robot:\n"
      "  start: [0.2, 0.3, 45]\n"
      "  radius: 0.04\n"
      "  camera:\n"
      "    image_width: 320\n";
  EXPECT_EQ(text.substr(0, head.size()), head);
  EXPECT_NE(text.find("\n    mount:\n      height: 0.11\n      tilt: 30\n"), std::string::npos)
      << text;
}

TEST(WorldFileTextTest, RefusesNumbersThatAreNot) {
  sim::WorldSpec spec = EverySpec();
  spec.floor.texture = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(WorldFileText(spec), std::invalid_argument);
}

TEST(WorldFileTextTest, GeneratedWorldsReadBack) {
  const TempDir dir;
  for (const sim::WorldKind kind : sim::kWorldKinds) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const sim::WorldSpec spec = sim::GenerateWorld(kind, seed);
      const std::string path = dir.Write("w.yaml", WorldFileText(spec));
      EXPECT_TRUE(SameWorld(LoadWorldFile(path), sim::BuildWorld(spec)))
          << sim::WorldKindName(kind) << " seed " << seed;
    }
  }
}

}  // namespace
}  // namespace pirouette::io::world_writer_test
