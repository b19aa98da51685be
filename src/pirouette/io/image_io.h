#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <string_view>

#include "pirouette/core/image.h"

namespace pirouette::io {

// A cv::Mat (CV_8UC3, BGR, OpenCV's order) copy of an RGB image.
cv::Mat ToBgrMat(const core::ImageRgb8& image);
core::ImageRgb8 FromBgrMat(const cv::Mat& bgr);

// Writes a PNG atomically; throws std::runtime_error naming the path.
void WritePng(const std::string& path, const cv::Mat& image);
void WritePng(const std::string& path, const core::ImageRgb8& image);

// The most pixels an image read from a file may have: 2^26 (64 Mpixel,
// 192 MiB as RGB), far past any camera's frame or map a run reads.
inline constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 26;

// Throws core::InputError naming `path` when `head` (an image file's first
// bytes, at least 24 of them) is a PNG's header declaring more than
// kMaxImagePixels: OpenCV allocates the decoded image before anyone can
// look at its size (up to its own limit of 2^30 pixels, 3 GiB), so a crafted
// header would take the machine's memory. Any other head passes.
void CheckImageSize(const std::string& path, std::string_view head);
// The same for the file at `path` (a file that cannot be read passes).
void CheckImageFileSize(const std::string& path);

// Reads an image as RGB; throws core::InputError naming the path when it is
// missing, empty, not an image, or a PNG larger than kMaxImagePixels.
core::ImageRgb8 ReadImage(const std::string& path);

}  // namespace pirouette::io
