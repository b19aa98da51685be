#include "pirouette/io/image_io.h"

#include <gtest/gtest.h>

#include <string>

#include "pirouette/core/input_error.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::io {
namespace image_io_test {

// A PNG whose header declares 100000 x 100000 pixels is refused before
// OpenCV would allocate 30 GB for it; a small one reads.
TEST(ImageIo, RefusesAPngLargerThanTheLimitBeforeDecodingIt) {
  const testing::TempDir dir("image_io");
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0dIHDR", 8);
  png += std::string("\x00\x01\x86\xa0\x00\x01\x86\xa0", 8);  // 100000 x 100000
  png += std::string("\x08\x02\0\0\0", 5);
  const std::string path = dir.Write("huge.png", png);
  try {
    ReadImage(path);
    ADD_FAILURE() << "no InputError";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("100000 x 100000"), std::string::npos) << e.what();
  }

  core::ImageRgb8 small(4, 3);
  small.data()[0] = 200;
  WritePng(dir / "small.png", small);
  const core::ImageRgb8 back = ReadImage(dir / "small.png");
  EXPECT_EQ(back.width(), 4);
  EXPECT_EQ(back.data()[0], 200);
}

}  // namespace image_io_test
}  // namespace pirouette::io
