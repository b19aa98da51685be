#include "pirouette/io/colour_map_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "pirouette/core/input_error.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::io {
namespace {

namespace fs = std::filesystem;

class ColourMapFileTest : public ::testing::Test {
 protected:
  testing::TempDir temp_{"pirouette_colour_map"};
  fs::path dir_ = temp_.path();
};

TEST_F(ColourMapFileTest, EveryClassAndNoneReadBack) {
  const core::GridGeometry g(0.05, Eigen::Vector2d(-1.0, 2.0), 4, 5);
  std::vector<core::ColourClass> cells(g.CellCount(), core::ColourClass::kNone);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    cells[i] = static_cast<core::ColourClass>(i % (core::kColourClasses + 1));
  }
  const localize::ColourMap colours(g, cells);
  const std::string path = (dir_ / "m_colours.png").string();
  WriteColourMap(colours, path);
  const localize::ColourMap back = ReadColourMap(path, g);
  EXPECT_EQ(back.cells(), cells);
}

TEST_F(ColourMapFileTest, ThePictureIsLaidOutAsTheMap) {
  // Cell (0, 0) is the map's lower left: the picture's bottom-left pixel.
  const core::GridGeometry g(0.1, Eigen::Vector2d::Zero(), 3, 2);
  std::vector<core::ColourClass> cells(g.CellCount(), core::ColourClass::kNone);
  cells[g.Flat({0, 0})] = core::ColourClass::kHue0;
  const std::string path = (dir_ / "m_colours.png").string();
  WriteColourMap({g, cells}, path);
  const cv::Mat raw = cv::imread(path, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(raw.type(), CV_8UC4);
  EXPECT_EQ(raw.at<cv::Vec4b>(1, 0)[3], 255);
  EXPECT_GT(raw.at<cv::Vec4b>(1, 0)[2], 200);  // red
  EXPECT_EQ(raw.at<cv::Vec4b>(0, 0)[3], 0);
}

TEST_F(ColourMapFileTest, BesideTheMapYaml) {
  EXPECT_EQ(ColourMapPathFor("out/run/map.yaml"), "out/run/map_colours.png");
}

TEST_F(ColourMapFileTest, BadFilesNameTheFile) {
  const core::GridGeometry g(0.1, Eigen::Vector2d::Zero(), 3, 2);
  const std::string missing = (dir_ / "none.png").string();
  try {
    ReadColourMap(missing, g);
    FAIL() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("none.png"), std::string::npos) << e.what();
  }
  const std::string text = (dir_ / "text.png").string();
  std::ofstream(text) << "not a picture";
  EXPECT_THROW(ReadColourMap(text, g), core::InputError);
  const std::string other = (dir_ / "other.png").string();
  WriteColourMap(localize::ColourMap(core::GridGeometry(0.1, Eigen::Vector2d::Zero(), 4, 2),
                                     std::vector<core::ColourClass>(8, core::ColourClass::kWhite)),
                 other);
  try {
    ReadColourMap(other, g);
    FAIL() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("4x2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pirouette::io
