#include "pirouette/io/colour_map_file.h"

#include <fmt/format.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "pirouette/core/input_error.h"
#include "pirouette/io/image_io.h"

namespace pirouette::io {

std::string ColourMapPathFor(const std::string& map_yaml_path) {
  const std::filesystem::path p(map_yaml_path);
  return (p.parent_path() / (p.stem().string() + "_colours.png")).string();
}

void WriteColourMap(const localize::ColourMap& colours, const std::string& png_path) {
  const core::GridGeometry& g = colours.geometry();
  cv::Mat4b image(g.height(), g.width(), cv::Vec4b(0, 0, 0, 0));
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const core::ColourClass c = colours.At({x, y});
      if (c == core::ColourClass::kNone) continue;
      const core::Rgb rgb = core::ColourClassSwatch(c);
      image(g.height() - 1 - y, x) = cv::Vec4b(rgb.b, rgb.g, rgb.r, 255);
    }
  }
  WritePng(png_path, image);
}

localize::ColourMap ReadColourMap(const std::string& png_path, const core::GridGeometry& geometry) {
  if (!std::filesystem::exists(png_path)) {
    throw core::InputError(png_path, 0, "", "no such file");
  }
  CheckImageFileSize(png_path);
  const cv::Mat raw = cv::imread(png_path, cv::IMREAD_UNCHANGED);
  if (raw.empty() || raw.depth() != CV_8U) {
    throw core::InputError(png_path, 0, "", "not an 8-bit image OpenCV can read");
  }
  if (raw.cols != geometry.width() || raw.rows != geometry.height()) {
    throw core::InputError(png_path, 0, "",
                           fmt::format("the colour layer is {}x{} pixels, its map {}x{} cells",
                                       raw.cols, raw.rows, geometry.width(), geometry.height()));
  }
  cv::Mat4b bgra;
  if (raw.channels() == 4) {
    bgra = raw;
  } else if (raw.channels() == 3) {
    cv::cvtColor(raw, bgra, cv::COLOR_BGR2BGRA);
  } else {
    cv::cvtColor(raw, bgra, cv::COLOR_GRAY2BGRA);
  }
  std::vector<core::ColourClass> cells(geometry.CellCount(), core::ColourClass::kNone);
  for (int y = 0; y < geometry.height(); ++y) {
    for (int x = 0; x < geometry.width(); ++x) {
      const cv::Vec4b p = bgra(geometry.height() - 1 - y, x);
      if (p[3] == 0) continue;
      cells[geometry.Flat({x, y})] = core::ClassifyColour(core::Rgb{p[2], p[1], p[0]});
    }
  }
  return {geometry, std::move(cells)};
}

}  // namespace pirouette::io
