#include "pirouette/robot/ros2/ros2_image.h"

#include <fmt/format.h>

#include <cstring>
#include <span>
#include <stdexcept>
#include <string_view>

#include "pirouette/robot/ros2/ros2_sample.h"

namespace pirouette::robot::ros2 {

core::ImageRgb8 ImageOf(const sensor_msgs_msg_dds__Image_& message, int width, int height) {
  const std::string_view encoding = message.encoding != nullptr ? message.encoding : "";
  const bool rgb = encoding == "rgb8";
  if (!rgb && encoding != "bgr8") {
    throw std::invalid_argument(
        fmt::format("the encoding is '{}'; pirouette reads rgb8 or bgr8 (set the camera "
                    "driver's pixel format, or convert with image_proc)",
                    encoding));
  }
  const std::uint32_t w = message.width;
  const std::uint32_t h = message.height;
  if (w == 0 || h == 0 || w > 16384 || h > 16384) {
    throw std::invalid_argument(fmt::format("an image of {}×{} pixels", w, h));
  }
  if (width > 0 && height > 0 &&
      (w != static_cast<std::uint32_t>(width) || h != static_cast<std::uint32_t>(height))) {
    throw std::invalid_argument(
        fmt::format("the image is {}×{} but the camera file says {}×{}", w, h, width, height));
  }
  const std::uint64_t row_bytes = 3ULL * w;
  if (message.step < row_bytes ||
      static_cast<std::uint64_t>(message.step) * h > message.data._length) {
    throw std::invalid_argument(
        fmt::format("step {} and {} bytes of data do not hold {}×{} pixels of 3 bytes",
                    message.step, message.data._length, w, h));
  }
  core::ImageRgb8 image(static_cast<int>(w), static_cast<int>(h));
  for (std::uint32_t v = 0; v < h; ++v) {
    const std::uint8_t* source = message.data._buffer + static_cast<std::size_t>(v) * message.step;
    std::uint8_t* target = image.data() + static_cast<std::size_t>(v) * row_bytes;
    if (rgb) {
      std::memcpy(target, source, row_bytes);
    } else {
      for (std::uint32_t u = 0; u < w; ++u) {
        target[3 * u + 0] = source[3 * u + 2];
        target[3 * u + 1] = source[3 * u + 1];
        target[3 * u + 2] = source[3 * u + 0];
      }
    }
  }
  return image;
}

void SetImage(sensor_msgs_msg_dds__Image_& message, const core::ImageRgb8& image) {
  message.width = static_cast<std::uint32_t>(image.width());
  message.height = static_cast<std::uint32_t>(image.height());
  SetString(message.encoding, "rgb8");
  message.is_bigendian = 0;
  message.step = static_cast<std::uint32_t>(image.width() * 3);
  SetSequence(message.data, std::span<const std::uint8_t>(image.data(), image.size_bytes()));
}

}  // namespace pirouette::robot::ros2
