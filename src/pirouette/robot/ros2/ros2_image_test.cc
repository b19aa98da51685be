#include "pirouette/robot/ros2/ros2_image.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "pirouette/robot/ros2/ros2_sample.h"

// ImageOf is where a sample from the network is decoded: a malformed one is
// refused with std::invalid_argument and never read past its data (the asan
// build runs these with data allocated to its exact length).
namespace pirouette::robot::ros2::ros2_image_test {
namespace {

using ImageMessage = sensor_msgs_msg_dds__Image_;

// A message of `width` × `height` in `encoding`, rows `step` bytes apart,
// with `bytes` bytes of data (byte i is i mod 251).
Sample<ImageMessage> MessageOf(const std::string& encoding, std::uint32_t width,
                               std::uint32_t height, std::uint32_t step, std::size_t bytes) {
  Sample<ImageMessage> message;
  SetString(message->encoding, encoding);
  message->width = width;
  message->height = height;
  message->step = step;
  std::vector<std::uint8_t> data(bytes);
  for (std::size_t i = 0; i < bytes; ++i) data[i] = static_cast<std::uint8_t>(i % 251);
  SetSequence(message->data, std::span<const std::uint8_t>(data));
  return message;
}

TEST(Ros2Image, Rgb8WithPaddedRowsIsCopiedRowByRow) {
  const auto message = MessageOf("rgb8", 2, 2, 8, 16);
  const core::ImageRgb8 image = ImageOf(*message, 2, 2);
  EXPECT_EQ(image.At(1, 0), (core::Rgb{3, 4, 5}));
  EXPECT_EQ(image.At(0, 1), (core::Rgb{8, 9, 10}));
  EXPECT_EQ(image.At(1, 1), (core::Rgb{11, 12, 13}));
}

TEST(Ros2Image, Bgr8IsSwappedToRgb) {
  const auto message = MessageOf("bgr8", 2, 1, 6, 6);
  const core::ImageRgb8 image = ImageOf(*message);
  EXPECT_EQ(image.At(0, 0), (core::Rgb{2, 1, 0}));
  EXPECT_EQ(image.At(1, 0), (core::Rgb{5, 4, 3}));
}

TEST(Ros2Image, TruncatedDataIsRefused) {
  // One byte short of step × height, and no data at all.
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 4, 3, 12, 35)), std::invalid_argument);
  EXPECT_THROW(ImageOf(*MessageOf("bgr8", 4, 3, 12, 35)), std::invalid_argument);
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 4, 3, 12, 0)), std::invalid_argument);
  // Padded rows: the padding of the last row counts too.
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 4, 3, 16, 44)), std::invalid_argument);
}

TEST(Ros2Image, AStepShorterThanARowIsRefused) {
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 4, 3, 11, 1000)), std::invalid_argument);
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 4, 3, 0, 1000)), std::invalid_argument);
}

TEST(Ros2Image, AnEmptyOrHugeImageIsRefused) {
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 0, 3, 0, 0)), std::invalid_argument);
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 4, 0, 12, 0)), std::invalid_argument);
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 0, 0, 0, 0)), std::invalid_argument);
  // Sizes whose step × height would overflow 32 bits, with little data.
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 0xFFFFFFFFU, 2, 0xFFFFFFFFU, 12)), std::invalid_argument);
  EXPECT_THROW(ImageOf(*MessageOf("rgb8", 16, 16, 0x80000000U, 12)), std::invalid_argument);
}

TEST(Ros2Image, AnotherEncodingOrSizeIsNamed) {
  for (const char* encoding : {"mono8", "yuv422", "rgba8", ""}) {
    try {
      ImageOf(*MessageOf(encoding, 2, 2, 6, 12));
      ADD_FAILURE() << encoding;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("'") + encoding + "'"), std::string::npos)
          << e.what();
    }
  }
  try {
    ImageOf(*MessageOf("rgb8", 2, 2, 6, 12), 4, 3);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("2×2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("4×3"), std::string::npos) << e.what();
  }
}

TEST(Ros2Image, ANullEncodingOrDataIsRefused) {
  Sample<ImageMessage> message;  // all zero: no encoding, no data
  EXPECT_THROW(ImageOf(*message), std::invalid_argument);
  SetString(message->encoding, "rgb8");
  message->width = 2;
  message->height = 2;
  message->step = 6;
  EXPECT_THROW(ImageOf(*message), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::robot::ros2::ros2_image_test
