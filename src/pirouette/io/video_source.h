#pragma once

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace pirouette::io {

// A video source as the user names it.
struct VideoSource {
  std::string name;                 // as given, for messages
  std::optional<int> device_index;  // "0", "1", …: a camera device
  bool is_stream = false;           // a URL (scheme://…): rtsp, http, …
  // A device or a stream: it has no end of its own.
  bool live() const { return device_index.has_value() || is_stream; }
};

// A string of decimal digits is a device index; "scheme://…" a stream; anything
// else a file path (write "./0" for a file named "0"). Throws core::InputError
// for an empty source.
VideoSource ParseVideoSource(std::string_view source);

// Opens a source with OpenCV's VideoCapture. Throws core::InputError naming
// the source for a device that cannot be opened, a missing file, a folder, or
// a file or stream OpenCV cannot read.
cv::VideoCapture OpenVideoSource(const VideoSource& source);

// A frame as the source gave it, as 8-bit BGR (grey and BGRA converted).
// Throws core::InputError naming `source` for frames of another depth or
// channel count.
cv::Mat3b ToBgrFrame(const cv::Mat& raw, const std::string& source);

}  // namespace pirouette::io
