#include "pirouette/io/image_io.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

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

void CheckImageSize(const std::string& path, std::string_view head) {
  constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
  if (head.size() < 24 || head.substr(0, 8) != kSignature) return;
  const auto big_endian = [&](std::size_t at) {
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(head[at + k]);
    return v;
  };
  const std::uint64_t width = big_endian(16);
  const std::uint64_t height = big_endian(20);
  if (width * height > kMaxImagePixels) {
    throw core::InputError(path, 0, "",
                           "a PNG of " + std::to_string(width) + " x " + std::to_string(height) +
                               " pixels: more than the " + std::to_string(kMaxImagePixels) +
                               " an image may have");
  }
}

void CheckImageFileSize(const std::string& path) {
  std::string head(24, '\0');
  std::ifstream in(path, std::ios::binary);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  CheckImageSize(path, head);
}

core::ImageRgb8 ReadImage(const std::string& path) {
  if (!std::filesystem::exists(path)) throw core::InputError(path, 0, "", "no such file");
  CheckImageFileSize(path);
  const cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
  if (bgr.empty()) throw core::InputError(path, 0, "", "not an image OpenCV can read");
  return FromBgrMat(bgr);
}

}  // namespace pirouette::io
