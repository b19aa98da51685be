#pragma once

#include <cassert>
#include <cstdint>
#include <vector>

#include "pirouette/core/rgb.h"

namespace pirouette::core {

// An 8-bit RGB image, rows top to bottom, pixels left to right, channels
// R, G, B interleaved, no padding. The pixel (u, v) is column u, row v; its
// centre has the image coordinates (u, v), as in OpenCV.
class ImageRgb8 {
 public:
  ImageRgb8() = default;
  ImageRgb8(int width, int height)
      : width_(width), height_(height), data_(static_cast<std::size_t>(width) * height * 3) {
    assert(width >= 0 && height >= 0);
  }

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return data_.empty(); }
  std::uint8_t* data() { return data_.data(); }
  const std::uint8_t* data() const { return data_.data(); }
  std::size_t size_bytes() const { return data_.size(); }

  Rgb At(int u, int v) const {
    const std::uint8_t* p = Pixel(u, v);
    return {p[0], p[1], p[2]};
  }
  std::uint8_t* Pixel(int u, int v) {
    assert(u >= 0 && u < width_ && v >= 0 && v < height_);
    return data_.data() + (static_cast<std::size_t>(v) * width_ + u) * 3;
  }
  const std::uint8_t* Pixel(int u, int v) const {
    assert(u >= 0 && u < width_ && v >= 0 && v < height_);
    return data_.data() + (static_cast<std::size_t>(v) * width_ + u) * 3;
  }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> data_;
};

}  // namespace pirouette::core
