#include "pirouette/io/video_source.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <system_error>

#include "pirouette/core/input_error.h"

namespace pirouette::io {

namespace fs = std::filesystem;

VideoSource ParseVideoSource(std::string_view source) {
  if (source.empty()) throw core::InputError("", 0, "source", "is empty");
  VideoSource parsed;
  parsed.name = std::string(source);
  const bool digits = source.size() <= 6 && std::all_of(source.begin(), source.end(), [](char c) {
                        return c >= '0' && c <= '9';
                      });
  if (digits) {
    parsed.device_index = std::stoi(parsed.name);
  } else {
    const std::size_t scheme = source.find("://");
    if (scheme != std::string_view::npos && scheme > 0) {
      const std::string_view name = source.substr(0, scheme);
      parsed.is_stream = std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalpha(static_cast<unsigned char>(c)) != 0;
      });
    }
  }
  return parsed;
}

cv::VideoCapture OpenVideoSource(const VideoSource& source) {
  cv::VideoCapture capture;
  if (source.device_index) {
    capture.open(*source.device_index);
    if (!capture.isOpened()) {
      throw core::InputError(source.name, 0, "",
                             fmt::format("camera device {} cannot be opened (is it plugged in, "
                                         "and not in use?)",
                                         *source.device_index));
    }
    return capture;
  }
  if (!source.is_stream) {
    std::error_code error;
    if (!fs::exists(source.name, error)) throw core::InputError(source.name, 0, "", "no such file");
    if (fs::is_directory(source.name, error)) {
      throw core::InputError(source.name, 0, "", "is a folder, not a video");
    }
  }
  capture.open(source.name);
  if (!capture.isOpened()) {
    throw core::InputError(source.name, 0, "",
                           source.is_stream
                               ? "the stream cannot be opened (unreachable, or not a video stream "
                                 "OpenCV can read)"
                               : "cannot be opened as a video (not a video OpenCV can read)");
  }
  return capture;
}

cv::Mat3b ToBgrFrame(const cv::Mat& raw, const std::string& source) {
  if (raw.depth() != CV_8U) {
    throw core::InputError(source, 0, "", "frames that are not 8 bits a channel are not supported");
  }
  cv::Mat3b bgr;
  switch (raw.channels()) {
    case 1:
      cv::cvtColor(raw, bgr, cv::COLOR_GRAY2BGR);
      break;
    case 3:
      bgr = raw;
      break;
    case 4:
      cv::cvtColor(raw, bgr, cv::COLOR_BGRA2BGR);
      break;
    default:
      throw core::InputError(
          source, 0, "", fmt::format("frames with {} channels are not supported", raw.channels()));
  }
  return bgr;
}

}  // namespace pirouette::io
