#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "pirouette/core/image.h"

namespace pirouette::io {

// A cv::Mat (CV_8UC3, BGR, OpenCV's order) copy of an RGB image.
cv::Mat ToBgrMat(const core::ImageRgb8& image);
core::ImageRgb8 FromBgrMat(const cv::Mat& bgr);

// Writes a PNG atomically; throws std::runtime_error naming the path.
void WritePng(const std::string& path, const cv::Mat& image);
void WritePng(const std::string& path, const core::ImageRgb8& image);

// Reads an image as RGB; throws core::InputError naming the path when it is
// missing, empty or not an image.
core::ImageRgb8 ReadImage(const std::string& path);

}  // namespace pirouette::io
