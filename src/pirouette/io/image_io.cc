#include "pirouette/io/image_io.h"

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "pirouette/core/input_error.h"
#include "pirouette/io/atomic_file.h"

namespace pirouette::io {

cv::Mat ToBgrMat(const core::ImageRgb8& image) {
  const cv::Mat rgb(image.height(), image.width(), CV_8UC3,
                    const_cast<std::uint8_t*>(image.data()));  // NOLINT: read only
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

core::ImageRgb8 FromBgrMat(const cv::Mat& bgr) {
  CV_Assert(bgr.type() == CV_8UC3);
  core::ImageRgb8 image(bgr.cols, bgr.rows);
  cv::Mat rgb(bgr.rows, bgr.cols, CV_8UC3, image.data());
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  return image;
}

void WritePng(const std::string& path, const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  if (!cv::imencode(".png", image, bytes)) {
    throw std::runtime_error("cannot encode a PNG for " + path);
  }
  WriteFileAtomically(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

void WritePng(const std::string& path, const core::ImageRgb8& image) {
  WritePng(path, ToBgrMat(image));
}

core::ImageRgb8 ReadImage(const std::string& path) {
  if (!std::filesystem::exists(path)) throw core::InputError(path, 0, "", "no such file");
  const cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
  if (bgr.empty()) throw core::InputError(path, 0, "", "not an image OpenCV can read");
  return FromBgrMat(bgr);
}

}  // namespace pirouette::io
